// Runs one command in a child process under a wall-clock limit and an
// address-space limit, and measures it: the way the IPC and the reference
// runs in ../shared/benchmarks/baseline measured planners (one process per
// run, limits enforced by the operating system).
#pragma once

#include <string>
#include <vector>

namespace alplan::bench {

struct RunLimits {
  double seconds = 60.0;
  double memory_mib = 4096.0;  // RLIMIT_AS
};

struct RunResult {
  int exit_code = -1;        // when the child exited
  int signal = 0;            // when it was killed by a signal
  bool timed_out = false;
  double wall_seconds = 0.0;
  long max_rss_kib = 0;
  std::string out;           // standard output
  std::string err;           // standard error (last 64 KiB)
};

RunResult run_process(const std::vector<std::string>& argv, const RunLimits& limits);

// `text` as one word for /bin/sh: in single quotes, each ' closed, escaped
// and reopened.
std::string shell_quoted(const std::string& text);

// The running executable's own path (/proc/self/exe), so the harness can
// start `alplan` subcommands as child processes.
std::string self_executable();

// This process's own argv (/proc/self/cmdline), the first made absolute
// (self_executable), so the command can be run again elsewhere: what a
// Slurm array task runs (slurm_array.h).
std::vector<std::string> own_command_line();

}  // namespace alplan::bench
