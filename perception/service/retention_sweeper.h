// Deletes readings (and stress events) older than the retention period, in
// the background, so the database does not keep seniors' health data for
// ever. Age is by the server's arrival time (received_ms, recorded_ms), not
// the wristband's clock.
//
// Ingestion is not blocked: the sweeper has its own SQLite connection and
// deletes in small chunks, each its own short transaction, so a commit of
// readings waits at most for one chunk (SQLite allows one writer at a time;
// WAL readers never wait).
//
// The ingest's gap counts (missing_by_device) are kept in memory and still
// count deleted readings as stored; after a restart they are recounted from
// the database, where deleted readings of a boot that is still running would
// show as missing.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <thread>

#include "perception/service/request_handler.h"

namespace alplan::perception::service {

struct RetentionOptions {
  double days = 0.0;  // 0: keep everything, no sweeper
  std::chrono::milliseconds interval{60000};  // between sweeps
  std::size_t chunk = 500;  // rows deleted per transaction
};

class RetentionSweeper {
 public:
  // Throws std::invalid_argument for negative days or a zero chunk.
  RetentionSweeper(std::filesystem::path database, const RetentionOptions& options, ErrorLog error_log);
  ~RetentionSweeper();
  RetentionSweeper(const RetentionSweeper&) = delete;
  RetentionSweeper& operator=(const RetentionSweeper&) = delete;

  // Sweeps now and then every interval, on its own thread, until stop().
  void start();
  void stop();

  // One sweep on the caller's thread: deletes every reading that arrived
  // before now_ms minus the retention, chunk by chunk. Returns how many
  // readings it deleted. Throws SqliteError.
  std::uint64_t sweep(std::int64_t now_ms);
  std::uint64_t deleted() const { return deleted_.load(); }

 private:
  void run();

  std::filesystem::path database_;
  RetentionOptions options_;
  ErrorLog error_log_;
  std::atomic<std::uint64_t> deleted_{0};
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace alplan::perception::service
