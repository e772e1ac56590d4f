#include "benchmarks/harness/grounding_bench.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <ostream>

#include "benchmarks/harness/suite.h"
#include "benchmarks/harness/table.h"

namespace alplan::bench {

int run_grounding_bench(const GroundingBenchOptions& options, std::ostream& out, std::ostream& progress) {
  std::vector<SuiteProblem> suite = load_suite(options.suite);
  if (options.largest_only) suite = largest_problems(suite);
  Table table({"domain", "problem", "MB", "status", "seconds", "peak MiB", "facts", "actions", "axioms"});
  nlohmann::json rows = nlohmann::json::array();
  int failures = 0;
  for (std::size_t i = 0; i < suite.size(); ++i) {
    const SuiteProblem& p = suite[i];
    const std::string problem = std::filesystem::path(p.problem_file).filename().string();
    progress << "[" << i + 1 << "/" << suite.size() << "] " << p.domain << " " << problem << " ... " << std::flush;
    const RunResult r = run_process({options.alplan, "ground", "--json", p.domain_file, p.problem_file}, options.limits);
    std::string status = "ok";
    nlohmann::json sizes;
    if (r.timed_out) {
      status = "timeout";
    } else if (r.exit_code != 0) {
      status = r.signal ? "killed" : r.err.find("bad_alloc") != std::string::npos ? "memout" : "error";
    } else {
      sizes = nlohmann::json::parse(r.out, nullptr, false);
      if (sizes.is_discarded()) status = "error";
    }
    if (status != "ok") ++failures;
    const double mib = static_cast<double>(r.max_rss_kib) / 1024.0;
    progress << status << " " << fixed(r.wall_seconds, 2) << " s " << fixed(mib, 0) << " MiB\n";
    auto size_of = [&](const char* key) { return status == "ok" ? std::to_string(sizes[key].get<long>()) : ""; };
    table.add({p.domain, problem, fixed(static_cast<double>(p.bytes) / 1e6, 2), status, fixed(r.wall_seconds, 2),
               fixed(mib, 0), size_of("facts"), size_of("actions"), size_of("axioms")});
    rows.push_back({{"domain", p.domain},
                    {"problem", p.problem_file},
                    {"bytes", p.bytes},
                    {"status", status},
                    {"wall_seconds", r.wall_seconds},
                    {"max_rss_kib", r.max_rss_kib},
                    {"grounding", sizes}});
  }
  table.print(out);
  out << "\n" << suite.size() - static_cast<std::size_t>(failures) << " of " << suite.size()
      << " problems grounded within " << options.limits.seconds << " s and " << options.limits.memory_mib
      << " MiB\n";
  if (!options.out_dir.empty()) {
    std::filesystem::create_directories(options.out_dir);
    std::ofstream csv(options.out_dir + "/grounding.csv");
    table.write_csv(csv);
    std::ofstream md(options.out_dir + "/grounding.md");
    table.print_markdown(md);
    std::ofstream json(options.out_dir + "/grounding.json");
    json << nlohmann::json{{"limits", {{"seconds", options.limits.seconds}, {"memory_mib", options.limits.memory_mib}}},
                           {"runs", rows}}
                .dump(2)
         << "\n";
  }
  return failures;
}

}  // namespace alplan::bench
