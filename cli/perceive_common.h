// Shared pieces of the perceive commands (perception module only).
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

#include "perception/ontology/type_augmentation.h"

namespace CLI {
class App;
}

namespace alplan::cli {

// Bad input the command found itself (a file it cannot read, ...).
class CommandInputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Runs a command; a library's complaint about its input (any
// std::runtime_error or std::invalid_argument: unreadable files, malformed
// models or datasets) becomes "error: ..." and exit 2, anything else is an
// internal error (exit 70). `context` names what was being read.
int guarded(const std::function<int()>& command, const std::string& context);

// supertype -> subtypes, one line each, augmented types marked '+'.
void print_ontology(const perception::TypeParents& types, const perception::AugmentationResult& result, bool explain,
                    bool json);

void add_emotion_learning_commands(CLI::App& emotion, int& exit_code);
void add_object_learning_commands(CLI::App& objects, int& exit_code);
void add_perceive_stress_command(CLI::App& perceive, int& exit_code);
void add_stress_alarms_command(CLI::App& stress, int& exit_code);
void add_trainer_check_command(CLI::App& perceive, int& exit_code);

}  // namespace alplan::cli
