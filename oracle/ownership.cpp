#include "oracle/ownership.h"

namespace alplan::oracle {

bool Ownership::read_fact(int member, int atom) {
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
  auto [it, fresh] = facts_.emplace(atom, Claim{member, Kind::Delete});
  if (fresh) return true;
  Claim& c = it->second;
  if (c.kind == Kind::Delete) return true;  // several members may delete one fact
  if (c.owner != member) return false;
  if (c.kind == Kind::Read) c.kind = Kind::ReadDelete;
  return true;
}

bool Ownership::read_fluent(int member, int fluent) {
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

}  // namespace alplan::oracle
