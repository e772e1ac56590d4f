// The end of both entry points (alplan's main and the perception module's):
// parse the command line, which runs the chosen command's callback, and
// turn CLI11's outcomes into alplan's exit codes (help: 0, a bad command
// line: 2, otherwise the command's own).
#pragma once

namespace CLI {
class App;
}

namespace alplan::cli {

int parse_command_line(CLI::App& app, int argc, char** argv, const int& command_exit_code);

}  // namespace alplan::cli
