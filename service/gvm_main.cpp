// gvm: command-line front end of the accessibility engine.
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "gvm/analysis.h"
#include "report.h"

namespace {

constexpr const char* kUsage = R"(gvm - exact global visibility maps of CAD parts

Usage:
  gvm analyze PART [options]    analyse a part and print a report
  gvm --help                    show this help
  gvm --version                 show the version

PART is a closed polyhedral mesh: OFF, OBJ, STL (ASCII or binary) or PLY. It is
validated first (closed, manifold, consistently and outward oriented, no zero-area
or duplicate faces, no self-intersections); internal voids are allowed.

analyze options:
  --groups FILE        user features: JSON object of named lists of input face
                       indices, e.g. {"pocket": [12, 13, 14], "slot": [40, 41]}.
                       Without it, OBJ groups (g) are used, else features are
                       found automatically.
  --feature-angle DEG  automatic features: largest angle normals may turn across
                       an edge inside one feature (default 30)
  --json OUT           also write the full result as JSON (protobuf JSON mapping
                       of gvm.v1.Analysis) to OUT ("-" for standard output)
  --threads N          worker threads (default: all cores)
  --method M           how the occlusion by O_S is computed: eme (effective
                       Minkowski envelope, the default) or convex (union of
                       pairwise occlusion maps, the baseline); same GVMs
  --lvm-only           skip the occlusion by O_S (effective Minkowski envelope):
                       report LVM(S + N_S) only, an outer bound of each GVM
                       that takes a fraction of the time
  -v, --verbose        log details to standard error
  -q, --quiet          print only errors (no report unless --json -)

Directions are unit vectors u along which rays leave the surface; a tool or probe
approaches along -u. Faces are numbered from 0 in input-file order.

Exit status: 0 success, 1 invalid input or failure, 2 usage error.
)";

struct Args {
  std::string part;
  std::string groups;
  std::string json;
  std::optional<double> feature_angle;
  unsigned threads = 0;
  bool verbose = false;
  bool lvm_only = false;
  bool convex = false;
  bool quiet = false;
};

int usage_error(const std::string& message) {
  std::cerr << "gvm: " << message << "\nRun 'gvm --help' for usage.\n";
  return 2;
}

template <class T>
bool parse_number(const std::string& text, T& out) {
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, out);
  return ec == std::errc() && ptr == end;
}

// Returns an exit status when parsing ends the program, nothing to go on.
std::optional<int> parse_analyze(const std::vector<std::string>& argv, Args& args) {
  for (size_t i = 0; i < argv.size(); ++i) {
    const std::string& a = argv[i];
    auto value = [&]() -> std::optional<std::string> {
      if (i + 1 >= argv.size()) return std::nullopt;
      return argv[++i];
    };
    if (a == "--help" || a == "-h") {
      std::cout << kUsage;
      return 0;
    } else if (a == "--groups") {
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
    } else if (!a.empty() && a[0] == '-' && a != "-") {
      return usage_error("unknown option '" + a + "'");
    } else if (args.part.empty()) {
      args.part = a;
    } else {
      return usage_error("more than one PART given ('" + args.part + "', '" + a + "')");
    }
  }
  if (args.part.empty()) return usage_error("analyze needs a PART file");
  return std::nullopt;
}

// Writes through a temporary file and renames it, so a failure never leaves half a file.
bool write_file_atomically(const std::string& path, const std::string& content) {
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

int run_analyze(const Args& args) {
  gvm::AnalyzeRequest request;
  request.part_path = args.part;
  request.groups_path = args.groups;
  request.options.set_threads(args.threads);
  request.options.set_lvm_only(args.lvm_only);
  if (args.convex) {
    request.options.set_occlusion_method(gvm::v1::OCCLUSION_METHOD_CONVEX_DECOMPOSITION);
  }
  if (args.feature_angle) request.options.set_feature_angle_degrees(*args.feature_angle);

  auto result = gvm::analyze(request);
  if (!result.ok()) {
    std::cerr << "gvm: " << result.status().message() << "\n";
    return 1;
  }
  if (!args.json.empty()) {
    std::string json = gvm::to_json(*result);
    if (args.json == "-") {
      std::cout << json;
    } else if (!write_file_atomically(args.json, json)) {
      std::cerr << "gvm: cannot write JSON to '" << args.json << "'\n";
      return 1;
    }
  }
  if (!args.quiet && args.json != "-") gvm::print_report(*result, std::cout);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  auto logger = spdlog::stderr_color_mt("gvm");
  spdlog::set_default_logger(logger);
  spdlog::set_pattern("gvm: %v");
  spdlog::set_level(spdlog::level::info);

  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) return usage_error("no command given");
  const std::string command = args.front();
  if (command == "--help" || command == "-h" || command == "help") {
    std::cout << kUsage;
    return 0;
  }
  if (command == "--version") {
    std::cout << "gvm " << GVM_VERSION << "\n";
    return 0;
  }
  if (command != "analyze") return usage_error("unknown command '" + command + "'");

  Args parsed;
  if (auto exit_code = parse_analyze({args.begin() + 1, args.end()}, parsed)) return *exit_code;
  if (parsed.verbose) spdlog::set_level(spdlog::level::debug);
  if (parsed.quiet) spdlog::set_level(spdlog::level::err);
  return run_analyze(parsed);
}
