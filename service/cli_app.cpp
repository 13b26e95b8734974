#include "cli_app.h"

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <iostream>

#include "cli_common.h"

namespace gvm::cli {

void set_up_logging(const std::string& program) {
  set_program_name(program);
  auto logger = spdlog::stderr_color_mt(program);
  spdlog::set_default_logger(logger);
  spdlog::set_pattern(program + ": %v");
  spdlog::set_level(spdlog::level::info);
}

void add_help_flag(CLI::App& command) {
  command.set_help_flag();
  command.add_flag_callback("-h,--help", [] { throw CLI::CallForHelp(); }, "show this help")->trigger_on_parse();
}

int unknown(const std::string& arg) {
  return usage_error(std::string(arg.starts_with('-') ? "unknown option '" : "unknown command '") + arg + "'");
}

std::optional<int> parse(CLI::App& app, int argc, char** argv, const char* usage) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << usage;
    return 0;
  } catch (const CLI::CallForVersion& e) {
    std::cout << e.what() << "\n";
    return 0;
  } catch (const CLI::ArgumentMismatch& e) {
    // CLI11 says "--threads: 1 required N missing"; a person says it like this.
    const std::string what = e.what();
    return usage_error(what.substr(0, what.find(':')) + " needs a value");
  } catch (const CLI::ParseError& e) {
    return usage_error(e.what());
  }
  return std::nullopt;
}

}  // namespace gvm::cli
