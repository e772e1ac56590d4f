#include "perception/service/reading_ingest.h"

#include <algorithm>
#include <chrono>

namespace alplan::perception::service {
namespace {

std::int64_t unix_ms_now() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

struct NewReading {
  const std::string* senior;
  const ReceivedReading* reading;
};

}  // namespace

ReadingIngest::ReadingIngest(ReadingStore& store, StressDetector* detector, StressEventQueue& events,
                             const DeviceRegistry& registry, std::size_t priming_readings)
    : ReadingIngest(store, detector, events, registry, IngestOptions{priming_readings, kDefaultMaxClockSkewMs, {}}) {}

ReadingIngest::ReadingIngest(ReadingStore& store, StressDetector* detector, StressEventQueue& events,
                             const DeviceRegistry& registry, IngestOptions options)
    : store_(store), detector_(detector), events_(events), options_(std::move(options)) {
  for (const BootSequence& b : store_.boot_sequences()) boots_[{b.device, b.boot}] = {b.max_seq, b.count};
  prime_detector(registry, options_.priming_readings);
}

void ReadingIngest::prime_detector(const DeviceRegistry& registry, std::size_t priming_readings) {
  if (detector_ == nullptr || priming_readings == 0) return;
  // A reading from beyond the clock (stored before the service refused them)
  // must not prime: it would make every reading after the restart late.
  const std::int64_t horizon_ms = unix_ms_now() + options_.max_clock_skew_ms;
  std::map<std::string, std::vector<ReceivedReading>> by_senior;
  for (const Device& d : registry.devices()) {
    std::vector<ReceivedReading> latest = store_.latest_readings_of(d.id, priming_readings, horizon_ms);
    auto& list = by_senior[d.senior];
    list.insert(list.end(), latest.begin(), latest.end());
  }
  for (auto& [senior, readings] : by_senior) {
    std::stable_sort(readings.begin(), readings.end(),
                     [](const ReceivedReading& a, const ReceivedReading& b) { return a.t_ms < b.t_ms; });
    // Events these readings caused were stored when they first arrived.
    for (const ReceivedReading& r : readings) {
      detector_->observe(senior, window_features_of(r));
      newest_voted_ms_[senior] = static_cast<std::int64_t>(r.t_ms);
    }
  }
}

std::vector<bool> ReadingIngest::ingest(const std::string& senior, const std::vector<ReceivedReading>& readings) {
  Batch batch{&senior, &readings, {}, nullptr, false};
  std::unique_lock lock(queue_mutex_);
  waiting_.push_back(&batch);
  while (!batch.done) {
    if (leader_active_) {
      group_done_.wait(lock);
    } else {
      lead(lock);
    }
  }
  if (batch.error) std::rethrow_exception(batch.error);
  return batch.stored;
}

// Commits what is waiting. Whatever happens in the commit, the group is
// marked done and the leadership handed back: a leader that left with the
// flag set would block every later POST for good.
void ReadingIngest::lead(std::unique_lock<std::mutex>& lock) {
  leader_active_ = true;
  std::vector<Batch*> group;
  group.swap(waiting_);
  lock.unlock();
  try {
    commit_group(group);
  } catch (...) {
    for (Batch* b : group) {
      if (!b->error) b->error = std::current_exception();
    }
  }
  lock.lock();
  for (Batch* b : group) b->done = true;
  leader_active_ = false;
  group_done_.notify_all();
}

void ReadingIngest::commit_group(const std::vector<Batch*>& group) {
  std::vector<StressEvent> events;
  DetectionUndo undo;
  try {
    store_.begin();
    try {
      events = write_group(group, unix_ms_now(), undo);
      store_.commit();
    } catch (...) {
      store_.rollback();
      throw;
    }
  } catch (...) {
    // Nothing of the group is stored: the detector forgets it too, so the
    // re-sent readings are voted on (not "late") and raise their event then.
    undo_detection(undo);
    for (Batch* b : group) {
      b->stored.clear();
      b->error = std::current_exception();
    }
    const std::lock_guard stats(stats_mutex_);
    counters_.failed_commits += 1;
    return;
  }
  after_commit(group, events);
}

std::vector<StressEvent> ReadingIngest::write_group(const std::vector<Batch*>& group, std::int64_t now_ms,
                                                    DetectionUndo& undo) {
  std::vector<NewReading> fresh;
  for (Batch* b : group) {
    b->stored.clear();
    for (const ReceivedReading& r : *b->readings) {
      const bool stored = store_.insert_reading(r, now_ms);
      b->stored.push_back(stored);
      if (stored) fresh.push_back({b->senior, &r});
    }
  }
  std::vector<StressEvent> events;
  if (detector_ == nullptr) return events;
  std::stable_sort(fresh.begin(), fresh.end(), [](const NewReading& a, const NewReading& b) {
    if (*a.senior != *b.senior) return *a.senior < *b.senior;
    return a.reading->t_ms < b.reading->t_ms;
  });
  for (const NewReading& n : fresh) {
    if (undo.count(*n.senior) == 0) {
      const auto newest = newest_voted_ms_.find(*n.senior);
      undo[*n.senior] = {detector_->remember(*n.senior),
                         newest == newest_voted_ms_.end() ? std::nullopt : std::optional(newest->second)};
    }
    detect(*n.senior, *n.reading, now_ms, events);
  }
  for (const StressEvent& e : events) store_.insert_stress_event(e, now_ms);
  return events;
}

void ReadingIngest::undo_detection(const DetectionUndo& undo) {
  for (const auto& [senior, memory] : undo) {
    detector_->restore(senior, memory.detector);
    if (memory.newest_voted_ms) {
      newest_voted_ms_[senior] = *memory.newest_voted_ms;
    } else {
      newest_voted_ms_.erase(senior);
    }
  }
}

void ReadingIngest::detect(const std::string& senior, const ReceivedReading& reading, std::int64_t now_ms,
                           std::vector<StressEvent>& events) {
  const auto t_ms = static_cast<std::int64_t>(reading.t_ms);
  if (t_ms > now_ms + options_.max_clock_skew_ms) {
    const std::lock_guard stats(stats_mutex_);
    counters_.ahead += 1;
    return;
  }
  const auto newest = newest_voted_ms_.find(senior);
  if (newest != newest_voted_ms_.end() && t_ms <= newest->second) {
    const std::lock_guard stats(stats_mutex_);
    counters_.late += 1;
    return;
  }
  newest_voted_ms_[senior] = t_ms;
  const StressObservation seen = detector_->observe(senior, window_features_of(reading));
  if (!seen.changed) return;
  events.push_back({senior, reading.device, seen.state.stressed, reading.t_ms, seen.state.stressed_fraction,
                    seen.state.votes});
}

void ReadingIngest::after_commit(const std::vector<Batch*>& group, const std::vector<StressEvent>& events) {
  {
    const std::lock_guard stats(stats_mutex_);
    counters_.commits += 1;
    for (const Batch* b : group) {
      counters_.batches += 1;
      for (std::size_t i = 0; i < b->stored.size(); ++i) {
        if (!b->stored[i]) {
          counters_.duplicates += 1;
          continue;
        }
        counters_.stored += 1;
        const ReceivedReading& r = (*b->readings)[i];
        BootCount& boot = boots_[{r.device, r.boot}];
        boot.max_seq = boot.count == 0 ? r.seq : std::max(boot.max_seq, r.seq);
        boot.count += 1;
      }
    }
    for (const StressEvent& e : events) (e.stressed ? counters_.became_stressed : counters_.became_calm) += 1;
  }
  for (const StressEvent& e : events) {
    if (options_.publish) {
      options_.publish(e);
    } else {
      events_.push(e);
    }
  }
}

std::map<std::string, std::uint64_t> ReadingIngest::missing_by_device() const {
  const std::lock_guard stats(stats_mutex_);
  std::map<std::string, std::uint64_t> missing;
  for (const auto& [key, boot] : boots_) {
    missing[key.first] += static_cast<std::uint64_t>(boot.max_seq) + 1 - boot.count;
  }
  return missing;
}

IngestCounters ReadingIngest::counters() const {
  const std::lock_guard stats(stats_mutex_);
  return counters_;
}

}  // namespace alplan::perception::service
