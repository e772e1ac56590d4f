// The soak benchmark: many simulated wristbands against one service for a
// long time while faults are injected, then every reading and stress event
// accounted for. Faults: commits that fail (SQLite's commit hook vetoes a
// fraction of them, as a full disk would), the service stopped and started
// again on the same port and database, and clients that connect, send half
// a request and stall. Every senior is the simulator's typical subject, so
// each stressed senior must raise exactly one "stressed" event and the calm
// ones none, however the faults fall.
//
// Not a unit test: `alplan bench soak` runs it (10 minutes for the README's
// figures); the tests run a short one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <iosfwd>

namespace alplan::perception::service {

struct SoakOptions {
  std::size_t devices = 1000;
  double duration_s = 600.0;  // of signal, played in real time (times speed)
  double speed = 1.0;
  double rate_hz = 0.2;  // the board's: one reading per wristband every 5 s
  double commit_failure_rate = 0.02;  // of commits, vetoed at random
  double restart_every_s = 120.0;     // 0: never
  std::size_t stalled_clients = 20;   // connections that stall mid-request, reconnecting
  std::size_t connections = 16;       // the fleet's client threads
  std::size_t handler_threads = 4;
  std::uint64_t seed = 1;
  std::filesystem::path work_dir = "build/bench-soak";
};

struct SoakReport {
  std::uint64_t offered = 0;        // readings the wristbands made
  std::uint64_t acknowledged = 0;   // answered 2xx (stored or duplicate)
  std::uint64_t stored = 0;         // rows in the database afterwards
  std::uint64_t lost = 0;           // acknowledged but not stored, or made but never acknowledged
  std::uint64_t events_stored = 0;
  std::uint64_t events_published = 0;
  std::uint64_t duplicate_events = 0;  // a senior's state raised twice in a row (stored or published)
  std::uint64_t missed_events = 0;     // stressed seniors with no event, or calm ones with one
  std::uint64_t commit_failures = 0;   // injected
  std::uint64_t restarts = 0;
  std::uint64_t stalled_connections = 0;  // opened by the stalling clients
  std::uint64_t retries = 0;
  double client_p50_ms = 0.0, client_p99_ms = 0.0, client_max_ms = 0.0;
  double wall_s = 0.0;
  bool passed() const { return lost == 0 && duplicate_events == 0 && missed_events == 0 && offered > 0; }
};

// Runs the soak; throws std::invalid_argument for bad options and
// std::runtime_error when the service cannot start.
SoakReport run_soak(const SoakOptions& options);

void print_soak_report(std::ostream& out, const SoakOptions& options, const SoakReport& report);

}  // namespace alplan::perception::service
