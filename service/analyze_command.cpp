// gvm analyze: every region and feature with its maps, as a report and as JSON.
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>

#include "analysis_report.h"
#include "cli_common.h"
#include "commands.h"
#include "gvm/analysis_proto.h"
#include "remote_client.h"

namespace gvm::cli {

namespace {

// The report and the JSON, the same whether the analysis ran here or on a daemon (then
// `mesh` is null and the part file is read here for the HTML report).
int emit(const AnalysisArgs& args, const v1::Analysis& result, const SolidMesh* mesh) {
  if (!args.json.empty() && !write_output(args.json, to_json(result))) {
    return failure("cannot write JSON to '" + args.json + "'");
  }
  if (int exit = write_report(args, mesh, result, nullptr)) return exit;
  if (!args.quiet && args.json != "-" && args.report != "-") print_report(result, std::cout);
  return 0;
}

int run_analyze(const AnalysisArgs& args) {
  if (auto exit = check_parts(args, "analyze")) return *exit;
  set_log_level(args);
  if (!args.server.empty()) {
    return remote_analyze(args, [&](const std::string&, const v1::AnalyzeResponse& r) {
      return emit(args, r.analysis(), nullptr);
    });
  }

  auto analysis = analyze(analyze_request(args));
  if (!analysis.ok()) return failure(analysis.status().message());
  return emit(args, to_proto(*analysis), &analysis->mesh());
}

}  // namespace

Run add_analyze(CLI::App& gvm) {
  CLI::App* command = gvm.add_subcommand("analyze", "every concave region and feature with its maps");
  auto args = std::make_shared<AnalysisArgs>();
  add_analysis_options(*command, *args);
  return [args] { return run_analyze(*args); };
}

}  // namespace gvm::cli
