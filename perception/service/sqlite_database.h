// A thin RAII layer over the SQLite C API (Debian's libsqlite3): a
// connection and prepared statements, every failure turned into a
// SqliteError that names the operation and SQLite's own message. Nothing
// here is thread-safe; one connection belongs to one thread at a time.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

struct sqlite3;
struct sqlite3_stmt;

namespace alplan::perception::service {

class SqliteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class SqliteStatement {
 public:
  SqliteStatement(sqlite3* db, std::string_view sql);
  ~SqliteStatement();
  SqliteStatement(const SqliteStatement&) = delete;
  SqliteStatement& operator=(const SqliteStatement&) = delete;
  SqliteStatement(SqliteStatement&& other) noexcept;
  SqliteStatement& operator=(SqliteStatement&&) = delete;

  // Parameters are 1-based, as in SQLite.
  void bind(int index, std::int64_t value);
  void bind(int index, double value);
  void bind(int index, std::string_view text);
  void bind(int index, const std::optional<double>& value);  // NULL when empty
  void bind_null(int index);

  // Runs one step: true while a row is ready, false when done.
  bool step();
  // Resets for the next use and clears the bindings.
  void reset();

  std::int64_t column_int(int index) const;
  double column_double(int index) const;
  std::optional<double> column_optional_double(int index) const;
  std::string column_text(int index) const;

 private:
  sqlite3* db_;
  sqlite3_stmt* statement_ = nullptr;
};

class SqliteDatabase {
 public:
  // Opens (creating it when missing) read-write, or read-only.
  explicit SqliteDatabase(const std::filesystem::path& file, bool read_only = false);
  ~SqliteDatabase();
  SqliteDatabase(const SqliteDatabase&) = delete;
  SqliteDatabase& operator=(const SqliteDatabase&) = delete;

  // Runs SQL without results (may hold several statements).
  void execute(std::string_view sql);
  SqliteStatement prepare(std::string_view sql);
  // Rows changed by the last INSERT/UPDATE/DELETE.
  int changes() const;
  // True between BEGIN and the COMMIT or ROLLBACK that ends it (a failed
  // COMMIT may or may not have ended the transaction, depending on why).
  bool in_transaction() const;
  // Fault injection: `veto` is asked at every COMMIT; when it returns true
  // SQLite turns the COMMIT into a rollback and the COMMIT fails, exactly as
  // a failed write would. Empty: no veto. Lives as long as the connection.
  void set_commit_veto(std::function<bool()> veto);
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  sqlite3* db_ = nullptr;
  std::function<bool()> commit_veto_;
};

}  // namespace alplan::perception::service
