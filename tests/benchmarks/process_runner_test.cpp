#include "benchmarks/harness/process_runner.h"

#include <catch2/catch.hpp>

using alplan::bench::run_process;

TEST_CASE("the process runner captures output and the exit code") {
  const auto r = run_process({"/bin/sh", "-c", "echo out; echo err >&2; exit 3"}, {10, 512});
  CHECK(r.exit_code == 3);
  CHECK(r.out == "out\n");
  CHECK(r.err == "err\n");
  CHECK_FALSE(r.timed_out);
  CHECK(r.max_rss_kib > 0);
}

TEST_CASE("the process runner kills a run at the wall-clock limit") {
  const auto r = run_process({"/bin/sh", "-c", "sleep 30"}, {0.3, 512});
  CHECK(r.timed_out);
  CHECK(r.wall_seconds < 5);
}

TEST_CASE("the process runner enforces the memory limit") {
  // Allocating 256 MiB under a 64 MiB address-space limit must fail.
  const auto r = run_process({"/usr/bin/python3", "-c", "x = bytearray(256 * 1024 * 1024)"}, {10, 64});
  CHECK(r.exit_code != 0);
}

TEST_CASE("a missing executable is an exit code, not a crash") {
  const auto r = run_process({"/no/such/program"}, {5, 256});
  CHECK(r.exit_code == 127);
}
