#include "cli/parse_command_line.h"

#include <CLI/CLI.hpp>

#include "cli/commands.h"

namespace alplan::cli {

int parse_command_line(CLI::App& app, int argc, char** argv, const int& command_exit_code) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitInputError;
  }
  return command_exit_code;
}

}  // namespace alplan::cli
