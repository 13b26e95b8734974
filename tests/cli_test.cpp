// The real `gvm` binary, run as a user would run it.
#include <google/protobuf/util/json_util.h>
#include <google/protobuf/util/message_differencer.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "gvm/v1/gvm.pb.h"
#include "support/cli.h"
#include "support/scratch_dir.h"

namespace {

namespace fs = std::filesystem;

using gvm::test::CliRun;
using gvm::test::read_file;
using gvm::test::shared;

CliRun run(const std::string& args) { return gvm::test::run_cli(args); }

gvm::v1::Analysis parse(const std::string& json) {
  gvm::v1::Analysis a;
  auto status = google::protobuf::util::JsonStringToMessage(json, &a);
  EXPECT_TRUE(status.ok()) << status.ToString();
  return a;
}

TEST(Cli, HelpIsCompleteAndSucceeds) {
  CliRun r = run("--help");
  EXPECT_EQ(r.status, 0);
  for (const char* word : {"analyze", "--groups", "--json", "--threads", "--feature-angle",
                           "--lvm-only", "OFF", "STL", "PLY", "OBJ"}) {
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
  }
}

TEST(Cli, UsageErrorsExitWithTwo) {
  EXPECT_EQ(run("").status, 2);
  EXPECT_EQ(run("frobnicate").status, 2);
  EXPECT_EQ(run("analyze").status, 2);
  CliRun r = run("analyze part.stl --threads zero");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("--threads"), std::string::npos);
}

// CLI11 parses the command line: its own errors are usage errors naming the option too.
TEST(Cli, UnknownOptionsAndMissingValuesAreUsageErrorsNamingTheOption) {
  const std::string part = shared("data/parts/prusa_plug-aligner.stl");
  for (const std::string args : {"--frobnicate", "-x", "--threads", "--json", "--threads=0", "--method=fast"}) {
    CliRun r = run("analyze " + part + " " + args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.out;
    const std::string option = args.substr(0, args.find('='));
    EXPECT_NE(r.out.find(option), std::string::npos) << args << ": " << r.out;
    EXPECT_NE(r.out.find("Run 'gvm --help' for usage."), std::string::npos) << args << ": " << r.out;
  }
  EXPECT_EQ(run("--frobnicate").status, 2);
  CliRun version = run("--version");
  EXPECT_EQ(version.status, 0);
  EXPECT_EQ(version.out.rfind("gvm ", 0), 0u) << version.out;
}

TEST(Cli, HelpWinsWhereverItIs) {
  for (const char* args : {"help", "-h", "analyze --help", "analyze part.stl --threads 0 -h", "help me"}) {
    CliRun r = run(args);
    EXPECT_EQ(r.status, 0) << args;
    EXPECT_NE(r.out.find("Exit status:"), std::string::npos) << args;
  }
}

TEST(Cli, MissingAndBrokenPartsAreRejectedWithTheProblemNamed) {
  CliRun missing = run("analyze /nonexistent/part.stl");
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.out.find("/nonexistent/part.stl"), std::string::npos) << missing.out;

  const fs::path& dir = gvm::test::scratch_dir();
  fs::path json = dir / "flipped.json";
  CliRun flipped = run("analyze " + shared("data/bad/prusa_endstop-block_FLIPPED.off") + " --json " +
                    json.string());
  EXPECT_EQ(flipped.status, 1);
  EXPECT_NE(flipped.out.find("inward"), std::string::npos) << flipped.out;
  EXPECT_FALSE(fs::exists(json)) << "nothing may be written for a rejected part";

  CliRun shared_edge = run("analyze " + shared("data/bad/trimesh_shared.STL"));
  EXPECT_EQ(shared_edge.status, 1);
  EXPECT_NE(shared_edge.out.find("non-manifold"), std::string::npos) << shared_edge.out;
}

TEST(Cli, ReportAndJsonOnARealPart) {
  const fs::path& dir = gvm::test::scratch_dir();
  fs::path json = dir / "plug.json";
  CliRun r = run("analyze " + shared("data/parts/prusa_plug-aligner.stl") + " --json " + json.string());
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("Concave regions"), std::string::npos);
  EXPECT_NE(r.out.find("LVM(S + N_S)"), std::string::npos);
  gvm::v1::Analysis a = parse(read_file(json));
  EXPECT_EQ(a.part().input_faces(), 48u);
  EXPECT_GT(a.features_size(), 0);
  // The field names other tools read are fixed.
  std::string text = read_file(json);
  for (const char* key : {"\"regions\"", "\"features\"", "\"faces\"", "\"lvm\"", "\"fullSphere\""}) {
    EXPECT_NE(text.find(key), std::string::npos) << key;
  }
  // Every face belongs to exactly one feature.
  std::vector<int> seen(a.part().input_faces(), 0);
  for (const auto& f : a.features()) {
    for (uint32_t face : f.faces()) ++seen.at(face);
  }
  for (int count : seen) EXPECT_EQ(count, 1);
  // The global occlusion is computed by default: every surface has its exact GVM.
  for (const auto& f : a.features()) {
    EXPECT_NE(f.info().gvm_status(), gvm::v1::GVM_STATUS_GLOBAL_OCCLUSION_NOT_COMPUTED) << f.name();
    EXPECT_TRUE(f.has_gvm()) << f.name();
  }
  for (const auto& g : a.regions()) EXPECT_TRUE(g.has_gvm()) << g.id();
}

TEST(Cli, LvmOnlyLeavesTheGlobalOcclusionOut) {
  const fs::path& dir = gvm::test::scratch_dir();
  fs::path json = dir / "plug-lvm.json";
  CliRun r = run("analyze " + shared("data/parts/prusa_plug-aligner.stl") + " --lvm-only --json " +
                 json.string());
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("--lvm-only"), std::string::npos) << r.out;
  gvm::v1::Analysis a = parse(read_file(json));
  int not_computed = 0;
  for (const auto& f : a.features()) {
    const bool occluders = f.info().potential_occluders() > 0;
    if (f.info().gvm_status() == gvm::v1::GVM_STATUS_EMPTY_VOID) continue;
    EXPECT_EQ(f.info().gvm_status() == gvm::v1::GVM_STATUS_GLOBAL_OCCLUSION_NOT_COMPUTED, occluders)
        << f.name();
    EXPECT_EQ(f.has_gvm(), !occluders) << f.name();
    not_computed += occluders;
  }
  EXPECT_GT(not_computed, 0);
}

TEST(Cli, SameJsonWithOneAndTwoThreads) {
  const fs::path& dir = gvm::test::scratch_dir();
  std::string part = shared("data/parts/trimesh_20mm-xyz-cube.stl");
  ASSERT_EQ(run("analyze " + part + " -q --threads 1 --json " + (dir / "t1.json").string()).status, 0);
  ASSERT_EQ(run("analyze " + part + " -q --threads 2 --json " + (dir / "t2.json").string()).status, 0);
  gvm::v1::Analysis a = parse(read_file(dir / "t1.json"));
  gvm::v1::Analysis b = parse(read_file(dir / "t2.json"));
  // Timings are the only fields allowed to differ.
  for (gvm::v1::Analysis* x : {&a, &b}) {
    x->clear_timing();
    for (auto& r : *x->mutable_regions()) r.mutable_info()->clear_seconds();
    for (auto& f : *x->mutable_features()) f.mutable_info()->clear_seconds();
  }
  EXPECT_TRUE(google::protobuf::util::MessageDifferencer::Equals(a, b));
  EXPECT_GT(a.features_size(), 1);
}

}  // namespace

namespace {

// A report that cannot be written is refused before the part is even read: the missing
// part is not what the message is about.
TEST(Cli, AnUnwritableReportIsRefusedBeforeAnyWork) {
  for (const char* command : {"analyze", "plan"}) {
    CliRun r = run(std::string(command) + " /nonexistent/part.stl --report /nonexistent-dir/r.html");
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_NE(r.out.find("/nonexistent-dir"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("part.stl"), std::string::npos) << r.out;
  }
  const fs::path& dir = gvm::test::scratch_dir();
  CliRun into_dir = run("plan " + shared("data/parts/prusa_plug-aligner.stl") + " --report " + dir.string());
  EXPECT_EQ(into_dir.status, 2);
  EXPECT_NE(into_dir.out.find("is a directory"), std::string::npos) << into_dir.out;
  CliRun several = run("plan a.stl b.stl --server unix:/nonexistent.sock --report " + (dir / "r.html").string());
  EXPECT_EQ(several.status, 2);
  EXPECT_NE(several.out.find("--report"), std::string::npos) << several.out;
}

TEST(Cli, ReportsAreWrittenForPlansAndAnalyses) {
  const fs::path& dir = gvm::test::scratch_dir();
  for (const char* command : {"analyze", "plan"}) {
    const fs::path html = dir / (std::string(command) + ".html");
    CliRun r = run(std::string(command) + " " + shared("data/parts/prusa_plug-aligner.stl") + " -q --report " +
                   html.string());
    ASSERT_EQ(r.status, 0) << r.out;
    const std::string text = read_file(html);
    EXPECT_EQ(text.rfind("<!DOCTYPE html>", 0), 0u);
    EXPECT_NE(text.find("id=\"gvm-report-data\""), std::string::npos);
    EXPECT_NE(text.find("<figure class=\"snapshot\""), std::string::npos);
    EXPECT_EQ(text.find("\"plan\":") != std::string::npos, std::string(command) == "plan");
  }
}

}  // namespace
