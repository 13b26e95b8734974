#include "cli_common.h"

#include <spdlog/spdlog.h>

#include <filesystem>
#include <fstream>
#include <iostream>

namespace gvm::cli {

int usage_error(const std::string& message) {
  std::cerr << "gvm: " << message << "\nRun 'gvm --help' for usage.\n";
  return 2;
}

int failure(const std::string& message) {
  std::cerr << "gvm: " << message << "\n";
  return 1;
}

bool write_output(const std::string& path, const std::string& content) {
  if (path == "-") {
    std::cout << content;
    return static_cast<bool>(std::cout.flush());
  }
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out || !(out << content) || !out.flush()) {
      std::error_code ec;
      std::filesystem::remove(tmp, ec);
      return false;
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) std::filesystem::remove(tmp, ec);
  return !ec;
}

std::optional<int> parse_analysis_arg(const std::vector<std::string>& argv, size_t& i,
                                      AnalysisArgs& args, bool* mine) {
  *mine = true;
  const std::string& a = argv[i];
  auto value = [&]() -> std::optional<std::string> {
    if (i + 1 >= argv.size()) return std::nullopt;
    return argv[++i];
  };
  if (a == "--groups") {
    auto v = value();
    if (!v) return usage_error("--groups needs a FILE");
    args.groups = *v;
  } else if (a == "--json") {
    auto v = value();
    if (!v) return usage_error("--json needs an output FILE");
    args.json = *v;
  } else if (a == "--threads") {
    auto v = value();
    if (!v || !parse_number(*v, args.threads) || args.threads == 0 || args.threads > 1024) {
      return usage_error("--threads needs a number from 1 to 1024");
    }
  } else if (a == "--feature-angle") {
    double deg = 0;
    auto v = value();
    if (!v || !parse_number(*v, deg) || !(deg > 0 && deg < 180)) {
      return usage_error("--feature-angle needs an angle in degrees, 0 < DEG < 180");
    }
    args.feature_angle = deg;
  } else if (a == "--method") {
    auto v = value();
    if (!v || (*v != "eme" && *v != "convex")) return usage_error("--method needs eme or convex");
    args.convex = *v == "convex";
  } else if (a == "--lvm-only") {
    args.lvm_only = true;
  } else if (a == "--global-occlusion") {
    // The default since 0.2; still accepted so that existing scripts keep working.
  } else if (a == "-v" || a == "--verbose") {
    args.verbose = true;
  } else if (a == "-q" || a == "--quiet") {
    args.quiet = true;
  } else if (a == "--server") {
    auto v = value();
    if (!v || v->empty()) return usage_error("--server needs the daemon's address, e.g. unix:/run/user/1000/gvmd.sock");
    args.server = *v;
  } else if (a == "--timeout") {
    auto v = value();
    if (!v || !parse_number(*v, args.timeout_seconds) || !(args.timeout_seconds > 0)) {
      return usage_error("--timeout needs a number of seconds > 0");
    }
  } else if (!a.empty() && a[0] == '-' && a != "-") {
    *mine = false;
  } else {
    args.parts.push_back(a);
  }
  return std::nullopt;
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
  }
  return std::nullopt;
}

void set_log_level(const AnalysisArgs& args) {
  if (args.verbose) spdlog::set_level(spdlog::level::debug);
  if (args.quiet) spdlog::set_level(spdlog::level::err);
}

}  // namespace gvm::cli
