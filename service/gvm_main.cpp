// gvm: command-line front end of the accessibility engine and planner.
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cli_app.h"
#include "cli_common.h"
#include "batch/local_batch.h"
#include "commands.h"

namespace {

constexpr const char* kUsage = R"(gvm - exact global visibility maps and setup plans of CAD parts

Usage:
  gvm plan PART [options]       the fewest setups (or rotary axes, or probe head
                                orientations) that reach every feature, provably
  gvm analyze PART [options]    every concave region and feature with its maps
  gvm plan|analyze --server ADDRESS PART... [options]
                                the same on a daemon (gvmd), several parts at once
  gvm batch MANIFEST --out DIR [options]
                                every part of a manifest planned, the plans in
                                DIR; a part that fails is recorded, the rest go on
  gvm --help                    show this help
  gvm --version                 show the version

PART is a closed polyhedral mesh: OFF, OBJ, STL (ASCII or binary) or PLY, or a STEP
file (.stp, .step: one B-rep solid, tessellated, its B-rep faces the features). It is
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
  --report HTML        also write a self-contained HTML report: the part in 3D
                       coloured by setup, every GVM on the sphere, the tables,
                       a static view along each setup (checked before any work)
  --solid N            STEP: the solid to read when the file holds several (from 0)
  --deflection MM      STEP: the tessellation's linear deflection (default 0.1% of
                       the bounding box diagonal)
  --angle DEG          STEP: the tessellation's angular deflection (default 10)
  --features F         STEP: brep (default, one feature per B-rep face) or auto
                       (grouped from the mesh, as for any mesh)
  --group-holes        STEP: the B-rep faces of one hole (coaxial cylinder and
                       cone walls, the planes closing them) are one feature
  --brepmesh-only      STEP: BRepMesh's triangles as they are, without the faithful
                       tessellation (which keeps the B-rep's normals and axes
                       exactly: hole walls parallel to their axes); to compare
  --step-memory MB     STEP: the address space of the process that reads the file
                       (default 1 GiB + 256 x the file's size, at least 2 GiB)
  --step-seconds SEC   STEP: its CPU time (default 600); a crash, a loop or a file
                       over these limits fails this part only
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
  --tolerance ANGLE    a feature is reached along u when u is within ANGLE of its
                       GVM, decided exactly (radians, or degrees as 0.001deg;
                       default 1e-6: above the rounding of float STL facets,
                       below any machine's resolution); 0: exact plans
  --no-split           keep automatic features whole (by default one that no
                       single direction sees, its own faces having no common
                       direction, is planned in pieces that each have one)
  --split-max-faces N  split only automatic features of at most N faces (default
                       20000: each piece costs a GVM; 0: no limit)
  --split              also plan every other unreachable feature piece by piece
                       (its coplanar connected pieces): "machinable in two setups"
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

batch options (with the plan options, --feature-angle, --method, --lvm-only, the
STEP options, --threads, -v and -q, applied to every part):
  MANIFEST             the parts: one path a line ('#' comments), or a CSV with a
                       header (columns part, groups, name and any field of
                       PlanOptions or AnalyzeOptions: mode, min_clearance_degrees,
                       step.solid, ...), or a JSON gvm.v1.BatchManifest (by the
                       extension .csv, .json); relative paths from its directory
  --out DIR            writes NAME.plan.json and NAME.result.json per part (NAME:
                       the file name without extension, or the manifest's name),
                       then summary.csv and summary.json
  --jobs N             parts at once, on one pool of --threads (default 2)
  --max-memory SIZE    start a part only while the parts running are expected to
                       fit in SIZE (e.g. 8G); one part always runs
  --part-timeout SEC   stop a part after SEC seconds (recorded as timed out)
  --resume             skip the parts done before with the same input and options
  --analysis           also write NAME.analysis.json
Directions are unit vectors u along which rays leave the surface; a tool or probe
approaches along -u. Faces are numbered from 0 in input-file order.

Exit status: 0 success, 1 invalid input or failure (batch: a part not done), 2 usage
error, 128+N a batch stopped by signal N (--resume goes on).
)";

// The commands and the options they share with the top level; how to run each command.
std::map<std::string, gvm::cli::Run> add_commands(CLI::App& app) {
  // As before CLI11: an option given twice takes its last value; unknown arguments are
  // kept, not thrown, so that the message can say "unknown command" or "unknown option".
  // Subcommands inherit both when added.
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.allow_extras();
  // One command: then "help" or "analyze" after `gvm plan` are PARTs, as before CLI11.
  app.require_subcommand(0, 1);
  app.set_version_flag("--version", std::string("gvm ") + GVM_VERSION, "show the version");
  std::map<std::string, gvm::cli::Run> commands = {{"analyze", gvm::cli::add_analyze(app)},
                                                    {"plan", gvm::cli::add_plan(app)},
                                                    {"batch", gvm::cli::add_batch(app, gvm::batch::run_local)}};
  app.add_subcommand("help", "show this help")->allow_extras();
  gvm::cli::add_help_flag(app);
  for (const auto& [name, run] : commands) gvm::cli::add_help_flag(*app.get_subcommand(name));
  return commands;
}

}  // namespace

int main(int argc, char** argv) {
  gvm::cli::set_up_logging("gvm");
  CLI::App app{"gvm - exact global visibility maps and setup plans of CAD parts", "gvm"};
  const std::map<std::string, gvm::cli::Run> commands = add_commands(app);
  if (std::optional<int> exit = gvm::cli::parse(app, argc, argv, kUsage)) return *exit;

  const std::vector<CLI::App*> chosen = app.get_subcommands();
  const std::string command = chosen.empty() ? std::string() : chosen.front()->get_name();
  if (command == "help") {
    std::cout << kUsage;
    return 0;
  }  // whatever follows it
  if (const std::vector<std::string> extra = app.remaining(true); !extra.empty()) return gvm::cli::unknown(extra.front());
  if (command.empty()) return gvm::cli::usage_error("no command given");
  return commands.at(command)();
}
