// gvm: command-line front end of the accessibility engine and planner.
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <iostream>
#include <string>
#include <vector>

#include "cli_common.h"
#include "commands.h"

namespace {

constexpr const char* kUsage = R"(gvm - exact global visibility maps and setup plans of CAD parts

Usage:
  gvm plan PART [options]       the fewest setups (or rotary axes, or probe head
                                orientations) that reach every feature, provably
  gvm analyze PART [options]    every concave region and feature with its maps
  gvm plan|analyze --server ADDRESS PART... [options]
                                the same on a daemon (gvmd), several parts at once
  gvm --help                    show this help
  gvm --version                 show the version

PART is a closed polyhedral mesh: OFF, OBJ, STL (ASCII or binary) or PLY. It is
validated first (closed, manifold, consistently and outward oriented, no zero-area
or duplicate faces, no self-intersections); internal voids are allowed.

Options of both commands:
  --groups FILE        user features: JSON object of named lists of input face
                       indices, e.g. {"pocket": [12, 13, 14], "slot": [40, 41]}.
                       Without it, OBJ groups (g) are used, else features are
                       found automatically.
  --feature-angle DEG  automatic features: largest angle normals may turn across
                       an edge inside one feature (default 30)
  --json OUT           also write the result as JSON (protobuf JSON mapping of
                       gvm.v1.Plan for plan, gvm.v1.Analysis for analyze) to OUT
                       ("-" for standard output)
  --threads N          worker threads (default: all cores)
  --method M           how the occlusion by O_S is computed: eme (effective
                       Minkowski envelope, the default) or convex (union of
                       pairwise occlusion maps, the baseline); same GVMs
  --lvm-only           skip the occlusion by O_S (effective Minkowski envelope):
                       report LVM(S + N_S) only, an outer bound of each GVM
                       that takes a fraction of the time
  --server ADDRESS     run on the daemon gvmd listening at ADDRESS (unix:PATH, as
                       gvmd prints on start); several PARTs are submitted at
                       once and printed in order; the output is the same
  --timeout SEC        with --server: the request's deadline
  -v, --verbose        log details to standard error
  -q, --quiet          print only errors (no report)

plan options:
  --mode M             setup (default): 3-axis machining or mould pulls, one tool
                         direction per setup;
                       rotary: 4-axis indexer, one rotary axis per setup, the
                         tool perpendicular to it (reports the table angles);
                       probe: CMM indexing head, one orientation of its grid per
                         setup, the probe's cone inside the GVM
  --surfaces S         features (default) or regions (concave regions)
  --concave-only       plan the concave features only (default: every feature,
                       hull features too)
  --planar-normal      a planar feature is reached only along its own normal
                       (a flat-end tool facing it, a probe touching it square)
  --split              plan an unreachable feature piece by piece (its coplanar
                       connected pieces): "machinable in two setups"
  --time-limit SEC     stop the exact set cover after SEC seconds and report the
                       best plan with its gap to the lower bound
  --min-clearance DEG  setup mode: a direction serves a feature only with this
                       clearance inside its GVM (GVMs that are arcs or points keep
                       their exact directions and are flagged)
  --head A0:A1:B0:B1:S probe mode: head tilt A from A0 to A1, rotation B from B0
                       to B1, step S, in degrees (default 0:105:-180:180:7.5)
  --part-up AXIS       probe mode: the part axis pointing up along the machine's
                       z: +x, -x, +y, -y, +z (default), -z or a vector X,Y,Z
  --cone DEG           probe mode: conical tolerance (default 5)
  --analysis-json OUT  also write the analysis the plan was made from

Directions are unit vectors u along which rays leave the surface; a tool or probe
approaches along -u. Faces are numbered from 0 in input-file order.

Exit status: 0 success, 1 invalid input or failure, 2 usage error.
)";

}  // namespace

int main(int argc, char** argv) {
  auto logger = spdlog::stderr_color_mt("gvm");
  spdlog::set_default_logger(logger);
  spdlog::set_pattern("gvm: %v");
  spdlog::set_level(spdlog::level::info);

  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) return gvm::cli::usage_error("no command given");
  const std::string command = args.front();
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  for (const std::string& a : args) {
    if (a == "--help" || a == "-h" || (a == "help" && &a == &args.front())) {
      std::cout << kUsage;
      return 0;
    }
  }
  if (command == "--version") {
    std::cout << "gvm " << GVM_VERSION << "\n";
    return 0;
  }
  if (command == "analyze") return gvm::cli::run_analyze(rest);
  if (command == "plan") return gvm::cli::run_plan(rest);
  return gvm::cli::usage_error("unknown command '" + command + "'");
}
