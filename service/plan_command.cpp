// gvm plan: the fewest setups (or rotary axes, or probe orientations) for a part.
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "cli_common.h"
#include "commands.h"
#include "gvm/analysis_proto.h"
#include "gvm/planner/plan.h"
#include "plan_options.h"
#include "plan_report.h"
#include "remote_client.h"

namespace gvm::cli {
namespace {

struct PlanArgs {
  AnalysisArgs analysis;
  std::string analysis_json;
  v1::PlanOptions options;
};

// Progress: phases at debug level, and at info level once planning has taken a while.
planner::PlanControl progress_log() {
  const auto start = std::chrono::steady_clock::now();
  planner::PlanControl control;
  control.progress = [start, last = std::string()](std::string_view phase, size_t done, size_t total) mutable {
    if (phase != last) {
      last = std::string(phase);
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      spdlog::log(s > 2 ? spdlog::level::info : spdlog::level::debug, "planning: {} ({}/{}), {:.1f} s",
                  last, done, total, s);
    }
    return true;
  };
  return control;
}

// The JSON files and the reports, the same whether the plan was made here or on a daemon
// (then `mesh` is null).
int emit(const PlanArgs& args, const v1::Plan& plan, const v1::Analysis* analysis, const SolidMesh* mesh) {
  const std::string& json = args.analysis.json;
  if (!json.empty() && !write_output(json, to_json(plan))) return failure("cannot write JSON to '" + json + "'");
  if (!args.analysis_json.empty() && !write_output(args.analysis_json, to_json(*analysis))) {
    return failure("cannot write the analysis JSON to '" + args.analysis_json + "'");
  }
  if (analysis) {
    if (int exit = write_report(args.analysis, mesh, *analysis, &plan)) return exit;
  }
  const bool stdout_taken = json == "-" || args.analysis_json == "-" || args.analysis.report == "-";
  if (!args.analysis.quiet && !stdout_taken) print_plan(plan, std::cout);
  return 0;
}

int run_plan(PlanArgs& args) {
  if (auto exit = check_parts(args.analysis, "plan")) return *exit;
  if (!args.analysis_json.empty() && args.analysis.parts.size() > 1) {
    return usage_error("--analysis-json writes one part's analysis: give one PART with it");
  }
  args.options.set_threads(args.analysis.threads);
  if (Status s = planner::validate(args.options); !s.ok()) return usage_error(with_flag_names(s.message()));
  set_log_level(args.analysis);
  // The report draws the maps: it needs the analysis as well.
  const bool with_analysis = !args.analysis_json.empty() || !args.analysis.report.empty();
  if (!args.analysis.server.empty()) {
    return remote_plan(args.analysis, args.options, with_analysis, [&](const std::string&, const v1::PlanResponse& r) {
      return emit(args, r.plan(), with_analysis ? &r.analysis() : nullptr, nullptr);
    });
  }

  auto analysis = analyze(analyze_request(args.analysis));
  if (!analysis.ok()) return failure(analysis.status().message());
  auto plan = planner::plan(*analysis, args.options, progress_log());
  if (!plan.ok()) return failure(plan.status().message());
  if (!with_analysis) return emit(args, plan->message, nullptr, nullptr);
  const v1::Analysis message = to_proto(*analysis);
  return emit(args, plan->message, &message, &analysis->mesh());
}

}  // namespace

Run add_plan(CLI::App& gvm) {
  CLI::App* command = gvm.add_subcommand("plan", "the fewest setups that reach every feature, provably");
  auto args = std::make_shared<PlanArgs>();
  add_analysis_options(*command, args->analysis);
  add_plan_options(*command, args->options);
  command->add_option("--analysis-json", args->analysis_json)->type_name("OUT");
  return [args] { return run_plan(*args); };
}

}  // namespace gvm::cli
