#include "perception/stress_detector.h"

#include <numeric>
#include <stdexcept>

namespace alplan::perception {

ClassifierStressDetector::ClassifierStressDetector(StressClassifier classifier, const StressSmoothing& smoothing)
    : classifier_(std::move(classifier)), smoothing_(smoothing) {
  if (smoothing_.smoothing_readings == 0 || smoothing_.min_votes == 0 ||
      smoothing_.min_votes > smoothing_.smoothing_readings) {
    throw std::invalid_argument("stress smoothing: need 1 <= min_votes <= smoothing_readings");
  }
  if (!(smoothing_.leave_fraction < smoothing_.enter_fraction)) {
    throw std::invalid_argument("stress smoothing: leave_fraction must be below enter_fraction");
  }
}

StressObservation ClassifierStressDetector::observe(const std::string& senior,
                                                    const firmware::WindowFeatures& reading) {
  Senior& s = seniors_[senior];
  StressObservation out;
  if (!reading.has_heart_rate || reading.motion_artefact) {
    s.state.rejected += 1;
    out.state = s.state;
    return out;
  }
  s.votes.push_back(classifier_.predict(reading));
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
