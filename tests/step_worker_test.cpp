// STEP input is read by a worker process (gvm-step-worker, engine/step_worker/), found
// beside the running program first, then where the build put it; the worker loads the
// STEP module (engine/step/step_module.h) found beside itself first. Mesh parts need
// neither, and the program itself never loads Open CASCADE. A worker or module that
// cannot be used is an error of the STEP part that names it. The dynamic loader's own log
// (LD_DEBUG=libs) says which files the program initialises (the worker's log goes to its
// own standard error, which the program keeps for messages).
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
const std::string kWorkerName = fs::path(GVM_STEP_WORKER_PATH).filename().string();
const std::string kModuleName = fs::path(GVM_STEP_MODULE_PATH).filename().string();

// A hard link where it can (a sanitizer build's binaries are large), else a copy.
void place(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::create_hard_link(from, to, ec);
  if (ec) fs::copy_file(from, to, fs::copy_options::overwrite_existing);
}

// gvm in a directory of its own, /proc/self/exe naming it there.
fs::path gvm_alone_in(const std::string& name) {
  const fs::path dir = gvm::test::scratch_dir() / name;
  fs::create_directories(dir);
  place(GVM_CLI_PATH, dir / "gvm");
  return dir;
}

// Whether the loader's log says it initialised a file whose path contains `name`.
bool initialised(const std::string& log, const std::string& name) {
  std::istringstream lines(log);
  for (std::string line; std::getline(lines, line);) {
    const size_t at = line.find("calling init: ");
    if (at != std::string::npos && line.find(name, at) != std::string::npos) return true;
  }
  return false;
}

TEST(StepWorker, TheProgramNeverLoadsOpenCascade) {
  const auto mesh = run_program("LD_DEBUG=libs " GVM_CLI_PATH, "analyze " + kMeshPart + " -q");
  EXPECT_EQ(mesh.status, 0);
  EXPECT_FALSE(initialised(mesh.out, "libTKernel"));
  const auto step = run_program("LD_DEBUG=libs " GVM_CLI_PATH, "analyze " + kStepPart + " -q");
  EXPECT_EQ(step.status, 0);
  EXPECT_TRUE(initialised(step.out, "libc.so"));  // the log is there...
  EXPECT_FALSE(initialised(step.out, "libgvm_step"));  // ...and the module is not in it
  EXPECT_FALSE(initialised(step.out, "libTKernel"));
}

TEST(StepWorker, WithoutOneBesideTheProgramTheBuildsIsUsed) {
  const fs::path dir = gvm_alone_in("alone");
  const auto r = run_program((dir / "gvm").string(), "analyze " + kStepPart + " -q");
  EXPECT_EQ(r.status, 0) << r.out;
}

TEST(StepWorker, OneBesideTheProgramComesFirst) {
  const fs::path dir = gvm_alone_in("worker-first");
  // A worker that says it ran, then is the real one (exec keeps its pid and parent).
  const fs::path ran = dir / "ran";
  fs::remove(ran);
  std::ofstream(dir / kWorkerName) << "#!/bin/sh\necho yes > " << ran << "\nexec " << GVM_STEP_WORKER_PATH
                                   << " \"$@\"\n";
  fs::permissions(dir / kWorkerName, fs::perms::owner_all);
  const auto r = run_program((dir / "gvm").string(), "analyze " + kStepPart + " -q");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(fs::exists(ran));
}

TEST(StepWorker, ABrokenWorkerIsNamedAndMeshesStillRead) {
  const fs::path dir = gvm_alone_in("broken-worker");
  std::ofstream(dir / kWorkerName) << "not a program\n";
  fs::permissions(dir / kWorkerName, fs::perms::owner_read | fs::perms::owner_write);
  const auto step = run_program((dir / "gvm").string(), "analyze " + kStepPart + " -q");
  EXPECT_EQ(step.status, 1);
  EXPECT_NE(step.out.find(kStepPart), std::string::npos) << step.out;
  EXPECT_NE(step.out.find((dir / kWorkerName).string() + ", which could not be started"), std::string::npos)
      << step.out;
  const auto mesh = run_program((dir / "gvm").string(), "analyze " + kMeshPart + " -q");
  EXPECT_EQ(mesh.status, 0) << mesh.out;
}

TEST(StepWorker, TheModuleBesideTheWorkerComesFirstAndABrokenOneIsNamed) {
  const fs::path dir = gvm_alone_in("broken-module");
  place(GVM_STEP_WORKER_PATH, dir / kWorkerName);
  std::ofstream(dir / kModuleName) << "not a shared object\n";
  const auto step = run_program((dir / "gvm").string(), "analyze " + kStepPart + " -q");
  EXPECT_EQ(step.status, 1);
  EXPECT_NE(step.out.find((dir / kModuleName).string() + ", which could not be loaded"), std::string::npos)
      << step.out;
  fs::remove(dir / kModuleName);
  place(GVM_STEP_MODULE_PATH, dir / kModuleName);
  const auto good = run_program((dir / "gvm").string(), "analyze " + kStepPart + " -q");
  EXPECT_EQ(good.status, 0) << good.out;
}

}  // namespace
