// Interference between the actions of one happening, as VAL judges it
// (VAL's Ownership.cpp; the rule of Fox & Long 2003, section 8.2: no two
// actions at one instant may touch what the other reads or writes, except
// that several may add one fact, delete one fact, or increase or decrease
// one fluent). The members are the happening's actions: instantaneous
// steps, starts, ends and timed initial literals alike, a start and the end
// of one step being two members.
//
// Claims are made in VAL's order (every member's reads first, then each
// member's effects), and the table below decides each one; the first claim
// refused is the mutex the verdict names.
//
// fact p, claim by member a          refused when p is already
//   read                             added or deleted by another member
//   add                              read (by another, or by two members),
//                                    deleted by another, or read and then
//                                    added or deleted by a itself
//   delete                           read by another or by two, added by
//                                    another
// fluent v, claim by member a
//   read                             written by another member
//   write (increase, decrease)       read by another, assigned by anyone,
//                                    or additively written by a and now
//                                    assigned
//   write (assign, scale-up/-down)   claimed by anyone else in any way, or
//                                    assigned by a already
//
// The symmetric rule (JudgeOptions::symmetric_mutex) asks more: it judges
// each pair of members by everything each claimed, whatever the order, so a
// member that deleted a fact and then reads or adds it in a firing
// conditional effect interferes with another deleting it, which VAL's table
// lets through when the first member's claim came first. Plans valid under
// both rules are the ones a planner that orders by pairwise footprints (as
// POPF and alplan do) can produce.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>

namespace alplan::oracle {

class Ownership {
 public:
  // Member numbers are the happening's; kShared marks a read by two.
  static constexpr int kShared = -1;

  bool read_fact(int member, int atom);
  bool add_fact(int member, int atom);
  bool delete_fact(int member, int atom);
  bool read_fluent(int member, int fluent);
  bool write_fluent(int member, int fluent, bool additive);

  // Under the symmetric rule: the first two members, and the atom or fluent,
  // where one claimed what the other writes in a way that does not commute.
  struct Conflict {
    int first = 0, second = 0;
    bool fluent = false;
    int key = 0;
  };
  std::optional<Conflict> symmetric_conflict() const;
  // The same pairwise rule between a member of `earlier` (first) and one of
  // this happening (second): the epsilon-separated rule
  // (JudgeOptions::epsilon_separation) asks it of happenings at distinct
  // times closer than epsilon, which a planner separating interfering
  // happenings by epsilon (Fox & Long 2003, section 5) cannot produce.
  std::optional<Conflict> conflict_with_earlier(const Ownership& earlier) const;

 private:
  struct Claims {
    std::set<int> reads, adds, deletes, fluent_reads, increases, assigns;
  };
  // Whether one member's claims and another's do not commute: the fluent
  // flag and the key of the first clash.
  static std::optional<std::pair<bool, int>> pair_conflict(const Claims& x, const Claims& y);
  std::map<int, Claims> claims_;  // every claim of each member, granted or not

  enum class Kind : unsigned char { Read, Add, Delete, ReadAdd, ReadDelete, Assign };
  struct Claim {
    int owner;
    Kind kind;
  };
  std::map<int, Claim> facts_, fluents_;
};

}  // namespace alplan::oracle
