// `gvm plan` as a user runs it: the report, the JSON other tools read, and bad input.
#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "gvm/v1/plan.pb.h"
#include "support/assertions.h"
#include "support/cli.h"
#include "support/scratch_dir.h"

namespace gvm {
namespace {

namespace fs = std::filesystem;
using test::Has;
using test::run_cli;
using test::shared;

v1::Plan parse_plan(const std::string& json) {
  v1::Plan p;
  auto status = google::protobuf::util::JsonStringToMessage(json, &p);
  EXPECT_TRUE(status.ok()) << status.ToString();
  return p;
}

TEST(CliPlan, HelpListsThePlanOptions) {
  const test::CliRun r = run_cli("plan --help");
  EXPECT_EQ(r.status, 0);
  for (const char* word : {"--mode", "setup", "rotary", "probe", "--surfaces", "--concave-only", "--planar-normal",
                           "--split", "--time-limit", "--min-clearance", "--head", "--part-up", "--cone"}) {
    EXPECT_TRUE(Has(r.out, word));
  }
}

TEST(CliPlan, ReportAndJsonOnARealPart) {
  const fs::path json = test::scratch_dir() / "endstop-plan.json";
  const test::CliRun r = run_cli("plan " + shared("data/parts/prusa_endstop-block.stl") + " --json " + json.string());
  ASSERT_EQ(r.status, 0) << r.out;
  for (const char* word : {"Setups:", "Optimality:", "Unreachable features:", "clearance"}) {
    EXPECT_TRUE(Has(r.out, word));
  }
  const std::string text = test::read_file(json);
  // The field names other tools read are fixed.
  for (const char* key : {"\"setups\"", "\"direction\"", "\"features\"", "\"clearanceDegrees\"", "\"unreachable\"",
                          "\"lowerBound\"", "\"optimal\"", "\"mode\""}) {
    EXPECT_TRUE(Has(text, key));
  }
  const v1::Plan p = parse_plan(text);
  EXPECT_EQ(p.mode(), v1::PLAN_MODE_SETUP);
  EXPECT_GT(p.setups_size(), 0);
  EXPECT_LE(p.lower_bound(), uint32_t(p.setups_size()));
  EXPECT_EQ(p.reached() + p.unreachable_count(), uint32_t(p.surfaces_size()));
  // Every feature is in one setup or listed unreachable, never dropped.
  std::vector<int> seen(p.surfaces_size(), 0);
  for (const auto& s : p.setups()) {
    for (uint32_t id : s.features()) ++seen.at(id);
  }
  for (const auto& u : p.unreachable()) ++seen.at(u.feature());
  for (int count : seen) EXPECT_EQ(count, 1);
}

TEST(CliPlan, JsonToStandardOutputIsTheWholeOutput) {
  const test::CliRun r = run_cli("plan " + shared("data/parts/prusa_plug-aligner.stl") + " --json -");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_GT(parse_plan(r.out).setups_size(), 0);
}

TEST(CliPlan, BadOptionsAreUsageErrorsNamingTheOption) {
  const std::string part = shared("data/parts/prusa_plug-aligner.stl");
  const fs::path json = test::scratch_dir() / "never.json";
  const std::string out = " --json " + json.string();
  struct Case {
    std::string args, says;
  };
  for (const Case& c : {Case{"--mode frobnicate", "--mode"}, Case{"--mode probe --head 0:105:-180", "--head"},
                        Case{"--mode probe --head 0:105:-180:180:0", "step"},
                        Case{"--mode probe --head 90:10:-180:180:5", "A range"},
                        Case{"--mode probe --cone 95", "--cone"}, Case{"--cone 5", "probe mode only"},
                        Case{"--min-clearance 90", "--min-clearance"}, Case{"--time-limit -1", "--time-limit"},
                        Case{"--part-up w", "--part-up"}, Case{"--surfaces faces", "--surfaces"}}) {
    const test::CliRun r = run_cli("plan " + part + " " + c.args + out);
    EXPECT_EQ(r.status, 2) << c.args << ": " << r.out;
    EXPECT_TRUE(Has(r.out, c.says)) << c.args;
    EXPECT_FALSE(fs::exists(json)) << c.args;
  }
}

// CLI11 parses the command line: its errors name the option, values may look like options.
TEST(CliPlan, UnknownOptionsAndMissingValuesAreUsageErrorsNamingTheOption) {
  const std::string part = shared("data/parts/prusa_plug-aligner.stl");
  for (const char* option : {"--frobnicate", "--mode", "--head", "--analysis-json", "--time-limit"}) {
    const test::CliRun r = run_cli("plan " + part + " " + option);
    EXPECT_EQ(r.status, 2) << option << ": " << r.out;
    EXPECT_TRUE(Has(r.out, option)) << option;
  }
  EXPECT_EQ(run_cli("plan " + part + " --mode probe --part-up -z -q").status, 0);
  EXPECT_EQ(run_cli("plan " + part + " --mode=rotary -q").status, 0);
  EXPECT_EQ(run_cli("plan -h").status, 0);
}

TEST(CliPlan, BadPartsFailWithTheProblemNamedAndNothingWritten) {
  const fs::path json = test::scratch_dir() / "never.json";
  const fs::path empty = test::scratch_dir() / "empty.off";
  std::ofstream(empty) << "OFF\n0 0 0\n";
  const test::CliRun e = run_cli("plan " + empty.string() + " --json " + json.string());
  EXPECT_EQ(e.status, 1) << e.out;
  EXPECT_TRUE(Has(e.out, "empty.off"));
  const test::CliRun f = run_cli("plan " + shared("data/bad/prusa_endstop-block_FLIPPED.off") + " --json " + json.string());
  EXPECT_EQ(f.status, 1);
  EXPECT_TRUE(Has(f.out, "inward"));
  EXPECT_FALSE(fs::exists(json));
}

}  // namespace
}  // namespace gvm
