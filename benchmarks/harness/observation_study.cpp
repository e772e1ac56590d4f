#include "benchmarks/harness/observation_study.h"

#include <algorithm>
#include <set>
#include <sstream>
#include <tuple>

#include "benchmarks/harness/table.h"

namespace alplan::bench {
namespace {

// How the robot learns of each kind (repair/random_events.h).
const std::vector<std::pair<std::string, std::string>>& kind_groups() {
  static const std::vector<std::pair<std::string, std::string>> groups{
      {"arrival", "seen: an untagged object found unavailable on arrival"},
      {"iot", "seen: a tagged object, its tag foresees the failure"},
      {"sibling", "seen: the substitute stands where the camera passes"},
      {"two", "seen and told: two failures of the others"},
      {"moves", "told: the senior's wristband or a room sensor"},
      {"emotion", "told: the senior's face, read again"},
      {"overrun", "timed: an action takes longer"}};
  return groups;
}

using RunKey = std::tuple<std::string, int, std::string>;  // home, run, strategy

std::map<RunKey, const StudyRun*> index(const std::vector<StudyRun>& runs, const std::string& kind) {
  std::map<RunKey, const StudyRun*> out;
  for (const StudyRun& r : runs) {
    if (kind == "all" || r.kind == kind) out[{r.home, r.run, r.strategy}] = &r;
  }
  return out;
}

struct Measures {
  std::size_t runs = 0, comforted = 0;
  double delay = 0.0, cost = 0.0;  // means over comforted runs
  std::size_t measured = 0;        // comforted runs with a delay and a cost
};

Measures measure(const std::map<RunKey, const StudyRun*>& runs, const std::string& strategy) {
  Measures m;
  std::size_t counted = 0;
  for (const auto& [key, r] : runs) {
    if (std::get<2>(key) != strategy) continue;
    ++m.runs;
    if (!r->comforted) continue;
    ++m.comforted;
    if (r->delay && r->cost) {
      m.delay += *r->delay;
      m.cost += *r->cost;
      ++counted;
    }
  }
  if (counted > 0) {
    m.delay /= static_cast<double>(counted);
    m.cost /= static_cast<double>(counted);
  }
  m.measured = counted;
  return m;
}

void models_table(std::ostream& out,
                  const std::vector<std::pair<std::string, std::map<RunKey, const StudyRun*>>>& by_model,
                  const std::vector<std::string>& strategies) {
  std::vector<std::string> header{"strategy"};
  for (const auto& [model, runs] : by_model) {
    for (const char* m : {"comforted", "delay", "cost"}) header.push_back(model + " " + m);
  }
  Table table(header);
  for (const std::string& s : strategies) {
    std::vector<std::string> row{s};
    for (const auto& [model, runs] : by_model) {
      const Measures m = measure(runs, s);
      row.push_back(std::to_string(m.comforted) + "/" + std::to_string(m.runs));
      // No comforted run, no mean: a 0.0 would read as "on time, free".
      row.push_back(m.measured ? fixed(m.delay, 1) : "-");
      row.push_back(m.measured ? fixed(m.cost, 1) : "-");
    }
    table.add(row);
  }
  table.print_markdown(out);
}

// Paired differences of one strategy's runs, `seen` minus `base` (full
// minus iot: what seeing everything is worth; iot minus camera: what the
// tags are worth).
void value_table(std::ostream& out, const std::map<RunKey, const StudyRun*>& seen,
                 const std::map<RunKey, const StudyRun*>& base, const std::vector<std::string>& strategies,
                 const BootstrapOptions& bootstrap) {
  Table table({"strategy", "measure", "pairs", "mean difference", "95% CI (homes resampled)",
               "Wilcoxon p (home means)"});
  for (const std::string& s : strategies) {
    std::vector<double> comforted_base, comforted_seen, delay_base, delay_seen;
    std::vector<std::string> homes, delay_homes;  // the runs of one home are one cluster
    for (const auto& [key, b] : base) {
      const auto it = seen.find(key);
      if (std::get<2>(key) != s || it == seen.end()) continue;
      comforted_base.push_back(b->comforted ? 1.0 : 0.0);
      comforted_seen.push_back(it->second->comforted ? 1.0 : 0.0);
      homes.push_back(std::get<0>(key));
      if (b->delay && it->second->delay) {
        delay_homes.push_back(std::get<0>(key));
        delay_base.push_back(*b->delay);
        delay_seen.push_back(*it->second->delay);
      }
    }
    for (const auto& [name, x, y, clusters] : {std::tuple{"comforted", &comforted_base, &comforted_seen, &homes},
                                               std::tuple{"delay", &delay_base, &delay_seen, &delay_homes}}) {
      if (x->empty()) continue;
      const PairedComparison c = compare_paired(*x, *y, *clusters, bootstrap);
      table.add({s, name, std::to_string(c.pairs) + " in " + std::to_string(c.clusters) + " homes",
                 fixed(c.mean_difference, 3), "[" + fixed(c.ci_low, 3) + ", " + fixed(c.ci_high, 3) + "]",
                 fixed(c.wilcoxon_p, 4)});
    }
  }
  table.print_markdown(out);
}

}  // namespace

std::string observation_tables(const std::map<std::string, std::vector<StudyRun>>& by_model,
                               const std::vector<std::string>& strategies, const BootstrapOptions& bootstrap) {
  std::ostringstream out;
  out << "# What the sensors change\n\nThe same runs under each observation model (comforted runs / runs; delay "
         "and cost: means over comforted runs). Value of observation: full minus iot, and iot minus camera, run by "
         "run.\n";
  for (const auto& [kind, how] : kind_groups()) {
    // Most seen first; a map would order the models by name.
    std::vector<std::pair<std::string, std::map<RunKey, const StudyRun*>>> indexed;
    for (const char* model : {"full", "iot", "camera"}) {
      if (by_model.count(model)) indexed.emplace_back(model, index(by_model.at(model), kind));
    }
    if (std::all_of(indexed.begin(), indexed.end(), [](const auto& m) { return m.second.empty(); })) continue;
    out << "\n## " << kind << " (" << how << ")\n\n";
    models_table(out, indexed, strategies);
    if (by_model.count("full") && by_model.count("iot")) {
      out << "\nfull minus iot:\n\n";
      value_table(out, index(by_model.at("full"), kind), index(by_model.at("iot"), kind), strategies, bootstrap);
    }
    if (by_model.count("iot") && by_model.count("camera")) {
      out << "\niot minus camera (what the tags are worth):\n\n";
      value_table(out, index(by_model.at("iot"), kind), index(by_model.at("camera"), kind), strategies, bootstrap);
    }
  }
  return out.str();
}

}  // namespace alplan::bench
