#include "perception/service/simulated_wristband.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "firmware/core/upload_policy.h"

namespace alplan::perception::service {
namespace {

std::vector<float> simulate_signal(const WristbandSpec& spec) {
  PpgSimulator simulator(spec.seed);
  SubjectProfile subject = simulator.random_subject();
  StressResponse response = simulator.random_stress_response();
  if (spec.typical_subject) {
    subject = SubjectProfile{};
    response = StressResponse{};
  }
  if (spec.stressed) subject = under_stress(subject, response);
  RecordingConditions conditions;
  conditions.sample_rate_hz = spec.sample_rate_hz;
  conditions.duration_s = spec.duration_s;
  const SimulatedRecording simulated = simulator.simulate(subject, conditions);
  return {simulated.recording.ppg.begin(), simulated.recording.ppg.end()};
}

firmware::CoreConfig core_config(const WristbandSpec& spec) {
  firmware::CoreConfig config;
  config.sample_rate_hz = static_cast<float>(spec.sample_rate_hz);
  config.window_ms = spec.window_ms;
  config.hop_ms = spec.hop_ms;
  config.start_time_ms = spec.start_time_ms;
  return config;
}

}  // namespace

SimulatedWristband::SimulatedWristband(const WristbandSpec& spec)
    : spec_(spec),
      backoff_(spec.retry_initial_ms, spec.retry_max_ms),
      jitter_(static_cast<std::uint32_t>(spec.seed)),
      body_(kWristbandPostBytes) {
  if (!firmware::device_id_is_valid(spec_.device_id.c_str()) || spec_.device_id.size() > 32) {
    throw std::invalid_argument("device id '" + spec_.device_id + "' must be 1-32 of [A-Za-z0-9._-]");
  }
  if (spec_.batch == 0 || spec_.retry_initial_ms == 0 || spec_.retry_initial_ms > spec_.retry_max_ms) {
    throw std::invalid_argument("wristband: need batch >= 1 and 0 < retry initial <= retry max");
  }
  const firmware::CoreConfig config = core_config(spec_);
  if (const firmware::ConfigError error = firmware::check_config(config); error != firmware::ConfigError::None) {
    throw std::invalid_argument(std::string("wristband core refuses the configuration: ") +
                                firmware::config_error_name(error));
  }
  recording_ = simulate_signal(spec_);
  core_ = std::make_unique<firmware::WristbandCore>(config);
  queue_ = std::make_unique<firmware::ReadingQueue<kWristbandQueueReadings>>();
}

void SimulatedWristband::advance_to(double signal_s) {
  const double samples = std::floor(std::max(0.0, signal_s) * spec_.sample_rate_hz);
  const std::size_t until = std::min(recording_.size(), static_cast<std::size_t>(samples));
  for (; next_sample_ < until; ++next_sample_) {
    const firmware::CoreStep step = core_->push_sample(recording_[next_sample_]);
    if (step.reading_ready) queue_reading(step.reading);
  }
}

void SimulatedWristband::queue_reading(const firmware::Reading& reading) {
  char json[firmware::kMaxReadingJsonLength];
  const firmware::DeviceIdentity identity{spec_.device_id.c_str(), spec_.boot};
  const firmware::EncodeResult encoded = firmware::encode_reading(reading, identity, json, sizeof json);
  if (encoded.status != firmware::EncodeStatus::Ok) return;  // the id was checked at construction
  const bool full = queue_->size() == queue_->capacity();
  queue_->push(json, encoded.length);
  if (full) queued_sequences_.erase(queued_sequences_.begin());
  queued_sequences_.push_back(reading.sequence);
  counters_.made += 1;
  counters_.dropped = queue_->dropped();
}

int SimulatedWristband::upload(ReadingsClient& client, const std::string& path) {
  const firmware::QueuedBatch batch = queue_->write_batch(body_.data(), body_.size(), spec_.batch);
  if (batch.count == 0) return 0;
  const HttpResult result = client.post(path, std::string_view(body_.data(), batch.length), spec_.token);
  counters_.posts += 1;
  counters_.sent += batch.count;
  if (result.status > 0) counters_.latencies_s.push_back(result.seconds);
  switch (firmware::classify_upload_status(result.status)) {
    case firmware::UploadVerdict::Delivered:
      release(batch, result.body);
      backoff_.reset();
      next_attempt_ = {};
      break;
    case firmware::UploadVerdict::Discard: {
      const std::size_t before = queue_->size();
      queue_->release_before(batch.end_id);
      const std::size_t removed = before - queue_->size();
      queued_sequences_.erase(queued_sequences_.begin(), queued_sequences_.begin() + static_cast<long>(removed));
      counters_.discarded += removed;
      break;
    }
    case firmware::UploadVerdict::RetryLater:
      counters_.retries += 1;
      next_attempt_ = std::chrono::steady_clock::now() + std::chrono::milliseconds(backoff_.next_delay_ms(jitter_()));
      break;
  }
  return result.status;
}

void SimulatedWristband::release(const firmware::QueuedBatch& batch, const std::string& response_body) {
  const std::size_t before = queue_->size();
  queue_->release_before(batch.end_id);
  const std::size_t removed = before - queue_->size();
  acknowledged_.insert(acknowledged_.end(), queued_sequences_.begin(),
                       queued_sequences_.begin() + static_cast<long>(removed));
  queued_sequences_.erase(queued_sequences_.begin(), queued_sequences_.begin() + static_cast<long>(removed));
  counters_.acknowledged += removed;
  // The service says which were new; a body we cannot read still acknowledged the batch.
  const nlohmann::json answer = nlohmann::json::parse(response_body, nullptr, false);
  if (answer.is_object() && answer.contains("stored") && answer["stored"].is_number_unsigned()) {
    counters_.stored += answer["stored"].get<std::uint64_t>();
  }
  if (answer.is_object() && answer.contains("duplicates") && answer["duplicates"].is_number_unsigned()) {
    counters_.duplicates += answer["duplicates"].get<std::uint64_t>();
  }
}

}  // namespace alplan::perception::service
