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
// keep their readings and retry); the detector may then have seen readings
// that were not stored, and sees them again when they are re-sent.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <map>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "perception/service/device_registry.h"
#include "perception/service/reading_message.h"
#include "perception/service/reading_store.h"
#include "perception/service/stress_event_queue.h"
#include "perception/stress_detector.h"

namespace alplan::perception::service {

struct IngestCounters {
  std::uint64_t stored = 0;
  std::uint64_t duplicates = 0;
  std::uint64_t late = 0;  // stored, not voted on (older than the senior's newest)
  std::uint64_t became_stressed = 0;
  std::uint64_t became_calm = 0;
  std::uint64_t commits = 0;      // transactions
  std::uint64_t batches = 0;      // ingest() calls committed
  std::uint64_t failed_commits = 0;
};

class ReadingIngest {
 public:
  // `detector` may be null: readings are then stored but no stress is
  // detected. The store, detector and queue must outlive this object.
  // Primes the detector from the store (see above) with up to
  // `priming_readings` per device of `registry`.
  ReadingIngest(ReadingStore& store, StressDetector* detector, StressEventQueue& events,
                const DeviceRegistry& registry, std::size_t priming_readings);

  // Stores the readings of `senior`'s device, oldest first; returns for each
  // whether it was stored now (true) or already there (false). Blocks until
  // committed. Thread-safe. Throws SqliteError when the commit failed.
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

  void prime_detector(const DeviceRegistry& registry, std::size_t priming_readings);
  void commit_group(const std::vector<Batch*>& group);
  std::vector<StressEvent> write_group(const std::vector<Batch*>& group, std::int64_t now_ms);
  void detect(const std::string& senior, const ReceivedReading& reading, std::vector<StressEvent>& events);
  void after_commit(const std::vector<Batch*>& group, const std::vector<StressEvent>& events);

  ReadingStore& store_;
  StressDetector* detector_;
  StressEventQueue& events_;

  // The group commit's hand-over.
  std::mutex queue_mutex_;
  std::condition_variable group_done_;
  std::vector<Batch*> waiting_;
  bool leader_active_ = false;

  // Touched only by the leader (and read by missing_by_device under stats_mutex_).
  std::map<std::string, std::uint64_t> newest_voted_ms_;  // per senior
  mutable std::mutex stats_mutex_;
  std::map<std::pair<std::string, std::uint32_t>, BootCount> boots_;
  IngestCounters counters_;
};

}  // namespace alplan::perception::service
