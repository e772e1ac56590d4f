// Where accepted readings go: stored durably, counted per boot for gaps, and
// handed to the stress detector, whose events are stored and then published
// to the deliberation loop.
//
// Group commit. Any number of request threads call ingest() at once; the
// first becomes the leader and commits every batch waiting at that moment in
// one transaction, the others wait for it (and the next leader takes what
// arrived meanwhile). One fsync then serves many wristbands, and each caller
// still returns only once its readings are committed: the acknowledgement
// the wristband gets means "on disk".
//
// Stress detection. Newly stored readings (not duplicates) go to the detector
// per senior in time order, inside the same transaction as the readings, so
// an event is stored together with the reading that caused it. A reading
// older than the newest one the senior's detector has seen (it arrived out
// of order, e.g. from a queue emptied after an outage while newer ones got
// through) is stored but not voted on: the detector's smoothing assumes time
// order. On start-up the detector is primed with each device's latest
// readings from the database (without emitting events), so a restart does
// not forget a senior's recent state.
//
// If a commit fails, every batch in the group gets the error (the wristbands
// keep their readings and retry), and the detector is put back as it was
// before the group (StressDetector::remember/restore), so the re-sent
// readings are voted on, and their event raised, exactly once.
//
// Time. A reading stamped more than max_clock_skew_ms ahead of the server's
// clock is never voted on and never primes the detector: one such reading
// would otherwise make every later one "late" for good, across restarts.
// (The request handler refuses such readings before they get here.)
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "perception/service/device_registry.h"
#include "perception/service/reading_message.h"
#include "perception/service/reading_store.h"
#include "perception/service/stress_event_queue.h"
#include "perception/stress/stress_detector.h"

namespace alplan::perception::service {

struct IngestCounters {
  std::uint64_t stored = 0;
  std::uint64_t duplicates = 0;
  std::uint64_t late = 0;  // stored, not voted on (older than the senior's newest)
  std::uint64_t ahead = 0;  // stored, not voted on (beyond the server's clock plus the skew)
  std::uint64_t became_stressed = 0;
  std::uint64_t became_calm = 0;
  std::uint64_t commits = 0;      // transactions
  std::uint64_t batches = 0;      // ingest() calls committed
  std::uint64_t failed_commits = 0;
};

inline constexpr std::int64_t kDefaultMaxClockSkewMs = 5 * 60 * 1000;

struct IngestOptions {
  std::size_t priming_readings = 24;
  std::int64_t max_clock_skew_ms = kDefaultMaxClockSkewMs;
  // Where committed events go; empty: pushed to the queue. (Tests make it
  // throw to check that a failure after the commit blocks no later batch.)
  std::function<void(const StressEvent&)> publish;
};

class ReadingIngest {
 public:
  // `detector` may be null: readings are then stored but no stress is
  // detected. The store, detector and queue must outlive this object.
  // Primes the detector from the store (see above) with up to
  // `priming_readings` per device of `registry`.
  ReadingIngest(ReadingStore& store, StressDetector* detector, StressEventQueue& events,
                const DeviceRegistry& registry, std::size_t priming_readings);
  ReadingIngest(ReadingStore& store, StressDetector* detector, StressEventQueue& events,
                const DeviceRegistry& registry, IngestOptions options);

  // Stores the readings of `senior`'s device, oldest first; returns for each
  // whether it was stored now (true) or already there (false). Blocks until
  // committed. Thread-safe. Throws SqliteError when the commit failed, and
  // whatever publishing the group's events threw (the readings are stored).
  std::vector<bool> ingest(const std::string& senior, const std::vector<ReceivedReading>& readings);

  // Missing readings per device: sequence numbers below the highest stored
  // one of each boot that are not stored.
  std::map<std::string, std::uint64_t> missing_by_device() const;
  IngestCounters counters() const;

 private:
  struct Batch {
    const std::string* senior;
    const std::vector<ReceivedReading>* readings;
    std::vector<bool> stored;
    std::exception_ptr error;
    bool done = false;
  };
  struct BootCount {
    std::uint32_t max_seq = 0;
    std::uint64_t count = 0;
  };

  // What the detector knew of each senior of a group before it, to put back
  // when the group's commit fails.
  struct SeniorMemory {
    StressDetector::Memory detector;
    std::optional<std::int64_t> newest_voted_ms;
  };
  using DetectionUndo = std::map<std::string, SeniorMemory>;

  void prime_detector(const DeviceRegistry& registry, std::size_t priming_readings);
  void lead(std::unique_lock<std::mutex>& lock);
  void commit_group(const std::vector<Batch*>& group);
  std::vector<StressEvent> write_group(const std::vector<Batch*>& group, std::int64_t now_ms, DetectionUndo& undo);
  void detect(const std::string& senior, const ReceivedReading& reading, std::int64_t now_ms,
              std::vector<StressEvent>& events);
  void undo_detection(const DetectionUndo& undo);
  void after_commit(const std::vector<Batch*>& group, const std::vector<StressEvent>& events);

  ReadingStore& store_;
  StressDetector* detector_;
  StressEventQueue& events_;
  IngestOptions options_;

  // The group commit's hand-over.
  std::mutex queue_mutex_;
  std::condition_variable group_done_;
  std::vector<Batch*> waiting_;
  bool leader_active_ = false;

  // Touched only by the leader (and read by missing_by_device under stats_mutex_).
  std::map<std::string, std::int64_t> newest_voted_ms_;  // per senior
  mutable std::mutex stats_mutex_;
  std::map<std::pair<std::string, std::uint32_t>, BootCount> boots_;
  IngestCounters counters_;
};

}  // namespace alplan::perception::service
