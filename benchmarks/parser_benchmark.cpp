// Lexing + parsing throughput (bytes/s) on the largest IPC problem files and
// on a generated 20 MB problem. Target: 100 MB/s on a 2-core machine.
//   build/benchmarks/parser_benchmark --benchmark_filter=Parse
#include <benchmark/benchmark.h>

#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "pddl_parser/lexer.h"
#include "pddl_parser/parser.h"

namespace {

std::string read(const std::string& relative) {
  std::ifstream in(std::string(ALPLAN_SHARED_DIR) + "/benchmarks/ipc/" + relative, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A problem of the satellite time-windows shape: many objects, init atoms,
// numeric facts and timed initial literals, as large as asked.
std::string generated_problem(std::size_t bytes) {
  std::mt19937 random(42);
  std::uniform_int_distribution<int> object(0, 9999);
  std::uniform_real_distribution<double> value(0.5, 900.0);
  std::string s = "(define (problem generated) (:domain satellite)\n(:objects\n";
  for (int i = 0; i < 10000; ++i) s += "  direction" + std::to_string(i) + " - direction\n";
  s += ")\n(:init\n";
  int n = 0;
  while (s.size() < bytes) {
    const std::string a = "direction" + std::to_string(object(random));
    const std::string b = "direction" + std::to_string(object(random));
    switch (n++ % 3) {
      case 0: s += "  (= (slew_time " + a + " " + b + ") " + std::to_string(value(random)) + ")\n"; break;
      case 1: s += "  (visible " + a + " " + b + ")\n"; break;
      default: s += "  (at " + std::to_string(value(random)) + " (not (visible " + a + " " + b + ")))\n"; break;
    }
  }
  s += ")\n(:goal (and (pointing satellite0 direction1)))\n(:metric minimize (total-time)))\n";
  return s;
}

void parse_problem_text(benchmark::State& state, const std::string& text) {
  for (auto _ : state) {
    auto result = alplan::pddl::parse_problem(text, "bench");
    benchmark::DoNotOptimize(result.ast);
    if (!result.ok()) state.SkipWithError("parse failed");
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}

void BM_ParseSatelliteTimeWindows33(benchmark::State& state) {
  static const std::string text = read("ipc-2004/satellite-time-time-windows-strips/instances/instance-33.pddl");
  parse_problem_text(state, text);
}
BENCHMARK(BM_ParseSatelliteTimeWindows33)->Unit(benchmark::kMillisecond);

void BM_ParseSatelliteTimeWindows36(benchmark::State& state) {
  static const std::string text = read("ipc-2004/satellite-time-time-windows-strips/instances/instance-36.pddl");
  parse_problem_text(state, text);
}
BENCHMARK(BM_ParseSatelliteTimeWindows36)->Unit(benchmark::kMillisecond);

void BM_ParseAirport50(benchmark::State& state) {
  static const std::string text = read("ipc-2004/airport-temporal-time-windows-adl/instances/instance-50.pddl");
  parse_problem_text(state, text);
}
BENCHMARK(BM_ParseAirport50)->Unit(benchmark::kMillisecond);

void BM_ParseGenerated20MB(benchmark::State& state) {
  static const std::string text = generated_problem(20u << 20);
  parse_problem_text(state, text);
}
BENCHMARK(BM_ParseGenerated20MB)->Unit(benchmark::kMillisecond);

void BM_LexGenerated20MB(benchmark::State& state) {
  static const std::string text = generated_problem(20u << 20);
  for (auto _ : state) {
    alplan::pddl::Lexer lexer(text);
    std::size_t tokens = 0;
    while (lexer.next().kind != alplan::pddl::TokenKind::End) ++tokens;
    benchmark::DoNotOptimize(tokens);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_LexGenerated20MB)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
