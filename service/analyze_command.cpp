// gvm analyze: every region and feature with its maps, as a report and as JSON.
#include <iostream>

#include "analysis_report.h"
#include "cli_common.h"
#include "commands.h"
#include "gvm/analysis_proto.h"

namespace gvm::cli {

int run_analyze(const std::vector<std::string>& argv) {
  AnalysisArgs args;
  for (size_t i = 0; i < argv.size(); ++i) {
    bool mine = true;
    if (auto exit = parse_analysis_arg(argv, i, args, &mine)) return *exit;
    if (!mine) return usage_error("unknown option '" + argv[i] + "'");
  }
  if (args.part.empty()) return usage_error("analyze needs a PART file");
  set_log_level(args);

  auto analysis = analyze(analyze_request(args));
  if (!analysis.ok()) return failure(analysis.status().message());
  const v1::Analysis result = to_proto(*analysis);
  if (!args.json.empty() && !write_output(args.json, to_json(result))) {
    return failure("cannot write JSON to '" + args.json + "'");
  }
  if (!args.quiet && args.json != "-") print_report(result, std::cout);
  return 0;
}

}  // namespace gvm::cli
