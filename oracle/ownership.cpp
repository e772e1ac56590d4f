#include "oracle/ownership.h"

#include <iterator>
#include <utility>

namespace alplan::oracle {

bool Ownership::read_fact(int member, int atom) {
  claims_[member].reads.insert(atom);
  auto [it, fresh] = facts_.emplace(atom, Claim{member, Kind::Read});
  if (fresh) return true;
  Claim& c = it->second;
  if (c.kind == Kind::Read) {
    if (c.owner != member) c.owner = kShared;
    return true;
  }
  return c.owner == member;  // a read of what a member itself writes
}

bool Ownership::add_fact(int member, int atom) {
  claims_[member].adds.insert(atom);
  auto [it, fresh] = facts_.emplace(atom, Claim{member, Kind::Add});
  if (fresh) return true;
  Claim& c = it->second;
  if (c.kind == Kind::Add) return true;  // several members may add one fact
  if (c.owner != member) return false;
  switch (c.kind) {
    case Kind::Read: c.kind = Kind::ReadAdd; return true;
    case Kind::Delete: return true;  // one member adds and deletes: the add wins
    default: return false;           // read and written already, by this member
  }
}

bool Ownership::delete_fact(int member, int atom) {
  claims_[member].deletes.insert(atom);
  auto [it, fresh] = facts_.emplace(atom, Claim{member, Kind::Delete});
  if (fresh) return true;
  Claim& c = it->second;
  if (c.kind == Kind::Delete) return true;  // several members may delete one fact
  if (c.owner != member) return false;
  if (c.kind == Kind::Read) c.kind = Kind::ReadDelete;
  return true;
}

bool Ownership::read_fluent(int member, int fluent) {
  claims_[member].fluent_reads.insert(fluent);
  auto [it, fresh] = fluents_.emplace(fluent, Claim{member, Kind::Read});
  if (fresh) return true;
  Claim& c = it->second;
  if (c.owner == member) return true;
  if (c.kind == Kind::Read) {
    c.owner = kShared;
    return true;
  }
  return false;
}

bool Ownership::write_fluent(int member, int fluent, bool additive) {
  (additive ? claims_[member].increases : claims_[member].assigns).insert(fluent);
  const Kind kind = additive ? Kind::Add : Kind::Assign;
  auto [it, fresh] = fluents_.emplace(fluent, Claim{member, kind});
  if (fresh) return true;
  Claim& c = it->second;
  if (c.owner != member) {
    if (c.kind == Kind::Add && additive) {
      c.owner = kShared;
      return true;
    }
    return false;
  }
  if (c.kind == Kind::Read) {
    c.kind = kind;
    return true;
  }
  return c.kind == Kind::Add && additive;
}

namespace {

std::optional<int> common(const std::set<int>& a, const std::set<int>& b) {
  for (int k : a) {
    if (b.count(k)) return k;
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::pair<bool, int>> Ownership::pair_conflict(const Claims& x, const Claims& y) {
  for (const auto& [p, q] : {std::pair{&x, &y}, std::pair{&y, &x}}) {
    // A fact: read by one and written by the other, or added by one and
    // deleted by the other (a member both adding and deleting it counts as
    // both).
    if (auto key = common(p->reads, q->adds)) return std::pair{false, *key};
    if (auto key = common(p->reads, q->deletes)) return std::pair{false, *key};
    if (auto key = common(p->adds, q->deletes)) return std::pair{false, *key};
    // A fluent: read by one and written by the other; assigned by one and
    // written in any way by the other (increases commute).
    if (auto key = common(p->fluent_reads, q->increases)) return std::pair{true, *key};
    if (auto key = common(p->fluent_reads, q->assigns)) return std::pair{true, *key};
    if (auto key = common(p->assigns, q->increases)) return std::pair{true, *key};
    if (auto key = common(p->assigns, q->assigns)) return std::pair{true, *key};
  }
  return std::nullopt;
}

std::optional<Ownership::Conflict> Ownership::symmetric_conflict() const {
  for (auto a = claims_.begin(); a != claims_.end(); ++a) {
    for (auto b = std::next(a); b != claims_.end(); ++b) {
      if (const auto c = pair_conflict(a->second, b->second)) return Conflict{a->first, b->first, c->first, c->second};
    }
  }
  return std::nullopt;
}

std::optional<Ownership::Conflict> Ownership::conflict_with_earlier(const Ownership& earlier) const {
  for (const auto& [a, x] : earlier.claims_) {
    for (const auto& [b, y] : claims_) {
      if (const auto c = pair_conflict(x, y)) return Conflict{a, b, c->first, c->second};
    }
  }
  return std::nullopt;
}

}  // namespace alplan::oracle
