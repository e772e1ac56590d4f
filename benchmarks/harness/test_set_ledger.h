// The test-set ledger (issue 43): every run on a declared test set is
// written down by the harness that makes it, so that no run on a test set
// can go unreported and no choice can silently follow one.
//
// Declared test sets: instances 6-10 of every domain of a benchmark suite
// (`bench planners`, `bench stability`; 1-5 are for tuning), and the
// held-out homes, generated homes of seeds 1001-2000 (`bench repair`,
// `bench home`; every study before them chose on seeds 1-40). The protocol,
// in the spirit of a preregistered held-out evaluation:
// - a run on a test set states the change it measures (`--reason`); without
//   one it is refused;
// - it is refused from a tree with uncommitted changes or untracked files,
//   or with a binary built from another commit or from such a tree: the
//   ledger names the code that ran, and a reader can check it out; the
//   ledger's committed lines must still open the file (lines are only added);
// - a second run of the same test set by the same harness at the same commit
//   is refused unless it says why (`--repeat`): a re-run after a result is
//   seen is the thing the ledger exists to show;
// - the run appends a "started" line before it begins and a "finished" line
//   with its result summary when it ends, so a run that crashed or was
//   stopped still stands in the ledger (started, never finished).
// The ledger is a JSON-lines file under version control
// (benchmarks/test_set_ledger.jsonl); benchmarks/README.md reports every
// entry (benchmarks/readme_figures.py's `test-set-ledger` block), never only
// the last.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "benchmarks/harness/build_info.h"

namespace alplan::bench {

// The name of the test set a run over these instance numbers touches, or
// none: "instances 6-10" where any number is within 6..10. A problem's
// number is the N of its instance-N file, else its position in its domain.
std::optional<std::string> instance_test_set(const std::vector<int>& instance_numbers);

// The held-out homes: generated homes of these seeds are a test set.
inline constexpr std::uint64_t kHeldOutHomeSeedFirst = 1001;
inline constexpr std::uint64_t kHeldOutHomeSeedLast = 2000;

// The name of the test set `homes` generated homes from `first_seed` on
// (seeds first_seed .. first_seed + homes - 1) touch, or none.
std::optional<std::string> home_test_set(std::uint64_t first_seed, std::uint64_t homes);

// A run the ledger refuses, with what to do instead.
class TestSetRefused : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct TestSetRunOptions {
  std::string ledger;      // the file; "" for <source_dir>/benchmarks/test_set_ledger.jsonl
  std::string source_dir;  // the git tree the binary was built from
  std::string reason;      // the change this run measures
  std::string repeat;      // why a second run at one commit; "" refuses it
  BuildInfo build;         // the binary's commit
};

struct TestSetRunHead {
  std::string test_set;  // instance_test_set's name
  std::string harness;   // "bench planners", "bench stability", "bench repair", "bench home"
  std::string command;   // as typed (command_line())
  std::string out;       // the results folder
};

// A run recorded in the ledger: the constructor checks the protocol and
// appends the "started" line (throws TestSetRefused, or std::runtime_error
// when the ledger cannot be written); finish appends the result.
class TestSetRun {
 public:
  TestSetRun(TestSetRunHead head, TestSetRunOptions options);
  void finish(const nlohmann::json& result);
  const std::string& id() const { return id_; }
  const std::string& ledger() const { return ledger_; }

 private:
  std::string id_, ledger_;
  double began_ = 0.0;  // steady clock, seconds
};

// Every line of a ledger, in order; none for a missing file. Throws
// std::runtime_error naming the line that is not JSON.
std::vector<nlohmann::json> read_ledger(const std::string& path);

// This process's command line (/proc/self/cmdline), each argument quoted
// for a POSIX shell where it holds more than letters, digits and _./=:,+-@%.
std::string command_line();

// A Slurm array's task or merge whose folder `out` was submitted as a
// test-set run: throws TestSetRefused unless this binary is the submitted
// commit's, clean. Nothing for an array the ledger does not hold.
void check_array_build(const std::string& out, const TestSetRunOptions& options);

}  // namespace alplan::bench
