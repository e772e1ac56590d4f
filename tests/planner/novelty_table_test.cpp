#include "planner/novelty_table.h"

#include <catch2/catch.hpp>

using namespace alplan;

namespace {

SearchState state_with(std::initializer_list<FactId> facts, std::vector<double> values = {}) {
  SearchState s(130, std::move(values));  // three words of facts
  for (FactId f : facts) s.set_fact(f, true);
  return s;
}

}  // namespace

TEST_CASE("a state is novel when it holds a fact no earlier state of its h held") {
  NoveltyTable table;
  CHECK(table.novelty(5.0, state_with({1, 70})) == 1);
  CHECK(table.novelty(5.0, state_with({1})) == 2);       // nothing new
  CHECK(table.novelty(5.0, state_with({1, 70})) == 2);   // the same state again
  CHECK(table.novelty(5.0, state_with({129})) == 1);     // a fact in the last word
  CHECK(table.novelty(5.0, state_with({1, 129})) == 2);  // both seen, if never together
}

TEST_CASE("novelty is kept apart per h: a fact seen under one h is new under another") {
  NoveltyTable table;
  CHECK(table.novelty(3.0, state_with({2})) == 1);
  CHECK(table.novelty(4.0, state_with({2})) == 1);
  CHECK(table.novelty(3.0, state_with({2})) == 2);
  CHECK(table.partitions() == 2);
}

TEST_CASE("numeric values and running actions are atoms of novelty too") {
  NoveltyTable table;
  CHECK(table.novelty(1.0, state_with({}, {0.0, 2.5})) == 1);
  CHECK(table.novelty(1.0, state_with({}, {0.0, 2.5})) == 2);
  CHECK(table.novelty(1.0, state_with({}, {2.5, 2.5})) == 1);  // variable 0 at 2.5 is new; the value alone is not
  CHECK(table.novelty(1.0, state_with({}, {2.5, 0.0})) == 1);
  SearchState running = state_with({}, {2.5, 0.0});
  CHECK(table.novelty(1.0, running) == 2);
  running.start(RunningAction{7, 0, 1.0, 1.0});
  CHECK(table.novelty(1.0, running) == 1);
  CHECK(table.novelty(1.0, running) == 2);
}

TEST_CASE("width 2: a state of seen facts is new when two of them were never held together") {
  NoveltyTable table(2);
  CHECK(table.novelty(2.0, state_with({1, 2})) == 1);
  CHECK(table.novelty(2.0, state_with({3, 4})) == 1);
  CHECK(table.novelty(2.0, state_with({1, 2})) == 3);
  CHECK(table.novelty(2.0, state_with({1, 4})) == 2);  // 1 and 4 seen, never together
  CHECK(table.novelty(2.0, state_with({1, 4})) == 3);
  CHECK(table.novelty(2.0, state_with({0, 129})) == 1);
  // The novel state's pairs were recorded too: {0, 129} is no longer new.
  CHECK(table.novelty(2.0, state_with({0, 129, 1})) == 2);  // (0, 1) and (1, 129) are
  CHECK(table.novelty(2.0, state_with({0, 129})) == 3);
}

TEST_CASE("width 2 leaves pairs out above its number of facts, and answers as width 1 there") {
  NoveltyTable table(2, 64);  // the states below have 192 fact slots
  CHECK(table.novelty(1.0, state_with({1, 2})) == 1);
  CHECK(table.novelty(1.0, state_with({3, 4})) == 1);
  CHECK(table.novelty(1.0, state_with({1, 4})) == 3);
}
