#include "repair/person_search.h"

#include <catch2/catch.hpp>

using namespace alplan;
using repair::AtomKey;
using repair::PersonSearch;
using repair::WorldState;

namespace {

// Five places in a line, a - b - c - d - e, with travel times 1, 2, 3, 4
// each way, and a side room f off b at 10: the nearest place from b is a
// (1), then c (2), then c's neighbour d (5 from b), then f (10), then e (9
// via c and d: 2 + 3 + 4).
WorldState home() {
  WorldState w;
  const auto way = [&](const std::string& x, const std::string& y, double t) {
    w.set({"path", x, y}, true);
    w.set({"path", y, x}, true);
    w.values[{"moving_time", x, y}] = t;
    w.values[{"moving_time", y, x}] = t;
  };
  way("a", "b", 1);
  way("b", "c", 2);
  way("c", "d", 3);
  way("d", "e", 4);
  way("b", "f", 10);
  w.set({"be", "robot1", "b"}, true);
  return w;
}

std::optional<std::string> place_of(const WorldState& w, const std::string& person) {
  for (const AtomKey& a : w.atoms) {
    if (a.size() == 3 && a[0] == "be" && a[1] == person) return a[2];
  }
  return std::nullopt;
}

}  // namespace

TEST_CASE("person search: a person believed somewhere is not searched for") {
  WorldState w = home();
  w.set({"be", "ann", "c"}, true);
  PersonSearch search({});
  CHECK_FALSE(search.update({"ann"}, {"b"}, 10.0, w));
  CHECK(place_of(w, "ann") == "c");
  CHECK_FALSE(search.status("ann"));
}

TEST_CASE("person search: nearest first by travel time, each place looked in once, then nothing") {
  WorldState w = home();  // ann was in b; the robot got there and saw it empty
  PersonSearch search({});
  CHECK(search.update({"ann"}, {"b"}, 10.0, w));
  CHECK(place_of(w, "ann") == "a");
  CHECK(search.assumed("(be ann a)"));
  CHECK_FALSE(search.assumed("(be ann b)"));  // what the problem said is a failure, not a guess
  REQUIRE(search.status("ann"));
  CHECK(search.status("ann")->lost_at == 10.0);
  CHECK(search.status("ann")->looked_in == std::vector<std::string>{"b"});

  // On the way: the robot moves (no place), the guess stands.
  w.set({"be", "robot1", "b"}, false);
  CHECK_FALSE(search.update({"ann"}, {}, 11.0, w));
  CHECK(place_of(w, "ann") == "a");

  // At a, the camera refutes the guess (the belief drops it); from a the
  // nearest unsearched place is c (1 + 2), not f (1 + 10).
  w.set({"be", "robot1", "a"}, true);
  w.set({"be", "ann", "a"}, false);
  CHECK(search.update({"ann"}, {"a"}, 12.0, w));
  CHECK(place_of(w, "ann") == "c");
  CHECK(search.assumed("(be ann a)"));  // still a step of this search when its failure is reported

  const auto look = [&](const std::string& from, const std::string& at, double t) {
    w.set({"be", "robot1", from}, false);
    w.set({"be", "robot1", at}, true);
    w.set({"be", "ann", at}, false);
    return search.update({"ann"}, {at}, t, w);
  };
  CHECK(look("a", "c", 13.0));
  CHECK(place_of(w, "ann") == "d");  // 3 from c; f is 12
  CHECK(look("c", "d", 14.0));
  CHECK(place_of(w, "ann") == "e");  // 4 from d; f is 15
  CHECK(look("d", "e", 15.0));
  CHECK(place_of(w, "ann") == "f");
  CHECK(look("e", "f", 16.0));
  CHECK_FALSE(place_of(w, "ann"));  // every place looked in: no guess, so no plan reaches her
  CHECK(search.status("ann")->looked_in == std::vector<std::string>{"b", "a", "c", "d", "e", "f"});
  CHECK_FALSE(search.status("ann")->guess);
  CHECK_FALSE(look("f", "b", 17.0));  // and none later: one sweep per loss
}

TEST_CASE("person search: found at the guess, or seen elsewhere, the search ends") {
  WorldState w = home();
  PersonSearch search({});
  REQUIRE(search.update({"ann"}, {"b"}, 10.0, w));
  REQUIRE(place_of(w, "ann") == "a");
  // The robot reaches a and the camera sees her there: the same fact, now
  // seen, not guessed.
  w.set({"be", "robot1", "b"}, false);
  w.set({"be", "robot1", "a"}, true);
  CHECK_FALSE(search.update({"ann"}, {"a"}, 12.0, w));
  CHECK_FALSE(search.status("ann"));
  CHECK_FALSE(search.assumed("(be ann a)"));

  // Lost again; before the robot reaches the guess, she is seen in f.
  w.set({"be", "ann", "a"}, false);
  REQUIRE(search.update({"ann"}, {"a"}, 20.0, w));
  const std::optional<std::string> guess = place_of(w, "ann");
  REQUIRE(guess == "b");
  w.set({"be", "ann", *guess}, false);
  w.set({"be", "ann", "f"}, true);
  CHECK_FALSE(search.update({"ann"}, {"a"}, 21.0, w));
  CHECK_FALSE(search.status("ann"));
  CHECK(place_of(w, "ann") == "f");
}

TEST_CASE("person search: a place with no way to it is never guessed") {
  WorldState w = home();
  w.set({"path", "x", "y"}, true);  // an island: x and y are places, unreachable from b
  PersonSearch search({});
  REQUIRE(search.update({"ann"}, {"b"}, 10.0, w));
  for (const char* at : {"a", "c", "d", "e", "f"}) {
    REQUIRE(place_of(w, "ann") == at);
    w.set({"be", "ann", at}, false);
    search.update({"ann"}, {at}, 11.0, w);
  }
  CHECK_FALSE(place_of(w, "ann"));
}
