// gvm batch (and gvm-mpi batch): every part of a manifest planned, the outputs in a
// directory, a failing part recorded and the batch going on.
#include <unistd.h>

#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <memory>
#include <thread>

#include "batch/batch.h"
#include "cli_common.h"
#include "commands.h"
#include "gvm/planner/plan.h"
#include "plan_options.h"

namespace gvm::cli {
namespace {

namespace fs = std::filesystem;

struct BatchArgs {
  std::string manifest;
  AnalysisArgs analysis;      // the map options, threads, -v, -q
  v1::PlanOptions plan;
  batch::BatchOptions options;
};

// "8G", "512M", "1.5G", "300000000": bytes.
bool parse_size(const std::string& text, uint64_t& bytes) {
  static const std::string kUnits = "KMGT";
  std::string number = text;
  double scale = 1;
  if (!number.empty()) {
    const size_t unit = kUnits.find(static_cast<char>(std::toupper(static_cast<unsigned char>(number.back()))));
    if (unit != std::string::npos) {
      scale = std::ldexp(1.0, 10 * static_cast<int>(unit + 1));
      number.pop_back();
    }
  }
  double value = 0;
  if (!parse_number(number, value) || !(value > 0) || !(value * scale <= 0x1p62)) return false;
  bytes = static_cast<uint64_t>(value * scale);
  return true;
}

void add_batch_options(CLI::App& command, BatchArgs& args) {
  batch::BatchOptions& o = args.options;
  command.add_option("MANIFEST", args.manifest, "the parts: a path a line, or CSV, or JSON")->type_name("MANIFEST");
  add_value(command, "--out", "DIR", "a directory", [&o](const std::string& v) {
    o.out = v;
    return !v.empty();
  });
  add_value(command, "--jobs", "N", "a number from 1 to 256", [&o](const std::string& v) {
    return parse_number(v, o.jobs) && o.jobs >= 1 && o.jobs <= 256;
  });
  add_value(command, "--max-memory", "SIZE", "a size in bytes, or with K, M, G, T (e.g. 8G)",
            [&o](const std::string& v) { return parse_size(v, o.max_memory); });
  add_value(command, "--part-timeout", "SEC", "a number of seconds > 0", [&o](const std::string& v) {
    return parse_number(v, o.part_timeout_seconds) && o.part_timeout_seconds > 0 && std::isfinite(o.part_timeout_seconds);
  });
  command.add_flag("--resume", o.resume);
  command.add_flag("--analysis", o.write_analysis);
  add_threads(command, args.analysis.threads);
  command.add_flag("-v,--verbose", args.analysis.verbose);
  command.add_flag("-q,--quiet", args.analysis.quiet);
}

std::string host_name() {
  char name[256] = {};
  if (gethostname(name, sizeof name - 1) != 0) return "localhost";
  return name;
}

// The manifest read and every option checked, the output directory made: then the runner.
int run_batch(BatchArgs& args, const BatchRunner& runner) {
  if (args.manifest.empty()) return usage_error("batch needs a MANIFEST file");
  if (args.options.out.empty()) return usage_error("batch needs --out DIR, where the plans are written");
  if (Status s = planner::validate(args.plan); !s.ok()) return usage_error(with_flag_names(s.message()));
  const v1::AnalyzeOptions analyze = analyze_request(args.analysis).options;
  if (Status s = validate(analyze); !s.ok()) return usage_error(s.message());
  // The batch shows each part's progress itself: the engine's lines only with -v.
  spdlog::set_level(spdlog::level::warn);
  set_log_level(args.analysis);
  StatusOr<std::vector<batch::BatchItem>> items = batch::read_manifest(args.manifest, analyze, args.plan);
  if (!items.ok()) return usage_error(items.status().message());
  std::error_code ec;
  fs::create_directories(args.options.out, ec);
  if (ec || !fs::is_directory(args.options.out)) {
    return failure("cannot make the output directory '" + args.options.out.string() + "'");
  }
  batch::BatchOptions& o = args.options;
  o.threads = args.analysis.threads ? args.analysis.threads : std::max(1u, std::thread::hardware_concurrency());
  o.host = host_name();
  return runner(*items, o, args.analysis.quiet);
}

}  // namespace

Run add_batch(CLI::App& app, BatchRunner runner) {
  CLI::App* command = app.add_subcommand("batch", "every part of a manifest planned, outputs in a directory");
  auto args = std::make_shared<BatchArgs>();
  add_batch_options(*command, *args);
  add_map_options(*command, args->analysis);
  add_plan_options(*command, args->plan);
  return [args, runner = std::move(runner)] { return run_batch(*args, runner); };
}

}  // namespace gvm::cli
