// How a snap's footprint (snap_action.h) is put together from its
// conditions and effects: the parts TaskIndex assembles (task_index.cpp),
// for the planner's own use. What each part counts follows VAL's mutex
// rule (Fox & Long 2003, section 8.2; VAL's Ownership.cpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "planner/derived_support.h"
#include "planner/ground_task.h"
#include "planner/snap_action.h"

namespace alplan::footprint_parts {

template <typename T>
void unique(std::vector<T>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

template <typename T>
bool intersect(const std::vector<T>& a, const std::vector<T>& b) {
  auto i = a.begin();
  auto j = b.begin();
  while (i != a.end() && j != b.end()) {
    if (*i < *j) {
      ++i;
    } else if (*j < *i) {
      ++j;
    } else {
      return true;
    }
  }
  return false;
}

// What a condition reads.
void condition_reads(const ConditionSet& c, Footprint& fp);
// An over-all condition: held, not read (snap_action.h).
void condition_holds(const ConditionSet& c, Footprint& fp);
// `skipped`: conditional effects left out, condition and effects.
void effect_footprint(const HappeningEffects& e, Footprint& fp, const std::vector<std::uint32_t>& skipped = {});
// Atoms that are never facts but that a snap's condition names or its
// effects delete (GroundTask::ghosts), under keys after the facts': VAL's
// mutex rule counts them, so they order snaps like facts do.
void add_ghosts(const GroundTask& t, const ConditionSet& condition, const HappeningEffects& effects, Footprint& fp);
// Sorts and deduplicates every list, and drops from the weaker kinds what a
// stronger kind of the same key already says.
void finish(Footprint& fp);
bool effects_mention_duration(const HappeningEffects& e);
bool conditions_mention_duration(const ConditionSet& c);

// A snap reading a derived fact reads every fact and variable of the
// predicates and functions its rules read (derived_support.h says why not
// only those of the planner's own axioms): without this, a writer of one of
// them could be scheduled at the same time as the reader, which VAL rejects.
class DerivedReads {
 public:
  explicit DerivedReads(const GroundTask& task) : task_(task), lifted_(*task.lifted) {
    facts_of_.resize(task.lifted->predicates.size());
    variables_of_.resize(task.lifted->functions.size());
    for (FactId f = 0; f < task.facts.size(); ++f) {
      if (!task.is_derived(f)) facts_of_[task.facts.key(f).head].push_back(f);
    }
    for (NumericVarId v = 0; v < task.numeric.size(); ++v) variables_of_[task.numeric.key(v).head].push_back(v);
  }

  void expand(Footprint& fp) const {
    expand(fp.reads, fp.reads, fp.reads_values);
    expand(fp.holds, fp.holds, fp.holds_values);
    expand(fp.reads_first, fp.reads_first, fp.reads_first_values);
  }

 private:
  void expand(const std::vector<FactId>& derived_from, std::vector<FactId>& facts,
              std::vector<NumericVarId>& values) const {
    std::vector<PredicateId> predicates;
    std::vector<FunctionId> functions;
    for (FactId f : derived_from) {
      if (!task_.is_derived(f)) continue;
      const PredicateId p = task_.facts.key(f).head;
      predicates.insert(predicates.end(), lifted_.predicates(p).begin(), lifted_.predicates(p).end());
      functions.insert(functions.end(), lifted_.functions(p).begin(), lifted_.functions(p).end());
    }
    unique(predicates);
    unique(functions);
    for (PredicateId p : predicates) facts.insert(facts.end(), facts_of_[p].begin(), facts_of_[p].end());
    for (FunctionId f : functions) values.insert(values.end(), variables_of_[f].begin(), variables_of_[f].end());
  }

 private:
  const GroundTask& task_;
  LiftedDerivedReads lifted_;
  std::vector<std::vector<FactId>> facts_of_;
  std::vector<std::vector<NumericVarId>> variables_of_;
};

// A hard PDDL 3 `always` constraint is read in every state the search makes
// (successor_generator.h). The partial order keeps only the orders that
// reads and writes ask for, so a snap that writes what the constraint reads
// reads all of it: such snaps then keep the order in which the search
// checked their states, and the schedule cannot interleave them into a state
// it never checked.
class AlwaysReads {
 public:
  explicit AlwaysReads(const GroundTask& task) {
    for (const GroundConstraint& g : task.pddl3.constraints) {
      if (g.op != ModalOperator::Always || g.preference) continue;
      Footprint f;
      condition_reads(g.requirement, f);
      finish(f);
      if (!f.reads.empty() || !f.reads_values.empty()) reads_.push_back(std::move(f));
    }
  }
  bool empty() const { return reads_.empty(); }

  void expand(Footprint& fp) const {
    bool grown = false;
    for (const Footprint& r : reads_) {
      if (!intersect(fp.writes, r.reads) && !intersect(fp.writes_values, r.reads_values)) continue;
      fp.reads.insert(fp.reads.end(), r.reads.begin(), r.reads.end());
      fp.reads_values.insert(fp.reads_values.end(), r.reads_values.begin(), r.reads_values.end());
      grown = true;
    }
    if (grown) finish(fp);
  }

 private:
  std::vector<Footprint> reads_;
};

}  // namespace alplan::footprint_parts
