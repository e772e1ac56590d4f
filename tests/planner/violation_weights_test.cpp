// The weights a metric gives the preferences' violations (planner/
// violation_weights.h), read off hand-built expressions: what decides
// whether the anytime search may bound by the true metric.
#include "planner/violation_weights.h"

#include <catch2/catch.hpp>

using namespace alplan;

namespace {

using K = GroundExpression::Kind;

GroundExpression constant(double v) {
  GroundExpression e;
  e.kind = K::Constant;
  e.value = v;
  return e;
}

GroundExpression violated(NumericVarId p) {
  GroundExpression e;
  e.kind = K::IsViolated;
  e.variable = p;
  return e;
}

GroundExpression node(K kind, std::vector<GroundExpression> operands) {
  GroundExpression e;
  e.kind = kind;
  e.operands = std::move(operands);
  return e;
}

GroundExpression fluent(NumericVarId v) {
  GroundExpression e;
  e.kind = K::Variable;
  e.variable = v;
  return e;
}

}  // namespace

TEST_CASE("violation weights: sums, differences, constant factors and negation, by hand") {
  // (+ (* 2 (is-violated p0)) (* 3 (- 1 (is-violated p1))) (total-time) (fuel))
  const GroundExpression metric = node(
      K::Add, {node(K::Multiply, {constant(2), violated(0)}),
               node(K::Multiply, {constant(3), node(K::Subtract, {constant(1), violated(1)})}),
               node(K::TotalTime, {}), fluent(0)});
  const auto weights = violation_coefficients(metric, 3);
  REQUIRE(weights);
  CHECK((*weights)[0] == Approx(2.0));
  CHECK((*weights)[1] == Approx(-3.0));
  CHECK((*weights)[2] == Approx(0.0));  // never read
  // (- (/ (is-violated p0) 4)) weighs -0.25
  const auto quarter = violation_coefficients(node(K::Negate, {node(K::Divide, {violated(0), constant(4)})}), 1);
  REQUIRE(quarter);
  CHECK((*quarter)[0] == Approx(-0.25));
}

TEST_CASE("violation weights: a violation times a fluent, or divided into, is not linear") {
  CHECK_FALSE(violation_coefficients(node(K::Multiply, {fluent(0), violated(0)}), 1));
  CHECK_FALSE(violation_coefficients(node(K::Divide, {constant(1), violated(0)}), 1));
  CHECK_FALSE(violation_coefficients(node(K::Multiply, {violated(0), violated(1)}), 2));
}
