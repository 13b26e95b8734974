// What the commands of the `gvm` command line share: the options of an analysis, number
// parsing, usage errors, logging and writing output files.
#pragma once

#include <charconv>
#include <optional>
#include <string>
#include <vector>

#include "gvm/analysis.h"

namespace gvm::cli {

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
  std::optional<double> feature_angle;
  unsigned threads = 0;
  bool lvm_only = false;
  bool convex = false;
  bool verbose = false;
  bool quiet = false;
};

// Reads argv[i] (and its value, advancing i) when it is one of the shared options or the
// PART. Returns nothing when consumed, an exit status on a usage error; sets *mine to
// false when the argument is not a shared option (the command decides).
std::optional<int> parse_analysis_arg(const std::vector<std::string>& argv, size_t& i,
                                      AnalysisArgs& args, bool* mine);

AnalyzeRequest analyze_request(const AnalysisArgs& args);
// Exit status of a usage error when the parts given do not fit the options (several
// parts need --server; --json then needs one part).
std::optional<int> check_parts(const AnalysisArgs& args, const char* command);
void set_log_level(const AnalysisArgs& args);

// "gvm: message" to stderr; returns 1.
int failure(const std::string& message);

}  // namespace gvm::cli
