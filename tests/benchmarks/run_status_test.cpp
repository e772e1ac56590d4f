#include "benchmarks/harness/run_status.h"

#include <catch2/catch.hpp>

#include <csignal>

using namespace alplan::bench;

namespace {

RunResult exited(int code, const std::string& out = "", const std::string& err = "") {
  RunResult r;
  r.exit_code = code;
  r.out = out;
  r.err = err;
  return r;
}

nlohmann::json parsed(const RunResult& r) { return nlohmann::json::parse(r.out, nullptr, false); }

}  // namespace

TEST_CASE("a run's status follows the planner's JSON") {
  const RunResult solved = exited(0, R"({"status": "solved"})");
  CHECK(planner_run_status(solved, parsed(solved)) == "solved");
  const RunResult limit = exited(11, R"({"status": "limit_reached", "message": "memory"})");
  CHECK(planner_run_status(limit, parsed(limit)) == "limit");
  const RunResult unsolvable = exited(10, R"({"status": "unsolvable"})");
  CHECK(planner_run_status(unsolvable, parsed(unsolvable)) == "unsolvable");
}

TEST_CASE("memory running out is a limit in every phase, not an error") {
  // The CLI reports a limit reached before the planner ran by exit 11.
  const RunResult before_search = exited(11, "", "error: memory limit reached while grounding\n");
  CHECK(planner_run_status(before_search, parsed(before_search)) == "limit");
  // An allocation refused where nothing catches it aborts the process.
  RunResult aborted;
  aborted.signal = SIGABRT;
  aborted.err = "terminate called after throwing an instance of 'std::bad_alloc'\n  what():  std::bad_alloc\n";
  CHECK(planner_run_status(aborted, parsed(aborted)) == "limit");
  // Any other crash is an error.
  RunResult crashed;
  crashed.signal = SIGSEGV;
  CHECK(planner_run_status(crashed, parsed(crashed)) == "error");
  const RunResult timed_out = [] {
    RunResult r;
    r.timed_out = true;
    r.signal = SIGKILL;
    return r;
  }();
  CHECK(planner_run_status(timed_out, parsed(timed_out)) == "limit");
}
