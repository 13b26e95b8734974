// `gvm analyze|plan --server ADDRESS PART...`: the parts submitted to a daemon (gvmd) all
// at once, one request each, their results printed in PART order exactly as the command
// runs them locally.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "cli_common.h"
#include "gvm/v1/service.pb.h"

namespace gvm::cli {

// What to do with one part's result; returns the part's exit status.
using AnalysisSink = std::function<int(const std::string& part, const v1::AnalyzeResponse&)>;
using PlanSink = std::function<int(const std::string& part, const v1::PlanResponse&)>;

int remote_analyze(const AnalysisArgs& args, const AnalysisSink& sink);
int remote_plan(const AnalysisArgs& args, const v1::PlanOptions& options, bool include_analysis,
                const PlanSink& sink);

}  // namespace gvm::cli
