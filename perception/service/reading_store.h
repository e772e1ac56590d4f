// Durable storage of readings and stress events in SQLite: a reading is
// acknowledged to the wristband only after the transaction that holds it has
// committed, so a restart loses nothing that was acknowledged.
//
// Tables (schema version 1, PRAGMA user_version):
//   readings(device, boot, seq, t_ms, window_ms, hr_bpm, ibi_ms, sdnn_ms,
//            rmssd_ms, beats, rejected_fraction, motion, received_ms)
//     primary key (device, boot, seq): a re-sent reading is stored once;
//     readings may arrive in any order. Indexed by (device, t_ms) for the
//     detector's priming and by received_ms for retention.
//   stress_events(id, senior, device, stressed, t_ms, stressed_fraction,
//                 votes, recorded_ms)
//
// The database runs in WAL mode, so readers (tests, an operator with the
// sqlite3 shell) do not block the writer. Durability::Full syncs the log at
// every commit (an acknowledged reading survives a power cut);
// Durability::Normal only at checkpoints (it survives the process dying, not
// the machine). Not thread-safe: one thread at a time (reading_ingest.h
// serialises the writers).
#pragma once

#include <cstdint>
#include <climits>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "perception/service/reading_message.h"
#include "perception/service/sqlite_database.h"
#include "perception/service/stress_event_queue.h"

namespace alplan::perception::service {

enum class Durability { Normal, Full };
enum class StoreAccess { ReadWrite, ReadOnly };

// The readings stored for one boot of one device: with sequence numbers
// starting at 0, max_seq + 1 - count of them are missing (lost or not yet
// arrived).
struct BootSequence {
  std::string device;
  std::uint32_t boot = 0;
  std::uint32_t max_seq = 0;
  std::uint64_t count = 0;
};

class ReadingStore {
 public:
  // Opens or creates the database. Throws SqliteError (naming the file) when
  // it cannot, or when the file holds another schema.
  explicit ReadingStore(const std::filesystem::path& file, Durability durability = Durability::Full,
                        StoreAccess access = StoreAccess::ReadWrite);

  void begin();
  void commit();
  // Rolls back the open transaction, if any (a failed COMMIT may have ended it).
  void rollback();
  // Fault injection for tests and the soak benchmark: see
  // SqliteDatabase::set_commit_veto.
  void set_commit_veto(std::function<bool()> veto) { db_.set_commit_veto(std::move(veto)); }

  // True when stored, false when (device, boot, seq) was already there.
  bool insert_reading(const ReceivedReading& reading, std::int64_t received_ms);
  void insert_stress_event(const StressEvent& event, std::int64_t recorded_ms);

  std::vector<BootSequence> boot_sequences();
  std::uint64_t count_readings();
  // One device's readings by (boot, seq).
  std::vector<ReceivedReading> readings_of(const std::string& device);
  // The device's last `limit` readings by time, oldest first, of those
  // stamped at or before `max_t_ms`.
  std::vector<ReceivedReading> latest_readings_of(const std::string& device, std::size_t limit,
                                                  std::int64_t max_t_ms = INT64_MAX);
  std::vector<StressEvent> stress_events();

  // Retention (retention_sweeper.h): deletes up to `limit` readings that
  // arrived before `cutoff_ms`, and every stress event recorded before it.
  // Return how many rows went. Call inside a transaction.
  std::size_t delete_readings_received_before(std::int64_t cutoff_ms, std::size_t limit);
  std::size_t delete_stress_events_recorded_before(std::int64_t cutoff_ms);
  // The same for the events a live home wrote (home_event_store.h), which
  // name seniors' emotions too; nothing when no home ever wrote here.
  std::size_t delete_home_events_recorded_before(std::int64_t cutoff_ms);

  const std::filesystem::path& file() const { return db_.file(); }

 private:
  void create_schema();
  std::vector<ReceivedReading> select_readings(SqliteStatement& query);

  SqliteDatabase db_;
  std::optional<SqliteStatement> insert_reading_;
  std::optional<SqliteStatement> insert_event_;
};

}  // namespace alplan::perception::service
