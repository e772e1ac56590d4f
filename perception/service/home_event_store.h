// The running home's event log (home/event_log.h) in the signal service's
// database, beside the readings it came from (`alplan home --live`): one
// row per event, so that an operator reads what the robots did about a
// senior's stress with the same sqlite3 shell as the readings.
//
//   home_events(id, time, type, senior, robot, payload_json, recorded_ms)
//
// `time` is the run's clock (seconds since the run began), `payload_json`
// the event's fields other than type, time, senior and robot, as JSON.
//
// Its own connection, as the retention sweeper has: the ingest's connection
// belongs to the request threads, this one to the home's loop, and WAL lets
// both write in turn (SQLite's busy timeout covers the wait). The same file
// handling as the readings (SqliteDatabase: made 0600, it holds health
// data) and the same durability: with Durability::Full every event is
// synced when written. The table is created when missing; the readings'
// schema and its version are not touched, so `alplan serve` opens a
// database a live home wrote to, and the other way round.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "perception/service/reading_store.h"
#include "perception/service/sqlite_database.h"

namespace alplan::perception::service {

struct HomeEventRow {
  double time = 0.0;
  std::string type;
  std::string senior;  // empty: none concerned (stored as NULL)
  std::string robot;
  std::string payload_json = "{}";
};

class HomeEventStore {
 public:
  // Opens (or creates) the database and the table. Throws SqliteError
  // naming the file.
  explicit HomeEventStore(const std::filesystem::path& file, Durability durability = Durability::Full);

  // One row, committed on return. Not thread-safe: one writer thread.
  void insert(const HomeEventRow& row, std::int64_t recorded_ms);
  // Every row in the order written (tests, tools).
  std::vector<HomeEventRow> rows();

 private:
  SqliteDatabase db_;
  SqliteStatement insert_;
};

}  // namespace alplan::perception::service
