// The STEP module (engine/step/step_module.h): loaded for STEP input only, found beside the
// running program first, then where the build put it; a module that cannot be loaded is an
// error of the STEP part that names it, and mesh parts never need it. The dynamic loader's
// own log (LD_DEBUG=libs) says which files a run initialises.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/cli.h"
#include "support/scratch_dir.h"

namespace {

namespace fs = std::filesystem;

using gvm::test::run_program;
using gvm::test::shared;

const std::string kStepPart = shared("data/step/bug3883_xr2-ct-214_l-bracket.stp");
const std::string kMeshPart = shared("data/parts/trimesh_7_8ths_cube.stl");

// gvm in a directory of its own, /proc/self/exe naming it there: a hard link (a sanitizer
// build's gvm is 250 MB), a copy across file systems.
fs::path gvm_alone_in(const std::string& name) {
  const fs::path dir = gvm::test::scratch_dir() / name;
  fs::create_directories(dir);
  std::error_code ec;
  fs::create_hard_link(GVM_CLI_PATH, dir / "gvm", ec);
  if (ec) fs::copy_file(GVM_CLI_PATH, dir / "gvm", fs::copy_options::overwrite_existing);
  return dir;
}

const std::string kModuleName = fs::path(GVM_STEP_MODULE_PATH).filename().string();

// Whether the loader's log says it initialised a file whose path contains `name`.
bool initialised(const std::string& log, const std::string& name) {
  std::istringstream lines(log);
  for (std::string line; std::getline(lines, line);) {
    const size_t at = line.find("calling init: ");
    if (at != std::string::npos && line.find(name, at) != std::string::npos) return true;
  }
  return false;
}

TEST(StepModule, LoadedForStepInputOnly) {
  const auto mesh = run_program("LD_DEBUG=libs " GVM_CLI_PATH, "analyze " + kMeshPart + " -q");
  EXPECT_FALSE(initialised(mesh.out, "libTKernel"));
  const auto step = run_program("LD_DEBUG=libs " GVM_CLI_PATH, "analyze " + kStepPart + " -q");
  EXPECT_TRUE(initialised(step.out, "libgvm_step"));
}

TEST(StepModule, WithoutOneBesideTheProgramTheBuildsIsUsed) {
  const fs::path dir = gvm_alone_in("alone");
  const auto r = run_program((dir / "gvm").string(), "analyze " + kStepPart + " -q");
  EXPECT_EQ(r.status, 0) << r.out;
}

TEST(StepModule, OneBesideTheProgramComesFirstAndABrokenOneIsNamed) {
  const fs::path dir = gvm_alone_in("broken");
  std::ofstream(dir / kModuleName) << "not a shared object\n";
  const auto step = run_program((dir / "gvm").string(), "analyze " + kStepPart + " -q");
  EXPECT_NE(step.status, 0);
  EXPECT_NE(step.out.find(kStepPart), std::string::npos) << step.out;
  EXPECT_NE(step.out.find((dir / kModuleName).string() + ", which could not be loaded"), std::string::npos)
      << step.out;
  const auto mesh = run_program((dir / "gvm").string(), "analyze " + kMeshPart + " -q");
  EXPECT_EQ(mesh.status, 0) << mesh.out;
}

TEST(StepModule, OneCopiedBesideTheProgramIsTheOneLoaded) {
  const fs::path dir = gvm_alone_in("together");
  const fs::path module = dir / kModuleName;
  fs::copy_file(GVM_STEP_MODULE_PATH, module, fs::copy_options::overwrite_existing);
  const auto r = run_program("LD_DEBUG=libs " + (dir / "gvm").string(), "analyze " + kStepPart + " -q");
  EXPECT_EQ(r.status, 0) << r.out.substr(r.out.size() > 2000 ? r.out.size() - 2000 : 0);
  EXPECT_TRUE(initialised(r.out, module.string()));
  EXPECT_FALSE(initialised(r.out, GVM_STEP_MODULE_PATH));
}

}  // namespace
