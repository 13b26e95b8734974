// What the programs of the command line (gvm, gvm-mpi) share around their commands:
// logging to stderr, the help flag, parsing argv with usage errors a person can act on.
#pragma once

#include <optional>
#include <string>

namespace CLI {
class App;
}  // namespace CLI

namespace gvm::cli {

// spdlog's default logger on stderr, lines prefixed "PROGRAM: ", info level.
void set_up_logging(const std::string& program);

// -h/--help anywhere prints the whole usage at once, as before CLI11: its own help flag
// would first check every other value given.
void add_help_flag(CLI::App& command);

// Parses argv into app's options; the exit status when that decides it (help: `usage` is
// printed, version, a usage error).
std::optional<int> parse(CLI::App& app, int argc, char** argv, const char* usage);

// The first argument no command took: a word where a command belongs, or an option.
int unknown(const std::string& arg);

}  // namespace gvm::cli
