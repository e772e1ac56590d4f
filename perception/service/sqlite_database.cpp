#include "perception/service/sqlite_database.h"

#include <sqlite3.h>

#include "perception/service/private_file.h"

namespace alplan::perception::service {
namespace {

[[noreturn]] void fail(sqlite3* db, const std::string& what) {
  throw SqliteError("sqlite: " + what + ": " + (db != nullptr ? sqlite3_errmsg(db) : "out of memory"));
}

}  // namespace

SqliteStatement::SqliteStatement(sqlite3* db, std::string_view sql) : db_(db) {
  if (sqlite3_prepare_v3(db, sql.data(), static_cast<int>(sql.size()), SQLITE_PREPARE_PERSISTENT, &statement_,
                         nullptr) != SQLITE_OK) {
    fail(db, "cannot prepare '" + std::string(sql) + "'");
  }
}

SqliteStatement::~SqliteStatement() { sqlite3_finalize(statement_); }

SqliteStatement::SqliteStatement(SqliteStatement&& other) noexcept : db_(other.db_), statement_(other.statement_) {
  other.statement_ = nullptr;
}

void SqliteStatement::bind(int index, std::int64_t value) {
  if (sqlite3_bind_int64(statement_, index, value) != SQLITE_OK) fail(db_, "bind");
}

void SqliteStatement::bind(int index, double value) {
  if (sqlite3_bind_double(statement_, index, value) != SQLITE_OK) fail(db_, "bind");
}

void SqliteStatement::bind(int index, std::string_view text) {
  if (sqlite3_bind_text(statement_, index, text.data(), static_cast<int>(text.size()), SQLITE_TRANSIENT) !=
      SQLITE_OK) {
    fail(db_, "bind");
  }
}

void SqliteStatement::bind(int index, const std::optional<double>& value) {
  if (value) {
    bind(index, *value);
  } else {
    bind_null(index);
  }
}

void SqliteStatement::bind_null(int index) {
  if (sqlite3_bind_null(statement_, index) != SQLITE_OK) fail(db_, "bind");
}

bool SqliteStatement::step() {
  const int status = sqlite3_step(statement_);
  if (status == SQLITE_ROW) return true;
  if (status == SQLITE_DONE) return false;
  const std::string sql = sqlite3_sql(statement_);
  sqlite3_reset(statement_);
  fail(db_, "cannot run '" + sql + "'");
}

void SqliteStatement::reset() {
  sqlite3_reset(statement_);
  sqlite3_clear_bindings(statement_);
}

std::int64_t SqliteStatement::column_int(int index) const { return sqlite3_column_int64(statement_, index); }

double SqliteStatement::column_double(int index) const { return sqlite3_column_double(statement_, index); }

std::optional<double> SqliteStatement::column_optional_double(int index) const {
  if (sqlite3_column_type(statement_, index) == SQLITE_NULL) return std::nullopt;
  return sqlite3_column_double(statement_, index);
}

std::string SqliteStatement::column_text(int index) const {
  const unsigned char* text = sqlite3_column_text(statement_, index);
  if (text == nullptr) return {};
  return std::string(reinterpret_cast<const char*>(text), static_cast<std::size_t>(sqlite3_column_bytes(statement_, index)));
}

SqliteDatabase::SqliteDatabase(const std::filesystem::path& file, bool read_only) : file_(file) {
  // Readings are health data: the database is its owner's only. SQLite
  // creates the -wal and -shm files with the database's mode, so a new
  // database made 0600 here keeps them 0600 too; an older one is tightened.
  if (!read_only && file != ":memory:") {
    try {
      make_private_file(file);
      for (const char* suffix : {"-wal", "-shm"}) {
        const std::filesystem::path companion = file.string() + suffix;
        if (std::filesystem::exists(companion)) make_private_file(companion);
      }
    } catch (const PrivateFileError& e) {
      throw SqliteError(std::string("sqlite: cannot open ") + file.string() + ": " + e.what());
    }
  }
  const int flags = read_only ? SQLITE_OPEN_READONLY : (SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE);
  // NOMUTEX: each connection is used by one thread at a time (the callers say so).
  if (sqlite3_open_v2(file.c_str(), &db_, flags | SQLITE_OPEN_NOMUTEX, nullptr) != SQLITE_OK) {
    const std::string message = db_ != nullptr ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    throw SqliteError("sqlite: cannot open " + file.string() + ": " + message);
  }
  // Another connection (a reader, a restarted service) may hold a lock briefly.
  sqlite3_busy_timeout(db_, 5000);
}

SqliteDatabase::~SqliteDatabase() { sqlite3_close(db_); }

void SqliteDatabase::execute(std::string_view sql) {
  char* message = nullptr;
  const std::string text(sql);
  if (sqlite3_exec(db_, text.c_str(), nullptr, nullptr, &message) != SQLITE_OK) {
    const std::string error = message != nullptr ? message : "unknown error";
    sqlite3_free(message);
    throw SqliteError("sqlite: cannot run '" + text + "' on " + file_.string() + ": " + error);
  }
}

SqliteStatement SqliteDatabase::prepare(std::string_view sql) { return SqliteStatement(db_, sql); }

int SqliteDatabase::changes() const { return sqlite3_changes(db_); }

bool SqliteDatabase::in_transaction() const { return sqlite3_get_autocommit(db_) == 0; }

void SqliteDatabase::set_commit_veto(std::function<bool()> veto) {
  commit_veto_ = std::move(veto);
  if (!commit_veto_) {
    sqlite3_commit_hook(db_, nullptr, nullptr);
    return;
  }
  // SQLite's commit hook: non-zero turns the COMMIT into a ROLLBACK. No
  // exception may cross SQLite's C frames: a throwing veto vetoes.
  sqlite3_commit_hook(
      db_,
      [](void* self) {
        try {
          return static_cast<SqliteDatabase*>(self)->commit_veto_() ? 1 : 0;
        } catch (...) {
          return 1;
        }
      },
      this);
}

}  // namespace alplan::perception::service
