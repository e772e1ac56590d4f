#include "repair/person_search.h"

#include <algorithm>

#include "repair/travel_times.h"

namespace alplan::repair {
namespace {

std::optional<std::string> believed_place(const WorldState& belief, const std::string& predicate,
                                          const std::string& person) {
  // Atoms are ordered by head, then subject: the person's are together.
  for (auto it = belief.atoms.lower_bound({predicate, person}); it != belief.atoms.end(); ++it) {
    const AtomKey& a = *it;
    if (a.size() < 2 || a[0] != predicate || a[1] != person) break;
    if (a.size() == 3) return a[2];
  }
  return std::nullopt;
}

}  // namespace

bool PersonSearch::update(const std::set<std::string>& persons, const std::set<std::string>& rooms, double time,
                          WorldState& belief) {
  if (!rooms.empty()) last_rooms_ = rooms;
  bool changed = false;
  for (const std::string& person : persons) {
    const std::optional<std::string> place = believed_place(belief, options_.location_predicate, person);
    auto it = searches_.find(person);
    // Believed somewhere no guess put them, or at the guess while a robot
    // looks there (the camera confirmed it): seen, so not lost.
    const bool seen = place && (it == searches_.end() || it->second.guess != place || rooms.count(*place));
    if (seen) {
      if (it != searches_.end()) searches_.erase(it);
      continue;
    }
    if (it == searches_.end()) it = searches_.emplace(person, Search{time, {}, std::nullopt, {}}).first;
    Search& search = it->second;
    for (const std::string& room : rooms) {
      if (std::find(search.looked_in.begin(), search.looked_in.end(), room) == search.looked_in.end()) {
        search.looked_in.push_back(room);
      }
    }
    if (place) continue;  // the guess stands until a robot looks there
    const std::optional<std::string> guess = nearest_unsearched(search, last_rooms_, belief);
    changed = changed || guess != search.guess;
    search.guess = guess;
    if (!guess) continue;  // looked everywhere
    const AtomKey fact{options_.location_predicate, person, *guess};
    belief.set(fact, true);
    search.assumed.insert(to_string(fact));
  }
  return changed;
}

// The nearest place not looked in by shortest travel time from the places
// the robots are in, by name among equals; with no robot placed yet, the
// first by name.
std::optional<std::string> PersonSearch::nearest_unsearched(const Search& search, const std::set<std::string>& from,
                                                            const WorldState& belief) const {
  Ways ways;
  std::set<std::string> places;
  for (const AtomKey& a : belief.atoms) {
    if (a.size() != 3 || a[0] != options_.path_predicate) continue;
    const auto time = belief.values.find({options_.distance_function, a[1], a[2]});
    ways[a[1]].emplace_back(a[2], time == belief.values.end() ? 1.0 : time->second);
    places.insert({a[1], a[2]});
  }
  const auto unsearched = [&](const std::string& place) {
    return std::find(search.looked_in.begin(), search.looked_in.end(), place) == search.looked_in.end();
  };
  if (from.empty()) {
    const auto first = std::find_if(places.begin(), places.end(), unsearched);
    return first == places.end() ? std::nullopt : std::optional<std::string>(*first);
  }
  std::optional<std::string> best;
  double best_time = 0.0;
  for (const auto& [place, time] : shortest_times(ways, from)) {  // places with no way there are absent
    if (places.count(place) && unsearched(place) && (!best || time < best_time)) {
      best = place;
      best_time = time;
    }
  }
  return best;
}

bool PersonSearch::assumed(const std::string& condition) const {
  return std::any_of(searches_.begin(), searches_.end(),
                     [&](const auto& entry) { return entry.second.assumed.count(condition) != 0; });
}

std::optional<PersonSearch::Status> PersonSearch::status(const std::string& person) const {
  const auto it = searches_.find(person);
  if (it == searches_.end()) return std::nullopt;
  return Status{person, it->second.lost_at, it->second.looked_in, it->second.guess};
}

}  // namespace alplan::repair
