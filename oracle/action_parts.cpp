#include "oracle/action_parts.h"

namespace alplan::oracle {
namespace {

using CKind = pddl::Condition::Kind;
using EKind = pddl::Effect::Kind;

bool has_timed(const pddl::Condition& c) {
  if (c.kind == CKind::Timed) return true;
  for (const pddl::Condition& child : c.children) {
    if (has_timed(child)) return true;
  }
  return false;
}

// The part of a durative condition that holds at `time`, if any.
std::optional<pddl::Condition> timed_part(const pddl::Condition& c, pddl::TimeSpecifier time) {
  switch (c.kind) {
    case CKind::Timed:
      if (c.time == time) return c.children.front();
      return std::nullopt;
    case CKind::And: {
      pddl::Condition out = c;
      out.children.clear();
      for (const pddl::Condition& child : c.children) {
        if (std::optional<pddl::Condition> part = timed_part(child, time)) out.children.push_back(std::move(*part));
      }
      if (out.children.empty()) return std::nullopt;
      return out;
    }
    case CKind::Preference:
    case CKind::Forall: {
      std::optional<pddl::Condition> body = timed_part(c.children.front(), time);
      if (!body) return std::nullopt;
      pddl::Condition out = c;
      out.children = {std::move(*body)};
      return out;
    }
    default:
      throw NotJudged("a condition of a durative action outside at start, at end and over all: line " +
                      std::to_string(c.location.line));
  }
}

void split_conditions(const pddl::Condition& c, ActionParts& parts) {
  if (auto s = timed_part(c, pddl::TimeSpecifier::AtStart)) parts.start.conditions.push_back(std::move(*s));
  if (auto e = timed_part(c, pddl::TimeSpecifier::AtEnd)) parts.end.conditions.push_back(std::move(*e));
  if (auto o = timed_part(c, pddl::TimeSpecifier::OverAll)) parts.invariant.push_back(std::move(*o));
}

// Whether an effect sub-tree does anything at `moment` (`above`: the time
// specifier over it, if any).
bool acts_at(const pddl::Effect& e, Moment moment, std::optional<Moment> above) {
  if (moment == Moment::Instant) return true;
  if (e.kind == EKind::Timed) {
    above = e.time == pddl::TimeSpecifier::AtEnd ? Moment::End : Moment::Start;
  } else if (e.kind == EKind::Add || e.kind == EKind::Delete || e.kind == EKind::Numeric) {
    return above == moment;
  }
  for (const pddl::Effect& child : e.children) {
    if (acts_at(child, moment, above)) return true;
  }
  return false;
}

void bucket(const pddl::Effect& e, Moment moment, std::optional<Moment> above, ActionPart::Effects& out) {
  if (!acts_at(e, moment, above)) return;
  switch (e.kind) {
    case EKind::And:
      for (const pddl::Effect& child : e.children) bucket(child, moment, above, out);
      return;
    case EKind::Timed:
      bucket(e.children.front(), moment, e.time == pddl::TimeSpecifier::AtEnd ? Moment::End : Moment::Start, out);
      return;
    case EKind::Add: out.adds.push_back({&e, above}); return;
    case EKind::Delete: out.deletes.push_back({&e, above}); return;
    case EKind::Numeric: out.numerics.push_back({&e, above}); return;
    case EKind::When: out.whens.push_back({&e, above}); return;
    case EKind::Forall: out.foralls.push_back({&e, above}); return;
  }
}

void find_deferred(const pddl::Effect& e, ActionParts& parts) {
  for (const pddl::Effect& child : e.children) find_deferred(child, parts);
  if (e.kind != EKind::When || !has_timed(*e.condition)) return;
  auto s = timed_part(*e.condition, pddl::TimeSpecifier::AtStart);
  auto o = timed_part(*e.condition, pddl::TimeSpecifier::OverAll);
  auto end = timed_part(*e.condition, pddl::TimeSpecifier::AtEnd);
  const bool at_start = acts_at(e.children.front(), Moment::Start, std::nullopt);
  if (at_start && (o || end)) throw NotJudged("a conditional effect at start that depends on later conditions");
  if (!at_start && (s || o)) parts.deferred.push_back({&e, std::move(s), std::move(o)});
}

}  // namespace

ActionPart::Effects bucket_effects(const pddl::Effect& effect, Moment moment, std::optional<Moment> above) {
  ActionPart::Effects out;
  bucket(effect, moment, above, out);
  return out;
}

ActionParts parts_of(const pddl::Action& action) {
  ActionParts parts;
  if (action.precondition) parts.instant.conditions.push_back(*action.precondition);
  if (action.effect) parts.instant.effects = bucket_effects(*action.effect, Moment::Instant);
  return parts;
}

ActionParts parts_of(const pddl::DurativeAction& action) {
  ActionParts parts;
  parts.durative = true;
  if (action.condition) split_conditions(*action.condition, parts);
  for (const pddl::DurationConstraint& d : action.duration) {
    (d.time == pddl::TimeSpecifier::AtEnd ? parts.end : parts.start).durations.push_back(d);
  }
  if (action.effect) {
    parts.start.effects = bucket_effects(*action.effect, Moment::Start);
    parts.end.effects = bucket_effects(*action.effect, Moment::End);
    find_deferred(*action.effect, parts);
  }
  return parts;
}

}  // namespace alplan::oracle
