#include "home/live_goal_source.h"

#include <stdexcept>

namespace alplan::home {

LiveGoalSource::LiveGoalSource(perception::service::StressEventQueue& events, FaceLooks::Look read_face,
                               const HomeMap& map, const std::vector<std::string>& wristband_seniors,
                               const HomeSettings& settings, EventLog& log)
    : events_(events), read_face_(std::move(read_face)), log_(log), looks_(settings, log) {
  for (const std::string& senior : wristband_seniors) {
    if (map.has_senior(senior)) continue;
    std::string known;
    for (const Placed& s : map.seniors) known += (known.empty() ? "" : ", ") + s.name;
    throw std::invalid_argument("a wristband belongs to " + senior + ", not a senior of the home (" + known +
                                "); name the home's seniors in the tokens file");
  }
}

void LiveGoalSource::hear(const perception::service::StressEvent& e, double t) {
  LogEvent event{"stress", t, e.senior, {}, {}};
  event.payload = {{"stressed", e.stressed}, {"score", e.stressed_fraction}, {"votes", e.votes},
                   {"device", e.device}, {"t_ms", e.t_ms}};
  log_.write(event);
  perception::StressState& state = stress_[e.senior];
  state.stressed = e.stressed;
  state.stressed_fraction = e.stressed_fraction;
  state.votes = e.votes;
  if (e.stressed) looks_.stressed(e.senior, t);
}

std::vector<PerceivedGoal> LiveGoalSource::sense(double t) {
  while (const std::optional<perception::service::StressEvent> e = events_.try_pop()) hear(*e, t);
  std::vector<PerceivedGoal> goals;
  for (const auto& [senior, state] : stress_) {
    if (std::optional<PerceivedGoal> goal = looks_.look(senior, state, t, read_face_)) goals.push_back(std::move(*goal));
  }
  return goals;
}

}  // namespace alplan::home
