// The pieces of a batch's manifest that a user writes by hand: CSV cells and option
// columns, read exactly as a spreadsheet writes them.
#include <gtest/gtest.h>

#include "batch/csv.h"
#include "batch/option_fields.h"

namespace gvm::batch {
namespace {

TEST(BatchCsv, QuotedCellsKeepCommasQuotesAndLineBreaks) {
  auto rows = parse_csv("part,name\r\n\"a,b.stl\",\"say \"\"hi\"\"\"\n\n\"two\nlines.stl\",x\n");
  ASSERT_TRUE(rows.ok()) << rows.status().message();
  ASSERT_EQ(rows->size(), 3u);
  EXPECT_EQ((*rows)[1].cells, (std::vector<std::string>{"a,b.stl", "say \"hi\""}));
  EXPECT_EQ((*rows)[1].line, 2);
  EXPECT_EQ((*rows)[2].cells, (std::vector<std::string>{"two\nlines.stl", "x"}));
  EXPECT_EQ((*rows)[2].line, 4);  // the blank line 3 skipped
  for (const std::string cell : {"plain", "a,b", "say \"hi\"", "two\nlines", ""}) {
    auto back = parse_csv("h\n" + csv_cell(cell) + ",end\n");
    ASSERT_TRUE(back.ok());
    EXPECT_EQ((*back)[1].cells[0], cell);
  }
}

TEST(BatchCsv, BrokenQuotesNameTheirLine) {
  auto open = parse_csv("part\nx.stl\n\"y.stl\n");
  ASSERT_FALSE(open.ok());
  EXPECT_EQ(open.status().message(), "manifest line 3: a quote is never closed");
  auto after = parse_csv("part\n\"x.stl\"y\n");
  ASSERT_FALSE(after.ok());
  EXPECT_EQ(after.status().message(), "manifest line 2: text after a closing quote");
}

TEST(BatchColumns, OptionsOfEitherMessageByTheirProtoNames) {
  v1::BatchPart part;
  ASSERT_TRUE(set_column(part, "mode", "probe").ok());
  ASSERT_TRUE(set_column(part, "surfaces", "PLAN_SURFACES_REGIONS").ok());
  ASSERT_TRUE(set_column(part, "cone_degrees", "2.5").ok());
  ASSERT_TRUE(set_column(part, "head.step_degrees", "15").ok());
  ASSERT_TRUE(set_column(part, "concave_only", "1").ok());
  ASSERT_TRUE(set_column(part, "step.solid", "0").ok());
  ASSERT_TRUE(set_column(part, "feature_angle_degrees", "40").ok());
  EXPECT_EQ(part.plan().mode(), v1::PLAN_MODE_PROBE);
  EXPECT_EQ(part.plan().surfaces(), v1::PLAN_SURFACES_REGIONS);
  EXPECT_EQ(part.plan().cone_degrees(), 2.5);
  EXPECT_EQ(part.plan().head().step_degrees(), 15);
  EXPECT_TRUE(part.plan().concave_only());
  EXPECT_TRUE(part.analyze().step().has_solid());  // 0 is set, not absent
  EXPECT_EQ(part.analyze().feature_angle_degrees(), 40);
}

TEST(BatchColumns, WrongColumnsSayWhatTheyNeed) {
  v1::BatchPart part;
  auto message = [&](const std::string& column, const std::string& value) {
    return std::string(set_column(part, column, value).message());
  };
  EXPECT_EQ(message("mode", "drill"),
            "column 'mode' needs one of PLAN_MODE_SETUP, PLAN_MODE_ROTARY, PLAN_MODE_PROBE (not 'drill')");
  EXPECT_EQ(message("cone_degrees", "5deg"), "column 'cone_degrees' needs a finite number (not '5deg')");
  EXPECT_EQ(message("cone_degrees", "inf"), "column 'cone_degrees' needs a finite number (not 'inf')");
  EXPECT_EQ(message("step.solid", "-1"), "column 'step.solid' needs a whole number >= 0 (not '-1')");
  EXPECT_EQ(message("split", "yes"), "column 'split' needs true or false (not 'yes')");
  EXPECT_EQ(message("head", "1"), "column 'head' needs one of its fields named, e.g. 'head.a_min_degrees' (not '1')");
  EXPECT_EQ(message("threads", "4"), "column 'threads': the threads are the batch's (--threads), not a part's");
  EXPECT_NE(message("colour", "red").find("neither part, groups, name nor a field"), std::string::npos);
}

}  // namespace
}  // namespace gvm::batch
