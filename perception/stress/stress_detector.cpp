#include "perception/stress/stress_detector.h"

#include <numeric>
#include <stdexcept>

namespace alplan::perception {

ClassifierStressDetector::ClassifierStressDetector(StressClassifier classifier, const StressSmoothing& smoothing,
                                                   const StressCalibration& calibration)
    : classifier_(std::move(classifier)), smoothing_(smoothing), calibration_(calibration) {
  if (smoothing_.smoothing_readings == 0 || smoothing_.min_votes == 0 ||
      smoothing_.min_votes > smoothing_.smoothing_readings) {
    throw std::invalid_argument("stress smoothing: need 1 <= min_votes <= smoothing_readings");
  }
  if (!(smoothing_.leave_fraction < smoothing_.enter_fraction)) {
    throw std::invalid_argument("stress smoothing: leave_fraction must be below enter_fraction");
  }
  if (calibration_.readings > 0 && classifier_.calm_centre().empty()) {
    throw std::invalid_argument("the stress model keeps no calm centre (saved by an older alplan): retrain it, or "
                                "detect without a per-senior baseline");
  }
}

ClassifierStressDetector::Senior& ClassifierStressDetector::record_of(const std::string& name) {
  const auto it = seniors_.find(name);
  if (it != seniors_.end()) return it->second;
  Senior& s = seniors_[name];
  s.baseline = StressBaseline(classifier_.options().features, calibration_.readings);
  s.state.calibrating = !s.baseline.complete();
  return s;
}

StressObservation ClassifierStressDetector::observe(const std::string& senior,
                                                    const firmware::WindowFeatures& reading) {
  Senior& s = record_of(senior);
  StressObservation out;
  if (!reading.has_heart_rate || reading.motion_artefact) {
    s.state.rejected += 1;
    out.state = s.state;
    return out;
  }
  const std::vector<float> features = feature_vector(reading, classifier_.options().features);
  if (s.state.calibrating) {
    s.state.calibrating = !s.baseline.add(features);
    out.state = s.state;
    return out;
  }
  const int vote =
      classifier_.predict(calibration_.readings == 0 ? features : s.baseline.relative(features, classifier_.calm_centre()));
  // Only a senior judged calm moves their baseline: stress must not become
  // the new normal. Every reading of theirs does, including those voting
  // stressed: a baseline that ignored them would stop following a rate that
  // drifts up, and then alarm (measured: 11 against 7 calm seniors alarmed of
  // 50 under an 8-bpm drift).
  if (calibration_.readings > 0 && !s.state.stressed) s.baseline.follow(features, calibration_.follow_readings);
  s.votes.push_back(vote);
  while (s.votes.size() > smoothing_.smoothing_readings) s.votes.pop_front();
  s.state.votes = s.votes.size();
  s.state.stressed_fraction =
      static_cast<double>(std::accumulate(s.votes.begin(), s.votes.end(), 0)) / static_cast<double>(s.votes.size());
  if (s.votes.size() >= smoothing_.min_votes) {
    const bool before = s.state.stressed;
    if (!before && s.state.stressed_fraction >= smoothing_.enter_fraction) s.state.stressed = true;
    if (before && s.state.stressed_fraction <= smoothing_.leave_fraction) s.state.stressed = false;
    out.changed = before != s.state.stressed;
  }
  out.state = s.state;
  return out;
}

std::optional<StressState> ClassifierStressDetector::state(const std::string& senior) const {
  const auto it = seniors_.find(senior);
  if (it == seniors_.end()) return std::nullopt;
  return it->second.state;
}

StressDetector::Memory ClassifierStressDetector::remember(const std::string& senior) const {
  const auto it = seniors_.find(senior);
  if (it == seniors_.end()) return nullptr;
  return std::make_shared<const Senior>(it->second);
}

void ClassifierStressDetector::restore(const std::string& senior, const Memory& memory) {
  if (memory == nullptr) {
    seniors_.erase(senior);
    return;
  }
  seniors_[senior] = *static_cast<const Senior*>(memory.get());
}

}  // namespace alplan::perception
