// Over-all preferences counted by hand from the definition (Gerevini & Long,
// "Plan Constraints and Preferences in PDDL3", 2005: each violated
// preference instance of an action's occurrence counts once; an over-all
// one is violated when it fails at any point of the action's span), shared
// by the validator's test and the reference semantics' test so that both
// meet the same expectations, written here and not computed by either.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace alplan::test {

inline const char* const kOverAllPreferenceDomain = R"(
(define (domain watch)
  (:requirements :strips :typing :durative-actions :negative-preconditions :preferences)
  (:types spot)
  (:predicates (a) (b) (seen ?s - spot) (done) (busy))
  (:durative-action act :parameters () :duration (= ?duration 4)
    :condition (and (over all (preference pa (a))) (over all (preference pb (b))))
    :effect (at end (done)))
  (:durative-action scan :parameters () :duration (= ?duration 4)
    :condition (over all (forall (?s - spot) (preference ps (seen ?s))))
    :effect (at end (done)))
  (:durative-action look :parameters (?s - spot) :duration (= ?duration 1)
    :condition (at start (preference first (not (seen ?s))))
    :effect (at end (seen ?s)))
  (:action tick :parameters () :precondition (and) :effect (busy)))
)";

inline const char* const kOverAllPreferenceProblem = R"(
(define (problem w) (:domain watch) (:objects s1 s2 - spot) (:init) (:goal (done))
  (:metric minimize (+ (is-violated pa) (* 10 (is-violated pb)) (* 100 (is-violated ps))
                       (* 1000 (is-violated first)))))
)";

struct OverAllPreferenceCase {
  const char* what;
  const char* plan;
  std::map<std::string, double> violations;
  double value;
};

inline std::vector<OverAllPreferenceCase> over_all_preference_cases() {
  return {
      {"two over-all preferences of one action, both violated, each count",
       "0.000: (act) [4.000]\n", {{"pa", 1}, {"pb", 1}, {"ps", 0}, {"first", 0}}, 11},
      {"a step spanning other happenings counts its over-all preferences once",
       "0.000: (act) [4.000]\n1.000: (tick)\n2.000: (tick)\n3.000: (tick)\n",
       {{"pa", 1}, {"pb", 1}, {"ps", 0}, {"first", 0}}, 11},
      {"each occurrence of the action counts",
       "0.000: (act) [4.000]\n5.000: (act) [4.000]\n", {{"pa", 2}, {"pb", 2}, {"ps", 0}, {"first", 0}}, 22},
      {"under forall each instance counts once, as at start",
       "0.000: (scan) [4.000]\n", {{"pa", 0}, {"pb", 0}, {"ps", 2}, {"first", 0}}, 200},
      {"an instance violated at the start of the span counts though it holds later",
       "0.000: (look s1) [1.000]\n0.000: (scan) [4.000]\n", {{"pa", 0}, {"pb", 0}, {"ps", 2}, {"first", 0}}, 200},
      {"an instance that holds over the whole span does not count",
       "0.000: (look s1) [1.000]\n1.001: (scan) [4.000]\n", {{"pa", 0}, {"pb", 0}, {"ps", 1}, {"first", 0}}, 100},
      {"an at-start preference counts per occurrence",
       "0.000: (look s1) [1.000]\n1.001: (look s1) [1.000]\n2.002: (scan) [4.000]\n",
       {{"pa", 0}, {"pb", 0}, {"ps", 1}, {"first", 1}}, 1100},
  };
}

}  // namespace alplan::test
