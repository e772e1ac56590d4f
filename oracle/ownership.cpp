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

std::optional<Ownership::Conflict> Ownership::symmetric_conflict() const {
  for (auto a = claims_.begin(); a != claims_.end(); ++a) {
    for (auto b = std::next(a); b != claims_.end(); ++b) {
      const Claims& x = a->second;
      const Claims& y = b->second;
      auto found = [&](std::optional<int> key, bool fluent) -> std::optional<Conflict> {
        if (!key) return std::nullopt;
        return Conflict{a->first, b->first, fluent, *key};
      };
      // A fact: read by one and written by the other, or added by one and
      // deleted by the other (a member both adding and deleting it counts
      // as both).
      for (const auto& [p, q] : {std::pair{&x, &y}, std::pair{&y, &x}}) {
        if (auto c = found(common(p->reads, q->adds), false)) return c;
        if (auto c = found(common(p->reads, q->deletes), false)) return c;
        if (auto c = found(common(p->adds, q->deletes), false)) return c;
        // A fluent: read by one and written by the other; assigned by one
        // and written in any way by the other (increases commute).
        if (auto c = found(common(p->fluent_reads, q->increases), true)) return c;
        if (auto c = found(common(p->fluent_reads, q->assigns), true)) return c;
        if (auto c = found(common(p->assigns, q->increases), true)) return c;
        if (auto c = found(common(p->assigns, q->assigns), true)) return c;
      }
    }
  }
  return std::nullopt;
}

}  // namespace alplan::oracle
