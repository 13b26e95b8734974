// gvm: command-line front end of the accessibility engine and planner.
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <iostream>
#include <map>
#include <optional>
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

// -h/--help anywhere prints the whole usage at once, as before CLI11: its own help flag
// would first check every other value given.
void add_help_flag(CLI::App& command) {
  command.set_help_flag();
  command.add_flag_callback("-h,--help", [] { throw CLI::CallForHelp(); }, "show this help")->trigger_on_parse();
}

// The first argument no command took: a word where a command belongs, or an option.
int unknown(const std::string& arg) {
  return gvm::cli::usage_error(std::string(arg.starts_with('-') ? "unknown option '" : "unknown command '") + arg + "'");
}

int usage() {
  std::cout << kUsage;
  return 0;
}

void set_up_logging() {
  auto logger = spdlog::stderr_color_mt("gvm");
  spdlog::set_default_logger(logger);
  spdlog::set_pattern("gvm: %v");
  spdlog::set_level(spdlog::level::info);
}

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
                                                    {"plan", gvm::cli::add_plan(app)}};
  app.add_subcommand("help", "show this help")->allow_extras();
  add_help_flag(app);
  for (const auto& [name, run] : commands) add_help_flag(*app.get_subcommand(name));
  return commands;
}

// Parses argv into app's options; the exit status when that decides it (help, version,
// a usage error).
std::optional<int> parse(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    return usage();
  } catch (const CLI::CallForVersion& e) {
    std::cout << e.what() << "\n";
    return 0;
  } catch (const CLI::ArgumentMismatch& e) {
    // CLI11 says "--threads: 1 required N missing"; a person says it like this.
    const std::string what = e.what();
    return gvm::cli::usage_error(what.substr(0, what.find(':')) + " needs a value");
  } catch (const CLI::ParseError& e) {
    return gvm::cli::usage_error(e.what());
  }
  return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
  set_up_logging();
  CLI::App app{"gvm - exact global visibility maps and setup plans of CAD parts", "gvm"};
  const std::map<std::string, gvm::cli::Run> commands = add_commands(app);
  if (std::optional<int> exit = parse(app, argc, argv)) return *exit;

  const std::vector<CLI::App*> chosen = app.get_subcommands();
  const std::string command = chosen.empty() ? std::string() : chosen.front()->get_name();
  if (command == "help") return usage();  // whatever follows it
  if (const std::vector<std::string> extra = app.remaining(true); !extra.empty()) return unknown(extra.front());
  if (command.empty()) return gvm::cli::usage_error("no command given");
  return commands.at(command)();
}
