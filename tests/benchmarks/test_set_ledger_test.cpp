#include "benchmarks/harness/test_set_ledger.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

using namespace alplan::bench;

namespace {

namespace fs = std::filesystem;

// A git tree of its own with one committed file and a committed, empty
// ledger where the harness keeps it; its HEAD commit.
struct Tree {
  fs::path dir;
  std::string commit;

  explicit Tree(const std::string& name) : dir(fs::temp_directory_path() / ("alplan-ledger-" + name)) {
    fs::remove_all(dir);
    fs::create_directories(dir / "benchmarks");
    std::ofstream(dir / "code.txt") << "one\n";
    std::ofstream(dir / "benchmarks" / "test_set_ledger.jsonl");
    git("init -q");
    git("add code.txt benchmarks/test_set_ledger.jsonl");
    git("-c user.name=test -c user.email=test@example.org commit -q -m first");
    commit = head();
  }
  ~Tree() { fs::remove_all(dir); }

  void git(const std::string& arguments) const {
    const std::string command = "git -C '" + dir.string() + "' " + arguments + " > /dev/null 2>&1";
    REQUIRE(std::system(command.c_str()) == 0);
  }
  std::string head() const {
    const fs::path out = dir.string() + ".head";
    const std::string command = "git -C '" + dir.string() + "' rev-parse HEAD > '" + out.string() + "'";
    REQUIRE(std::system(command.c_str()) == 0);
    std::string text;
    std::ifstream(out) >> text;
    fs::remove(out);
    return text;
  }
  TestSetRunOptions options(const std::string& reason) const { return {"", dir.string(), reason, "", {commit, false}}; }
  std::string ledger() const { return (dir / "benchmarks" / "test_set_ledger.jsonl").string(); }
};

const TestSetRunHead kHead{"instances 6-10", "bench stability", "alplan bench stability --problems 6-10", "out"};

}  // namespace

TEST_CASE("a run touches the test set where any instance is 6 to 10") {
  CHECK_FALSE(instance_test_set({1, 2, 3, 4, 5}));
  CHECK_FALSE(instance_test_set({}));
  CHECK_FALSE(instance_test_set({0, 11, 12}));  // list files number 0; 11 is no declared test set
  CHECK(instance_test_set({5, 6}) == std::optional<std::string>("instances 6-10"));
  CHECK(instance_test_set({10}) == std::optional<std::string>("instances 6-10"));
}

TEST_CASE("a run touches the held-out homes where any home's seed is 1001 to 2000") {
  const std::optional<std::string> held_out("held-out homes (seeds 1001-2000)");
  CHECK_FALSE(home_test_set(1, 40));      // the studies' homes, seeds 1-40
  CHECK_FALSE(home_test_set(1, 1000));    // seeds 1-1000: the last is 1000
  CHECK(home_test_set(1, 1001) == held_out);
  CHECK(home_test_set(2000, 5) == held_out);
  CHECK_FALSE(home_test_set(2001, 40));
  CHECK_FALSE(home_test_set(1500, 0));    // no home, no run
  CHECK_FALSE(home_test_set(UINT64_MAX - 1, 1003));  // wraps: seeds MAX-1, MAX, 0-1000
  CHECK(home_test_set(UINT64_MAX - 1, 1004) == held_out);  // wraps: seeds MAX-1, MAX, 0-1001
}

TEST_CASE("the ledger records a run's start and its result, and reads back") {
  const Tree tree("records");
  TestSetRun run(kHead, tree.options("lmcut proves stable's repairs"));
  run.finish({{"valid", 100}});
  const std::vector<nlohmann::json> lines = read_ledger(tree.ledger());
  REQUIRE(lines.size() == 2);
  CHECK(lines[0]["status"] == "started");
  CHECK(lines[0]["commit"] == tree.commit);
  CHECK(lines[0]["reason"] == "lmcut proves stable's repairs");
  CHECK(lines[0]["test_set"] == "instances 6-10");
  CHECK(lines[0]["harness"] == "bench stability");
  CHECK(lines[1]["status"] == "finished");
  CHECK(lines[1]["id"] == lines[0]["id"]);
  CHECK(lines[1]["result"]["valid"] == 100);
}

TEST_CASE("the ledger refuses a run without a reason, from a dirty tree or another binary") {
  const Tree tree("refuses");
  CHECK_THROWS_AS(TestSetRun(kHead, tree.options("")), TestSetRefused);
  TestSetRunOptions dirty_binary = tree.options("a change");
  dirty_binary.build.dirty = true;
  CHECK_THROWS_AS(TestSetRun(kHead, dirty_binary), TestSetRefused);
  TestSetRunOptions other_commit = tree.options("a change");
  other_commit.build.commit = std::string(40, 'a');
  CHECK_THROWS_AS(TestSetRun(kHead, other_commit), TestSetRefused);
  std::ofstream(tree.dir / "code.txt") << "two\n";
  CHECK_THROWS_WITH(TestSetRun(kHead, tree.options("a change")), Catch::Contains("uncommitted changes"));
  // Nothing refused was written.
  CHECK(read_ledger(tree.ledger()).empty());
  // Not a git tree at all.
  TestSetRunOptions nowhere = tree.options("a change");
  nowhere.source_dir = (tree.dir / "benchmarks").string() + "-not-there";
  nowhere.ledger = (tree.dir.string() + "-elsewhere.jsonl");
  CHECK_THROWS_WITH(TestSetRun(kHead, nowhere), Catch::Contains("no git tree"));
}

TEST_CASE("a second run of a test set at one commit needs a stated repeat, and both stay") {
  const Tree tree("repeat");
  TestSetRun(kHead, tree.options("first look")).finish({{"distance", -1.02}});
  // The ledger itself changed: that does not make the tree dirty.
  CHECK_THROWS_WITH(TestSetRun(kHead, tree.options("again")), Catch::Contains("--repeat"));
  TestSetRunOptions repeat = tree.options("again");
  repeat.repeat = "the first run's binary was stale";
  TestSetRun(kHead, repeat).finish({{"distance", -2.15}});
  const std::vector<nlohmann::json> lines = read_ledger(tree.ledger());
  REQUIRE(lines.size() == 4);
  CHECK(lines[2]["repeat"] == "the first run's binary was stale");
  CHECK(lines[3]["result"]["distance"] == -2.15);
  // Another harness on the same test set is another run.
  TestSetRunHead planners = kHead;
  planners.harness = "bench planners";
  CHECK_NOTHROW(TestSetRun(planners, tree.options("the planner's change")));
}

TEST_CASE("a ledger line that is not JSON is named by its line") {
  const Tree tree("broken");
  std::ofstream(tree.ledger()) << "{\"id\": 1}\nnot json\n";
  CHECK_THROWS_WITH(read_ledger(tree.ledger()), Catch::Contains("test_set_ledger.jsonl:2"));
}
