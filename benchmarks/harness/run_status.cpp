#include "benchmarks/harness/run_status.h"

#include <csignal>

namespace alplan::bench {
namespace {

constexpr int kExitLimit = 11;  // alplan plan: limits reached

bool out_of_memory(const RunResult& run) {
  const bool aborted = run.signal == SIGABRT || run.exit_code == 128 + SIGABRT;
  return aborted && run.err.find("std::bad_alloc") != std::string::npos;
}

}  // namespace

std::string planner_run_status(const RunResult& run, const nlohmann::json& output) {
  if (run.timed_out || out_of_memory(run)) return "limit";
  if (output.is_discarded() || !output.is_object() || !output.contains("status")) {
    return run.exit_code == kExitLimit ? "limit" : "error";
  }
  const std::string s = output["status"];
  if (s == "solved") return "solved";
  if (s == "unsolvable") return "unsolvable";
  if (s == "exhausted") return "exhausted";
  if (s == "limit_reached") return "limit";
  return "error";
}

}  // namespace alplan::bench
