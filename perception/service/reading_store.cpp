#include "perception/service/reading_store.h"

#include <algorithm>

namespace alplan::perception::service {
namespace {

constexpr int kSchemaVersion = 1;

constexpr const char* kSchema = R"sql(
CREATE TABLE IF NOT EXISTS readings (
  device TEXT NOT NULL,
  boot INTEGER NOT NULL,
  seq INTEGER NOT NULL,
  t_ms INTEGER NOT NULL,
  window_ms INTEGER NOT NULL,
  hr_bpm REAL,
  ibi_ms REAL,
  sdnn_ms REAL,
  rmssd_ms REAL,
  beats INTEGER NOT NULL,
  rejected_fraction REAL NOT NULL,
  motion INTEGER NOT NULL,
  received_ms INTEGER NOT NULL,
  PRIMARY KEY (device, boot, seq)
) WITHOUT ROWID;
CREATE INDEX IF NOT EXISTS readings_by_time ON readings (device, t_ms);
CREATE INDEX IF NOT EXISTS readings_by_arrival ON readings (received_ms);
CREATE TABLE IF NOT EXISTS stress_events (
  id INTEGER PRIMARY KEY,
  senior TEXT NOT NULL,
  device TEXT NOT NULL,
  stressed INTEGER NOT NULL,
  t_ms INTEGER NOT NULL,
  stressed_fraction REAL NOT NULL,
  votes INTEGER NOT NULL,
  recorded_ms INTEGER NOT NULL
);
)sql";

constexpr const char* kReadingColumns =
    "device, boot, seq, t_ms, window_ms, hr_bpm, ibi_ms, sdnn_ms, rmssd_ms, beats, rejected_fraction, motion";

}  // namespace

ReadingStore::ReadingStore(const std::filesystem::path& file, Durability durability, StoreAccess access)
    : db_(file, access == StoreAccess::ReadOnly) {
  if (access == StoreAccess::ReadOnly) return;
  db_.execute("PRAGMA journal_mode = WAL");
  db_.execute(durability == Durability::Full ? "PRAGMA synchronous = FULL" : "PRAGMA synchronous = NORMAL");
  create_schema();
  insert_reading_.emplace(db_.prepare(std::string("INSERT OR IGNORE INTO readings (") + kReadingColumns +
                                      ", received_ms) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"));
  insert_event_.emplace(db_.prepare(
      "INSERT INTO stress_events (senior, device, stressed, t_ms, stressed_fraction, votes, recorded_ms) "
      "VALUES (?, ?, ?, ?, ?, ?, ?)"));
}

void ReadingStore::create_schema() {
  SqliteStatement version = db_.prepare("PRAGMA user_version");
  version.step();
  const std::int64_t found = version.column_int(0);
  if (found != 0 && found != kSchemaVersion) {
    throw SqliteError("sqlite: " + db_.file().string() + " has schema version " + std::to_string(found) +
                      ", this service writes version " + std::to_string(kSchemaVersion));
  }
  db_.execute("BEGIN IMMEDIATE");
  try {
    db_.execute(kSchema);
    db_.execute("PRAGMA user_version = " + std::to_string(kSchemaVersion));
    db_.execute("COMMIT");
  } catch (...) {
    db_.execute("ROLLBACK");
    throw;
  }
}

void ReadingStore::begin() { db_.execute("BEGIN IMMEDIATE"); }
void ReadingStore::commit() { db_.execute("COMMIT"); }
void ReadingStore::rollback() {
  if (db_.in_transaction()) db_.execute("ROLLBACK");
}

bool ReadingStore::insert_reading(const ReceivedReading& r, std::int64_t received_ms) {
  SqliteStatement& s = *insert_reading_;
  s.bind(1, r.device);
  s.bind(2, static_cast<std::int64_t>(r.boot));
  s.bind(3, static_cast<std::int64_t>(r.seq));
  s.bind(4, static_cast<std::int64_t>(r.t_ms));
  s.bind(5, static_cast<std::int64_t>(r.window_ms));
  s.bind(6, r.hr_bpm);
  s.bind(7, r.ibi_ms);
  s.bind(8, r.sdnn_ms);
  s.bind(9, r.rmssd_ms);
  s.bind(10, static_cast<std::int64_t>(r.beats));
  s.bind(11, r.rejected_fraction);
  s.bind(12, static_cast<std::int64_t>(r.motion ? 1 : 0));
  s.bind(13, received_ms);
  s.step();
  s.reset();
  return db_.changes() == 1;
}

void ReadingStore::insert_stress_event(const StressEvent& e, std::int64_t recorded_ms) {
  SqliteStatement& s = *insert_event_;
  s.bind(1, e.senior);
  s.bind(2, e.device);
  s.bind(3, static_cast<std::int64_t>(e.stressed ? 1 : 0));
  s.bind(4, static_cast<std::int64_t>(e.t_ms));
  s.bind(5, e.stressed_fraction);
  s.bind(6, static_cast<std::int64_t>(e.votes));
  s.bind(7, recorded_ms);
  s.step();
  s.reset();
}

std::vector<BootSequence> ReadingStore::boot_sequences() {
  SqliteStatement q = db_.prepare("SELECT device, boot, MAX(seq), COUNT(*) FROM readings GROUP BY device, boot");
  std::vector<BootSequence> out;
  while (q.step()) {
    out.push_back({q.column_text(0), static_cast<std::uint32_t>(q.column_int(1)),
                   static_cast<std::uint32_t>(q.column_int(2)), static_cast<std::uint64_t>(q.column_int(3))});
  }
  return out;
}

std::uint64_t ReadingStore::count_readings() {
  SqliteStatement q = db_.prepare("SELECT COUNT(*) FROM readings");
  q.step();
  return static_cast<std::uint64_t>(q.column_int(0));
}

std::vector<ReceivedReading> ReadingStore::select_readings(SqliteStatement& q) {
  std::vector<ReceivedReading> out;
  while (q.step()) {
    ReceivedReading r;
    r.device = q.column_text(0);
    r.boot = static_cast<std::uint32_t>(q.column_int(1));
    r.seq = static_cast<std::uint32_t>(q.column_int(2));
    r.t_ms = static_cast<std::uint64_t>(q.column_int(3));
    r.window_ms = static_cast<std::uint32_t>(q.column_int(4));
    r.hr_bpm = q.column_optional_double(5);
    r.ibi_ms = q.column_optional_double(6);
    r.sdnn_ms = q.column_optional_double(7);
    r.rmssd_ms = q.column_optional_double(8);
    r.beats = static_cast<std::uint32_t>(q.column_int(9));
    r.rejected_fraction = q.column_double(10);
    r.motion = q.column_int(11) != 0;
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<ReceivedReading> ReadingStore::readings_of(const std::string& device) {
  SqliteStatement q =
      db_.prepare(std::string("SELECT ") + kReadingColumns + " FROM readings WHERE device = ? ORDER BY boot, seq");
  q.bind(1, device);
  return select_readings(q);
}

std::vector<ReceivedReading> ReadingStore::latest_readings_of(const std::string& device, std::size_t limit,
                                                             std::int64_t max_t_ms) {
  SqliteStatement q = db_.prepare(std::string("SELECT ") + kReadingColumns +
                                  " FROM readings WHERE device = ? AND t_ms <= ?"
                                  " ORDER BY t_ms DESC, boot DESC, seq DESC LIMIT ?");
  q.bind(1, device);
  q.bind(2, max_t_ms);
  q.bind(3, static_cast<std::int64_t>(limit));
  std::vector<ReceivedReading> out = select_readings(q);
  std::reverse(out.begin(), out.end());
  return out;
}

std::size_t ReadingStore::delete_readings_received_before(std::int64_t cutoff_ms, std::size_t limit) {
  // Row values instead of DELETE ... LIMIT, which SQLite builds leave out by default.
  SqliteStatement q = db_.prepare(
      "DELETE FROM readings WHERE (device, boot, seq) IN "
      "(SELECT device, boot, seq FROM readings WHERE received_ms < ? LIMIT ?)");
  q.bind(1, cutoff_ms);
  q.bind(2, static_cast<std::int64_t>(limit));
  q.step();
  return static_cast<std::size_t>(db_.changes());
}

std::size_t ReadingStore::delete_stress_events_recorded_before(std::int64_t cutoff_ms) {
  SqliteStatement q = db_.prepare("DELETE FROM stress_events WHERE recorded_ms < ?");
  q.bind(1, cutoff_ms);
  q.step();
  return static_cast<std::size_t>(db_.changes());
}

std::size_t ReadingStore::delete_home_events_recorded_before(std::int64_t cutoff_ms) {
  SqliteStatement exists = db_.prepare("SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = 'home_events'");
  if (!exists.step()) return 0;
  SqliteStatement q = db_.prepare("DELETE FROM home_events WHERE recorded_ms < ?");
  q.bind(1, cutoff_ms);
  q.step();
  return static_cast<std::size_t>(db_.changes());
}

std::vector<StressEvent> ReadingStore::stress_events() {
  SqliteStatement q = db_.prepare(
      "SELECT senior, device, stressed, t_ms, stressed_fraction, votes FROM stress_events ORDER BY id");
  std::vector<StressEvent> out;
  while (q.step()) {
    out.push_back({q.column_text(0), q.column_text(1), q.column_int(2) != 0, static_cast<std::uint64_t>(q.column_int(3)),
                   q.column_double(4), static_cast<std::size_t>(q.column_int(5))});
  }
  return out;
}

}  // namespace alplan::perception::service
