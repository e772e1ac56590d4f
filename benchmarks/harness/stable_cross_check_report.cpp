// summary.md's "stable cross-checked" section: each perturbation's stable
// run against its classical cross-check (stable_cross_check.h). Issue 43
// asks that the two proven distances be equal wherever both are proven, so
// every difference is listed, never only counted.
#include <map>
#include <sstream>

#include "benchmarks/harness/stability_bench.h"
#include "benchmarks/harness/table.h"

namespace alplan::bench {
namespace {

std::string where(const StabilityRun& r) {
  return r.domain + " " + std::to_string(r.problem) + " " + r.kind + " " + std::to_string(r.perturbation);
}

std::string classical(const StabilityRun& r) {
  return r.cross_check_distance ? std::to_string(*r.cross_check_distance) : "no plan";
}

// The first words of a reason, so that the reasons can be counted.
std::string reason_kind(const std::string& note) {
  const std::size_t paren = note.find(" (");
  return paren == std::string::npos ? note : note.substr(0, paren);
}

}  // namespace

std::string stable_cross_check_section(const StabilityBenchResult& result) {
  std::vector<const StabilityRun*> checked;  // stable's run of each cross-checked perturbation
  for (const StabilityRun& r : result.runs) {
    if (r.strategy == "stable" && !r.cross_check_status.empty()) checked.push_back(&r);
  }
  if (checked.empty()) return "";
  std::vector<const StabilityRun*> equal, different, only_stable, only_classical, neither;
  std::map<std::string, int> not_comparable;
  for (const StabilityRun* r : checked) {
    if (r->cross_check_status == "not comparable") {
      ++not_comparable[reason_kind(r->cross_check_note)];
      continue;
    }
    const bool classical_proven = r->cross_check_status == "proven";
    const bool stable_proven = r->proven && r->valid;
    if (stable_proven && classical_proven) {
      (r->cross_check_distance == r->distance ? equal : different).push_back(r);
    } else if (stable_proven) {
      only_stable.push_back(r);
    } else if (classical_proven) {
      only_classical.push_back(r);
    } else {
      neither.push_back(r);
    }
  }
  std::ostringstream out;
  out << "\n## stable cross-checked\n\n"
      << "Each perturbation's minimum distance computed again by a classical compilation (compressed actions, "
      << "keep-i at cost 0, forgo-i and every new step at cost 1, the committed ends applied first) solved with "
      << "A* on LM-cut (benchmarks/harness/stable_cross_check.h). stable counts as proven where it says \"proven "
      << "minimal\" and its plan is valid.\n\n";
  Table counts({"perturbations", "both proven, equal", "both proven, different", "only stable proven",
                "only the classical task proven", "neither proven", "not comparable"});
  int incomparable = 0;
  for (const auto& [reason, n] : not_comparable) incomparable += n;
  counts.add({std::to_string(checked.size()), std::to_string(equal.size()), std::to_string(different.size()),
              std::to_string(only_stable.size()), std::to_string(only_classical.size()),
              std::to_string(neither.size()), std::to_string(incomparable)});
  counts.print_markdown(out);
  if (!different.empty()) {
    out << "\nBoth proven, different:\n\n";
    for (const StabilityRun* r : different) {
      out << "- " << where(*r) << ": stable " << r->distance << ", classical " << classical(*r) << " ("
          << r->cross_check_note << ")\n";
    }
  }
  if (!only_stable.empty() || !only_classical.empty()) {
    out << "\nOnly one proven (stable's distance / the classical plan's; the unproven one is an upper bound):\n\n";
    for (const StabilityRun* r : only_stable) {
      // An unproven classical plan still runs in the temporal task: below a
      // proven minimum it contradicts the proof.
      const bool below = r->cross_check_distance && *r->cross_check_distance < r->distance;
      out << "- " << where(*r) << ": stable " << r->distance << " proven, classical " << classical(*r) << " ("
          << r->cross_check_note << ")" << (below ? " CONTRADICTION: a classical plan below the proven minimum" : "")
          << "\n";
    }
    for (const StabilityRun* r : only_classical) {
      // stable's valid plan, sequenced (the witness held), is a classical
      // plan: a proven classical minimum above it contradicts the proof.
      const bool above = r->valid && (!r->cross_check_distance || *r->cross_check_distance > r->distance);
      out << "- " << where(*r) << ": classical " << classical(*r) << " proven, stable "
          << (r->valid ? std::to_string(r->distance) : "no valid plan")
          << (above ? " CONTRADICTION: stable's plan is below the proven classical minimum" : "") << "\n";
    }
  }
  if (!not_comparable.empty()) {
    out << "\nNot comparable, by reason:\n\n";
    for (const auto& [reason, n] : not_comparable) out << "- " << n << ": " << reason << "\n";
  }
  return out.str();
}

}  // namespace alplan::bench
