#include "repair/travel_times.h"

#include <functional>
#include <queue>

namespace alplan::repair {

std::map<std::string, double> shortest_times(const Ways& ways, const std::set<std::string>& sources) {
  std::map<std::string, double> best;
  using Item = std::pair<double, std::string>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  for (const std::string& s : sources) {
    best[s] = 0.0;
    open.emplace(0.0, s);
  }
  while (!open.empty()) {
    const auto [d, place] = open.top();
    open.pop();
    if (d > best[place]) continue;
    const auto out = ways.find(place);
    if (out == ways.end()) continue;
    for (const auto& [next, time] : out->second) {
      const auto known = best.find(next);
      if (known == best.end() || d + time < known->second) {
        best[next] = d + time;
        open.emplace(d + time, next);
      }
    }
  }
  return best;
}

}  // namespace alplan::repair
