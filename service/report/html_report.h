// HTML reports of a plan or an analysis: one self-contained file (every script, style and
// picture inlined, nothing fetched when opened) with the part in 3D coloured by setup,
// every surface's GVM on the sphere of directions, the tables, and a static picture along
// each setup for print.
#pragma once

#include <string>

#include "gvm/mesh.h"
#include "gvm/status.h"
#include "gvm/v1/gvm.pb.h"
#include "gvm/v1/plan.pb.h"

namespace gvm::report {

// Whether a report can be written to `path` (its directory exists and takes a new file;
// the path is not a directory): checked before any work, the message names the path
// and the reason.
Status check_report_path(const std::string& path);

// `mesh` is the solid the analysis was made on (input face numbering as in the analysis).
std::string plan_report(const SolidMesh& mesh, const v1::Analysis& analysis, const v1::Plan& plan);
std::string analysis_report(const SolidMesh& mesh, const v1::Analysis& analysis);

}  // namespace gvm::report
