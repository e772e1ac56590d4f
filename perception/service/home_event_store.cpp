#include "perception/service/home_event_store.h"

namespace alplan::perception::service {
namespace {

constexpr const char* kSchema = R"sql(
CREATE TABLE IF NOT EXISTS home_events (
  id INTEGER PRIMARY KEY,
  time REAL NOT NULL,
  type TEXT NOT NULL,
  senior TEXT,
  robot TEXT,
  payload_json TEXT NOT NULL,
  recorded_ms INTEGER NOT NULL
);
CREATE INDEX IF NOT EXISTS home_events_by_senior ON home_events (senior, time);
)sql";

// The statement is prepared once the table exists.
SqliteDatabase& with_schema(SqliteDatabase& db, Durability durability) {
  db.execute("PRAGMA journal_mode = WAL");
  db.execute(durability == Durability::Full ? "PRAGMA synchronous = FULL" : "PRAGMA synchronous = NORMAL");
  db.execute(kSchema);
  return db;
}

}  // namespace

HomeEventStore::HomeEventStore(const std::filesystem::path& file, Durability durability)
    : db_(file),
      insert_(with_schema(db_, durability)
                  .prepare("INSERT INTO home_events (time, type, senior, robot, payload_json, recorded_ms) "
                           "VALUES (?, ?, ?, ?, ?, ?)")) {}

void HomeEventStore::insert(const HomeEventRow& row, std::int64_t recorded_ms) {
  insert_.bind(1, row.time);
  insert_.bind(2, row.type);
  if (row.senior.empty()) insert_.bind_null(3);
  else insert_.bind(3, row.senior);
  if (row.robot.empty()) insert_.bind_null(4);
  else insert_.bind(4, row.robot);
  insert_.bind(5, row.payload_json);
  insert_.bind(6, recorded_ms);
  try {
    insert_.step();
  } catch (...) {
    insert_.reset();
    throw;
  }
  insert_.reset();
}

std::vector<HomeEventRow> HomeEventStore::rows() {
  SqliteStatement q = db_.prepare("SELECT time, type, senior, robot, payload_json FROM home_events ORDER BY id");
  std::vector<HomeEventRow> out;
  while (q.step()) out.push_back({q.column_double(0), q.column_text(1), q.column_text(2), q.column_text(3), q.column_text(4)});
  return out;
}

}  // namespace alplan::perception::service
