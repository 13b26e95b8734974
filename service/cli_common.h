// What the commands of the `gvm` command line share: the options of an analysis, number
// parsing, usage errors, logging and writing output files.
#pragma once

#include <charconv>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gvm/analysis.h"
#include "gvm/v1/plan.pb.h"

// CLI11 stays out of this header: remote_client.cpp includes it too.
namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace gvm::cli {

// The program messages name: "gvm" unless set.
void set_program_name(const std::string& name);

// Prints "gvm: message" and the hint to stderr; returns the usage-error status, 2.
int usage_error(const std::string& message);

template <class T>
bool parse_number(const std::string& text, T& out) {
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, out);
  return ec == std::errc() && ptr == end;
}

// Writes through a temporary file and renames it, so a failure never leaves half a file;
// "-" writes to standard output.
bool write_output(const std::string& path, const std::string& content);

// The options every command that analyses a part takes.
struct AnalysisArgs {
  std::vector<std::string> parts;    // one, or several with --server
  std::string server;                // --server ADDRESS: run on a daemon (gvmd)
  double timeout_seconds = 0;        // --timeout: the daemon's deadline (0: none)
  std::string groups;
  std::string json;                  // the command's main JSON output
  std::string report;                // --report FILE: the HTML report
  std::optional<double> feature_angle;
  unsigned threads = 0;
  bool lvm_only = false;
  v1::StepOptions step;              // STEP parts: --solid, --deflection, --angle, --features
  bool convex = false;
  bool verbose = false;
  bool quiet = false;
};

// Adds the option `name` taking one value (METAVAR `meta`) that `read` parses into its
// destination. We read values ourselves rather than with CLI11's typed options: numbers
// the way the rest of gvm reads them (from_chars: "010" is ten, not octal eight; doubles
// rounded once), and a refused value gets a usage error naming the option and saying
// what it `needs` ("an angle in degrees, 0 < DEG < 180"), not only that it is invalid.
CLI::Option* add_value(CLI::App& command, const std::string& name, const std::string& meta,
                       const std::string& needs, std::function<bool(const std::string&)> read);

// --threads N, 1 to 1024.
void add_threads(CLI::App& command, unsigned& threads);

// How the maps are computed: --feature-angle, --method, --lvm-only and the STEP options,
// read into args (which must outlive the parse).
void add_map_options(CLI::App& command, AnalysisArgs& args);

// The PARTs and the options every command that analyses a part takes, read into args
// (which must outlive the parse).
void add_analysis_options(CLI::App& command, AnalysisArgs& args);

AnalyzeRequest analyze_request(const AnalysisArgs& args);
// Exit status of a usage error when the parts given do not fit the options (several
// parts need --server; --json then needs one part).
std::optional<int> check_parts(const AnalysisArgs& args, const char* command);
void set_log_level(const AnalysisArgs& args);

// Writes args.report, if asked: the report of `plan` when set, else of the analysis.
// `mesh` is the analysis's own, or null for a result from a daemon: then the part file is
// read and validated here. Returns 0, or the exit status of a failure it printed.
int write_report(const AnalysisArgs& args, const SolidMesh* mesh, const v1::Analysis& analysis, const v1::Plan* plan);

// "gvm: message" to stderr; returns 1.
int failure(const std::string& message);

}  // namespace gvm::cli
