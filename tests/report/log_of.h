// The report tests' logs: JSON Lines text read as `alplan report` reads a
// file; the test fails when nothing in it is usable.
#pragma once

#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include "report/event_log.h"

namespace alplan::report::test {

inline EventLog log_of(const std::string& text) {
  std::istringstream in(text);
  std::ostringstream warnings;
  ReadResult r = read_event_log(in, "run.jsonl", warnings);
  REQUIRE(r.log);
  return *r.log;
}

}  // namespace alplan::report::test
