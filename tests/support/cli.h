// The real `gvm` binary, run as a user runs it (tests only).
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace gvm::test {

struct CliRun {
  int status = -1;
  std::string out;  // stdout and stderr
};

// `program` (a copy of gvm, say) with `args`.
inline CliRun run_program(const std::string& program, const std::string& args) {
  const std::string cmd = program + " " + args + " 2>&1";
  CliRun r;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf;
  while (size_t n = fread(buf.data(), 1, buf.size(), pipe)) r.out.append(buf.data(), n);
  const int raw = pclose(pipe);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return r;
}

inline CliRun run_cli(const std::string& args) { return run_program(GVM_CLI_PATH, args); }

inline std::string shared(const std::string& rel) { return std::string(GVM_SHARED_DIR) + "/" + rel; }

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace gvm::test
