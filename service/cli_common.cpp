#include "cli_common.h"

#include "common/files.h"
#include "report/html_report.h"

#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace gvm::cli {

namespace {

std::string& program_name() {
  static std::string name = "gvm";
  return name;
}

}  // namespace

void set_program_name(const std::string& name) { program_name() = name; }

int usage_error(const std::string& message) {
  std::cerr << program_name() << ": " << message << "\nRun '" << program_name() << " --help' for usage.\n";
  return 2;
}

int failure(const std::string& message) {
  std::cerr << program_name() << ": " << message << "\n";
  return 1;
}

bool write_output(const std::string& path, const std::string& content) {
  if (path == "-") {
    std::cout << content;
    return static_cast<bool>(std::cout.flush());
  }
  return write_file_atomically(path, content);
}

CLI::Option* add_value(CLI::App& command, const std::string& name, const std::string& meta,
                       const std::string& needs, std::function<bool(const std::string&)> read) {
  auto apply = [name, needs, read = std::move(read)](const std::string& value) {
    if (!read(value)) throw CLI::ValidationError(name + " needs " + needs + " (not '" + value + "')");
  };
  return command.add_option_function<std::string>(name, apply)->type_name(meta);
}

void add_threads(CLI::App& command, unsigned& threads) {
  add_value(command, "--threads", "N", "a number from 1 to 1024", [&threads](const std::string& v) {
    return parse_number(v, threads) && threads >= 1 && threads <= 1024;
  });
}

namespace {

// How a STEP part becomes a mesh and its features (ignored for meshes).
void add_step_options(CLI::App& command, v1::StepOptions& step) {
  add_value(command, "--solid", "N", "a solid's number, from 0", [&step](const std::string& v) {
    uint32_t n = 0;
    if (!parse_number(v, n)) return false;
    step.set_solid(n);
    return true;
  });
  add_value(command, "--deflection", "MM", "a length in mm > 0 (STEP tessellation)", [&step](const std::string& v) {
    double mm = 0;
    if (!parse_number(v, mm) || !(mm > 0 && std::isfinite(mm))) return false;
    step.set_linear_deflection(mm);
    return true;
  });
  add_value(command, "--angle", "DEG", "an angle in degrees, 0 < DEG < 90 (STEP tessellation)",
            [&step](const std::string& v) {
              double deg = 0;
              if (!parse_number(v, deg) || !(deg > 0 && deg < 90)) return false;
              step.set_angular_deflection_degrees(deg);
              return true;
            });
  add_value(command, "--features", "F", "brep or auto", [&step](const std::string& v) {
    if (v != "brep" && v != "auto") return false;
    step.set_features(v == "brep" ? v1::STEP_FEATURES_BREP : v1::STEP_FEATURES_AUTO);
    return true;
  });
  command.add_flag_callback("--group-holes", [&step] { step.set_group_holes(true); });
  command.add_flag_callback("--brepmesh-only", [&step] { step.set_brepmesh_only(true); });
  add_value(command, "--step-memory", "MB", "a whole number of MiB, at least 64", [&step](const std::string& v) {
    double mb = 0;
    if (!parse_number(v, mb) || !(mb >= 64 && mb <= 4194304) || mb != std::floor(mb)) return false;
    step.set_reader_memory_mb(static_cast<uint32_t>(mb));
    return true;
  });
  add_value(command, "--step-seconds", "SEC", "a number of seconds > 0", [&step](const std::string& v) {
    double s = 0;
    if (!parse_number(v, s) || !(s > 0 && std::isfinite(s))) return false;
    step.set_reader_seconds(s);
    return true;
  });
}

}  // namespace

void add_map_options(CLI::App& command, AnalysisArgs& args) {
  add_value(command, "--feature-angle", "DEG", "an angle in degrees, 0 < DEG < 180", [&args](const std::string& v) {
    double deg = 0;
    if (!parse_number(v, deg) || !(deg > 0 && deg < 180)) return false;
    args.feature_angle = deg;
    return true;
  });
  add_value(command, "--method", "M", "eme or convex", [&args](const std::string& v) {
    args.convex = v == "convex";
    return args.convex || v == "eme";
  });
  command.add_flag("--lvm-only", args.lvm_only);
  add_step_options(command, args.step);
  // The default since 0.2; still accepted so that existing scripts keep working.
  command.add_flag("--global-occlusion")->group("");
}

namespace {

// Where it runs and what it prints: the same maps whatever these say.
void add_run_options(CLI::App& command, AnalysisArgs& args) {
  command.add_option("--json", args.json)->type_name("OUT");
  command.add_option("--report", args.report)->type_name("HTML");
  add_threads(command, args.threads);
  add_value(command, "--server", "ADDRESS", "the daemon's address, e.g. unix:/run/user/1000/gvmd.sock",
            [&args](const std::string& v) {
              args.server = v;
              return !v.empty();
            });
  add_value(command, "--timeout", "SEC", "a number of seconds > 0", [&args](const std::string& v) {
    return parse_number(v, args.timeout_seconds) && args.timeout_seconds > 0;
  });
  command.add_flag("-v,--verbose", args.verbose);
  command.add_flag("-q,--quiet", args.quiet);
}

}  // namespace

void add_analysis_options(CLI::App& command, AnalysisArgs& args) {
  command.add_option("PART", args.parts, "mesh file(s); several with --server")->type_name("PART");
  command.add_option("--groups", args.groups)->type_name("FILE");
  add_map_options(command, args);
  add_run_options(command, args);
}

AnalyzeRequest analyze_request(const AnalysisArgs& args) {
  AnalyzeRequest request;
  request.part_path = args.parts.empty() ? std::string() : args.parts.front();
  request.groups_path = args.groups;
  request.options.set_threads(args.threads);
  request.options.set_lvm_only(args.lvm_only);
  if (args.convex) {
    request.options.set_occlusion_method(v1::OCCLUSION_METHOD_CONVEX_DECOMPOSITION);
  }
  if (args.feature_angle) request.options.set_feature_angle_degrees(*args.feature_angle);
  *request.options.mutable_step() = args.step;
  return request;
}

std::optional<int> check_parts(const AnalysisArgs& args, const char* command) {
  if (args.parts.empty()) return usage_error(std::string(command) + " needs a PART file");
  if (args.server.empty()) {
    if (args.parts.size() > 1) {
      return usage_error("more than one PART given ('" + args.parts[0] + "', '" + args.parts[1] +
                         "'); several parts are submitted together with --server");
    }
    if (args.timeout_seconds > 0) return usage_error("--timeout is the daemon's deadline: it needs --server");
  } else if (args.parts.size() > 1 && !args.json.empty()) {
    return usage_error("--json writes one part's result: give one PART with it");
  } else if (args.parts.size() > 1 && !args.report.empty()) {
    return usage_error("--report draws one part: give one PART with it");
  }
  // A report that cannot be written is known now, not after the work.
  if (!args.report.empty()) {
    if (Status s = report::check_report_path(args.report); !s.ok()) return usage_error(s.message());
  }
  return std::nullopt;
}

int write_report(const AnalysisArgs& args, const SolidMesh* mesh, const v1::Analysis& analysis, const v1::Plan* plan) {
  if (args.report.empty()) return 0;
  std::optional<StatusOr<SolidMesh>> loaded;
  if (!mesh) {
    loaded.emplace(load_part_solid(analyze_request(args)));
    if (!loaded->ok()) return failure(loaded->status().message());
    mesh = &loaded->value();
  }
  const std::string html = plan ? report::plan_report(*mesh, analysis, *plan) : report::analysis_report(*mesh, analysis);
  if (!write_output(args.report, html)) return failure("cannot write the report to '" + args.report + "'");
  return 0;
}

void set_log_level(const AnalysisArgs& args) {
  if (args.verbose) spdlog::set_level(spdlog::level::debug);
  if (args.quiet) spdlog::set_level(spdlog::level::err);
}

}  // namespace gvm::cli
