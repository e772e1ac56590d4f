#include "benchmarks/harness/test_set_ledger.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace alplan::bench {
namespace {

constexpr const char* kLedgerInTree = "benchmarks/test_set_ledger.jsonl";

std::string shell_quoted(const std::string& word) {
  std::string out = "'";
  for (char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// A git command's output in `tree`; nullopt where git failed.
std::optional<std::string> git(const std::string& tree, const std::string& arguments) {
  // --no-optional-locks: a status must not take the index lock a
  // concurrent git command (or the build stamp) may hold.
  const std::string command = "git --no-optional-locks -C " + shell_quoted(tree) + " " + arguments + " 2>/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return std::nullopt;
  std::string out;
  std::array<char, 4096> buffer{};
  for (std::size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;) out.append(buffer.data(), n);
  if (pclose(pipe) != 0) return std::nullopt;
  return out;
}

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

double steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void append(const std::string& path, const nlohmann::json& line) {
  std::ofstream out(path, std::ios::app);
  out << line.dump() << '\n';
  out.flush();
  if (!out) throw std::runtime_error(path + ": cannot append to the test-set ledger");
}

// The tree's commit, checked clean (the ledger aside) and equal to the
// binary's; the refusal says what to do.
std::string checked_commit(const TestSetRunOptions& o) {
  const std::optional<std::string> head = git(o.source_dir, "rev-parse HEAD");
  if (!head) {
    throw TestSetRefused("no git tree at " + o.source_dir +
                         ": a run on a test set must name the commit it ran (run it from a checkout)");
  }
  const std::string commit = head->substr(0, head->find_first_of(" \n"));
  const std::optional<std::string> changes =
      git(o.source_dir, std::string("status --porcelain --untracked-files=normal -- . ':(exclude)") + kLedgerInTree + "'");
  if (!changes) throw TestSetRefused("git status failed in " + o.source_dir);
  if (!changes->empty()) {
    throw TestSetRefused("the tree at " + o.source_dir + " has uncommitted changes or untracked files (" +
                         changes->substr(0, changes->find('\n')) +
                         " ...): commit them, rebuild, and run again; a run on a test set must name the code it ran");
  }
  // The ledger is left out of the status (runs append to it), so what was
  // committed of it must still be there: lines are only ever added.
  if (const std::optional<std::string> committed = git(o.source_dir, std::string("show HEAD:") + kLedgerInTree)) {
    std::ifstream in(std::filesystem::path(o.source_dir) / kLedgerInTree, std::ios::binary);
    const std::string local((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (local.compare(0, committed->size(), *committed) != 0) {
      throw TestSetRefused(std::string(kLedgerInTree) + " no longer begins with what HEAD holds of it: a ledger's "
                           "lines are never removed or changed (git checkout the file, then run)");
    }
  }
  if (o.build.dirty || o.build.commit != commit) {
    throw TestSetRefused("this binary was built from " + o.build.commit + (o.build.dirty ? " with uncommitted changes" : "") +
                         ", the tree is at " + commit + ": rebuild from the commit, then run");
  }
  return commit;
}

// The earlier run of this test set by this harness at this commit, if any.
std::optional<nlohmann::json> earlier_run(const std::vector<nlohmann::json>& ledger, const TestSetRunHead& head,
                                          const std::string& commit) {
  for (const nlohmann::json& line : ledger) {
    if (line.value("status", "") == "started" && line.value("test_set", "") == head.test_set &&
        line.value("harness", "") == head.harness && line.value("commit", "") == commit) {
      return line;
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> instance_test_set(const std::vector<int>& instance_numbers) {
  for (int n : instance_numbers) {
    if (n >= 6 && n <= 10) return "instances 6-10";
  }
  return std::nullopt;
}

std::optional<std::string> home_test_set(std::uint64_t first_seed, std::uint64_t homes) {
  if (homes == 0) return std::nullopt;
  const std::uint64_t last_seed = first_seed + (homes - 1);  // may wrap past the largest seed to 0
  const bool touches = last_seed >= first_seed
                           ? last_seed >= kHeldOutHomeSeedFirst && first_seed <= kHeldOutHomeSeedLast
                           : last_seed >= kHeldOutHomeSeedFirst || first_seed <= kHeldOutHomeSeedLast;
  if (!touches) return std::nullopt;
  return "held-out homes (seeds " + std::to_string(kHeldOutHomeSeedFirst) + "-" + std::to_string(kHeldOutHomeSeedLast) +
         ")";
}

TestSetRun::TestSetRun(TestSetRunHead head, TestSetRunOptions options) {
  ledger_ = options.ledger.empty() ? (std::filesystem::path(options.source_dir) / kLedgerInTree).string() : options.ledger;
  if (options.reason.empty()) {
    throw TestSetRefused("this run touches a test set (" + head.test_set + " of " + head.harness +
                         "): say which change it measures with --reason \"...\"; it is recorded in " + ledger_);
  }
  const std::string commit = checked_commit(options);
  if (const std::optional<nlohmann::json> earlier = earlier_run(read_ledger(ledger_), head, commit)) {
    if (options.repeat.empty()) {
      throw TestSetRefused(head.test_set + " was run by " + head.harness + " at this commit already (" +
                           earlier->value("id", "") + ", " + earlier->value("reason", "") +
                           "): a second run needs --repeat \"why\", and both stay in " + ledger_);
    }
  }
  const std::string started = utc_now();
  id_ = commit.substr(0, 10) + "-" + started;
  began_ = steady_seconds();
  nlohmann::json line = {{"id", id_},           {"status", "started"},   {"test_set", head.test_set},
                         {"harness", head.harness}, {"commit", commit},  {"started_utc", started},
                         {"reason", options.reason}, {"command", head.command}, {"out", head.out}};
  if (!options.repeat.empty()) line["repeat"] = options.repeat;
  append(ledger_, line);
}

void TestSetRun::finish(const nlohmann::json& result) {
  append(ledger_, {{"id", id_},
                   {"status", "finished"},
                   {"finished_utc", utc_now()},
                   {"wall_seconds", steady_seconds() - began_},
                   {"result", result}});
}

std::vector<nlohmann::json> read_ledger(const std::string& path) {
  std::vector<nlohmann::json> lines;
  std::ifstream in(path);
  std::string text;
  for (int number = 1; std::getline(in, text); ++number) {
    if (text.empty()) continue;
    try {
      lines.push_back(nlohmann::json::parse(text));
    } catch (const nlohmann::json::parse_error& e) {
      throw std::runtime_error(path + ":" + std::to_string(number) + ": not a JSON line: " + e.what());
    }
  }
  return lines;
}

std::string command_line() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::string out, word;
  const auto plain = [](const std::string& w) {
    return !w.empty() && std::all_of(w.begin(), w.end(), [](unsigned char c) {
      return std::isalnum(c) || std::strchr("_./=:,+-@%", c) != nullptr;
    });
  };
  while (std::getline(in, word, '\0')) {
    if (!out.empty()) out += ' ';
    out += plain(word) ? word : shell_quoted(word);
  }
  return out;
}

void check_array_build(const std::string& out, const TestSetRunOptions& options) {
  const std::string ledger =
      options.ledger.empty() ? (std::filesystem::path(options.source_dir) / kLedgerInTree).string() : options.ledger;
  for (const nlohmann::json& line : read_ledger(ledger)) {
    if (line.value("status", "") != "started" || line.value("out", "") != out) continue;
    if (options.build.dirty || options.build.commit != line.value("commit", "")) {
      throw TestSetRefused("the array in " + out + " was submitted as a test-set run at " + line.value("commit", "") +
                           " (" + line.value("id", "") + "); this binary was built from " + options.build.commit +
                           (options.build.dirty ? " with uncommitted changes" : "") +
                           ": its tasks and merge must run the submitted code");
    }
  }
}

}  // namespace alplan::bench
