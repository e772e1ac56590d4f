#include "perception/service/retention_sweeper.h"

#include <stdexcept>

#include "perception/service/reading_store.h"

namespace alplan::perception::service {
namespace {

std::int64_t unix_ms_now() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace

RetentionSweeper::RetentionSweeper(std::filesystem::path database, const RetentionOptions& options,
                                   ErrorLog error_log)
    : database_(std::move(database)), options_(options), error_log_(std::move(error_log)) {
  // Bounded so that the cutoff (now minus the period, in ms) stays an int64.
  if (!(options_.days >= 0.0 && options_.days <= 36500.0)) {
    throw std::invalid_argument("--retention-days must be between 0 and 36500");
  }
  if (options_.chunk == 0) throw std::invalid_argument("the retention chunk must be at least one row");
}

RetentionSweeper::~RetentionSweeper() { stop(); }

void RetentionSweeper::start() {
  if (thread_.joinable() || options_.days <= 0.0) return;
  stopping_ = false;
  thread_ = std::thread([this] { run(); });
}

void RetentionSweeper::stop() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

std::uint64_t RetentionSweeper::sweep(std::int64_t now_ms) {
  // Opened per sweep: between sweeps the sweeper holds no connection.
  ReadingStore store(database_, Durability::Normal);
  const auto cutoff_ms = now_ms - static_cast<std::int64_t>(options_.days * 86400000.0);
  std::uint64_t deleted = 0;
  while (true) {
    store.begin();
    std::size_t rows = 0;
    try {
      rows = store.delete_readings_received_before(cutoff_ms, options_.chunk);
      store.delete_stress_events_recorded_before(cutoff_ms);
      store.delete_home_events_recorded_before(cutoff_ms);
      store.commit();
    } catch (...) {
      store.rollback();
      throw;
    }
    deleted += rows;
    deleted_.fetch_add(rows);
    if (rows < options_.chunk) return deleted;
    const std::lock_guard lock(mutex_);
    if (stopping_) return deleted;
  }
}

void RetentionSweeper::run() {
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    lock.unlock();
    try {
      sweep(unix_ms_now());
    } catch (const std::exception& e) {
      // A busy or full database: the next sweep tries again.
      if (error_log_) error_log_(std::string("signal service: retention sweep failed: ") + e.what());
    }
    lock.lock();
    wake_.wait_for(lock, options_.interval, [this] { return stopping_; });
  }
}

}  // namespace alplan::perception::service
