#include "benchmarks/harness/observation_study.h"

#include <algorithm>
#include <set>
#include <sstream>
#include <tuple>

#include "benchmarks/harness/table.h"
#include "stats/multiple_testing.h"

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

// One paired comparison of the document: a strategy's runs under two
// models, `seen` minus `base`, on one measure.
struct ValueRow {
  std::string strategy, measure;
  stats::PairedComparison c;
};

// Paired differences of one strategy's runs, `seen` minus `base` (full
// minus iot: what seeing everything is worth; iot minus camera: what the
// tags are worth).
std::vector<ValueRow> value_rows(const std::map<RunKey, const StudyRun*>& seen,
                                 const std::map<RunKey, const StudyRun*>& base,
                                 const std::vector<std::string>& strategies,
                                 const stats::BootstrapOptions& bootstrap) {
  std::vector<ValueRow> rows;
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
      rows.push_back({s, name, stats::compare_paired(*x, *y, *clusters, bootstrap)});
    }
  }
  return rows;
}

void print_value_table(std::ostream& out, const std::vector<ValueRow>& rows) {
  Table table({"strategy", "measure", "pairs", "mean difference", "95% CI (homes resampled)",
               "Wilcoxon p (home means)", "Holm p (every test of this page)"});
  for (const ValueRow& r : rows) {
    const stats::PairedComparison& c = r.c;
    table.add({r.strategy, r.measure, std::to_string(c.pairs) + " in " + std::to_string(c.clusters) + " homes",
               fixed(c.mean_difference, 3), "[" + fixed(c.ci_low, 3) + ", " + fixed(c.ci_high, 3) + "]",
               c.pairs > 0 ? fixed(c.wilcoxon_p, 4) : "-", c.pairs > 0 ? fixed(c.wilcoxon_p_adjusted, 4) : "-"});
  }
  table.print_markdown(out);
}

// A section of the page: one kind of failure, its models table, and the
// value of observation between pairs of models.
struct KindSection {
  std::string heading, models;
  std::vector<std::pair<std::string, std::vector<ValueRow>>> values;  // title, rows
};

// Every test of the page is one family (Holm 1979): a kind, a model pair, a
// strategy and a measure each add one, and a reader scanning the page for a
// small p is making all of them at once.
void adjust_family(std::vector<KindSection>& sections) {
  std::vector<stats::PairedComparison*> family;
  for (KindSection& k : sections) {
    for (auto& [title, rows] : k.values) {
      for (ValueRow& r : rows) {
        if (r.c.pairs > 0) family.push_back(&r.c);  // no pair, no test
      }
    }
  }
  std::vector<double> p;
  for (const stats::PairedComparison* c : family) p.push_back(c->wilcoxon_p);
  const std::vector<double> adjusted = stats::holm_adjust(p);
  for (std::size_t i = 0; i < family.size(); ++i) family[i]->wilcoxon_p_adjusted = adjusted[i];
}

}  // namespace

std::string observation_tables(const std::map<std::string, std::vector<StudyRun>>& by_model,
                               const std::vector<std::string>& strategies, const stats::BootstrapOptions& bootstrap) {
  std::vector<KindSection> sections;
  for (const auto& [kind, how] : kind_groups()) {
    // Most seen first; a map would order the models by name.
    std::vector<std::pair<std::string, std::map<RunKey, const StudyRun*>>> indexed;
    for (const char* model : {"full", "iot", "camera"}) {
      if (by_model.count(model)) indexed.emplace_back(model, index(by_model.at(model), kind));
    }
    if (std::all_of(indexed.begin(), indexed.end(), [](const auto& m) { return m.second.empty(); })) continue;
    KindSection section;
    section.heading = "## " + kind + " (" + how + ")";
    std::ostringstream models;
    models_table(models, indexed, strategies);
    section.models = models.str();
    if (by_model.count("full") && by_model.count("iot")) {
      section.values.emplace_back("full minus iot:", value_rows(index(by_model.at("full"), kind),
                                                                index(by_model.at("iot"), kind), strategies, bootstrap));
    }
    if (by_model.count("iot") && by_model.count("camera")) {
      section.values.emplace_back("iot minus camera (what the tags are worth):",
                                  value_rows(index(by_model.at("iot"), kind), index(by_model.at("camera"), kind),
                                             strategies, bootstrap));
    }
    sections.push_back(std::move(section));
  }
  adjust_family(sections);
  std::ostringstream out;
  out << "# What the sensors change\n\nThe same runs under each observation model (comforted runs / runs; delay "
         "and cost: means over comforted runs). Value of observation: full minus iot, and iot minus camera, run by "
         "run; the signed-rank p-values Holm-adjusted over every test of this page.\n";
  for (const KindSection& k : sections) {
    out << "\n" << k.heading << "\n\n" << k.models;
    for (const auto& [title, rows] : k.values) {
      out << "\n" << title << "\n\n";
      print_value_table(out, rows);
    }
  }
  return out.str();
}

}  // namespace alplan::bench
