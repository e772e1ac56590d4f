// The subcommands of `alplan`. Each registers its options on the app and, when
// chosen, leaves its exit code in `exit_code`. Exit codes shared by all:
// 0 success, 2 input error (unreadable or invalid files, bad options).
#pragma once

namespace CLI {
class App;
}

namespace alplan::cli {

constexpr int kExitOk = 0;
constexpr int kExitInvalid = 1;
constexpr int kExitInputError = 2;
constexpr int kExitUnsolvable = 10;
constexpr int kExitLimit = 11;
constexpr int kExitExhausted = 12;
constexpr int kExitInternalError = 70;

void add_parse_command(CLI::App& app, int& exit_code);
void add_ground_command(CLI::App& app, int& exit_code);
void add_validate_command(CLI::App& app, int& exit_code);
void add_bench_command(CLI::App& app, int& exit_code);
void add_plan_command(CLI::App& app, int& exit_code);
void add_scenario_command(CLI::App& app, int& exit_code);
void add_gen_command(CLI::App& app, int& exit_code);
void add_report_command(CLI::App& app, int& exit_code);
void add_fuzz_command(CLI::App& app, int& exit_code);
// In the perception module (perception_module.h):
void add_perceive_command(CLI::App& app, int& exit_code);
void add_deliberate_command(CLI::App& app, int& exit_code);
void add_bench_repair_command(CLI::App* bench, int& exit_code);
void add_bench_stability_command(CLI::App* bench, int& exit_code);
void add_bench_service_command(CLI::App* bench, int& exit_code);
void add_bench_soak_command(CLI::App* bench, int& exit_code);
void add_bench_home_command(CLI::App* bench, int& exit_code);
void add_serve_command(CLI::App& app, int& exit_code);
void add_wristband_command(CLI::App& app, int& exit_code);
void add_home_command(CLI::App& app, int& exit_code);  // home and replay

}  // namespace alplan::cli
