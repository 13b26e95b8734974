// The HTML report as a file: self-contained, its data the very messages it was made from,
// every face coloured by the setup the plan gives it, names that cannot break the page, and
// an unwritable path refused before any work. (What the page shows in a browser:
// tests/report/report_browser_test.mjs.)
#include <google/protobuf/struct.pb.h>
#include <google/protobuf/util/json_util.h>
#include <google/protobuf/util/message_differencer.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "gvm/analysis.h"
#include "gvm/analysis_proto.h"
#include "gvm/planner/plan.h"
#include "report/face_classes.h"
#include "report/html_report.h"
#include "support/mesh_files.h"
#include "support/scratch_dir.h"
#include "support/test_parts.h"

namespace gvm {
namespace {

struct Planned {
  Analysis analysis;
  v1::Analysis analysis_message;
  v1::Plan plan;
};

Planned planned(RawMesh raw, const std::string& file, v1::PlanOptions options = {}) {
  AnalyzeRequest request;
  request.part_path = test::write_obj(raw, test::scratch_dir() / file);
  auto a = analyze(request);
  EXPECT_TRUE(a.ok()) << a.status().message();
  auto p = planner::plan(*a, options);
  EXPECT_TRUE(p.ok()) << p.status().message();
  const v1::Analysis message = to_proto(*a);
  return {std::move(*a), message, p->message};
}

std::string decode_base64(const std::string& text) {
  static const std::string kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  uint32_t bits = 0;
  int count = 0;
  for (char c : text) {
    if (c == '=') break;
    bits = (bits << 6) | static_cast<uint32_t>(kAlphabet.find(c));
    if ((count += 6) >= 8) out += static_cast<char>((bits >> (count -= 8)) & 0xff);
  }
  return out;
}

// The page inflates the arrays with DecompressionStream("deflate"): a zlib stream.
std::string inflate(const std::string& zlib) {
  std::string out(64 << 20, '\0');
  uLongf size = out.size();
  EXPECT_EQ(uncompress(reinterpret_cast<Bytef*>(out.data()), &size, reinterpret_cast<const Bytef*>(zlib.data()),
                       zlib.size()), Z_OK);
  out.resize(size);
  return out;
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The page's data block, parsed as generic JSON.
google::protobuf::Struct page_data(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"gvm-report-data\">";
  const size_t begin = html.find(open) + open.size();
  const size_t end = html.find("</script>", begin);
  google::protobuf::Struct data;
  EXPECT_TRUE(google::protobuf::util::JsonStringToMessage(html.substr(begin, end - begin), &data).ok());
  return data;
}

template <class Message>
Message field_as(const google::protobuf::Struct& data, const std::string& name) {
  std::string json;
  (void)google::protobuf::util::MessageToJsonString(data.fields().at(name), &json);
  Message m;
  EXPECT_TRUE(google::protobuf::util::JsonStringToMessage(json, &m).ok()) << name;
  return m;
}

TEST(HtmlReport, IsOneSelfContainedFileCarryingThePlanItWasMadeFrom) {
  const Planned p = planned(test::slot_part(), "slot.obj");
  const std::string html = report::plan_report(p.analysis.mesh(), p.analysis_message, p.plan);
  EXPECT_EQ(count(html, "<script"), 2u);               // the data and the bundled script
  EXPECT_EQ(count(html, "</script>"), 2u);
  EXPECT_EQ(count(html, "<script src"), 0u);
  EXPECT_EQ(count(html, "<link"), 0u);
  EXPECT_EQ(count(html, "@GVM_"), 0u);
  EXPECT_EQ(count(html, "<figure class=\"snapshot\" data-setup="), static_cast<size_t>(p.plan.setups_size()));
  EXPECT_EQ(count(html, "src=\"data:image/png;base64,iVBORw0KGgo"), static_cast<size_t>(p.plan.setups_size()));

  const google::protobuf::Struct data = page_data(html);
  EXPECT_TRUE(google::protobuf::util::MessageDifferencer::Equals(field_as<v1::Plan>(data, "plan"), p.plan));
  EXPECT_TRUE(google::protobuf::util::MessageDifferencer::Equals(field_as<v1::Analysis>(data, "analysis"),
                                                                 p.analysis_message));
  // The typed arrays hold the whole mesh, 4 bytes a value.
  const auto& mesh = data.fields().at("mesh").struct_value().fields();
  auto bytes = [&](const char* name) { return inflate(decode_base64(mesh.at(name).string_value())).size(); };
  const SolidMesh& solid = p.analysis.mesh();
  EXPECT_EQ(bytes("positions"), 12 * solid.points.size());
  EXPECT_EQ(bytes("triangles"), 12 * solid.triangles.size());
  EXPECT_EQ(bytes("triangleFace"), 4 * solid.triangles.size());
  EXPECT_EQ(bytes("faceClass"), 4 * solid.input_face_count);
  EXPECT_EQ(bytes("faceSurface"), 4 * solid.input_face_count);
}

// Every face is in the class of the setup its feature is planned in, checked against the
// plan itself; classes no face uses are not in the legend.
TEST(HtmlReport, EveryFaceHasTheColourOfItsSetup) {
  const Planned p = planned(test::through_hole_part(), "hole.obj");
  const uint32_t faces = p.analysis.mesh().input_face_count;
  const report::FaceClasses c = report::plan_classes(p.analysis_message, p.plan, faces);
  ASSERT_EQ(c.face_class.size(), faces);
  ASSERT_GE(p.plan.setups_size(), 2);
  std::set<int32_t> used(c.face_class.begin(), c.face_class.end());
  EXPECT_EQ(used.size(), c.classes.size());
  std::set<std::string> colours;
  for (const v1::PlannedSurface& s : p.plan.surfaces()) {
    const v1::Feature& f = p.analysis_message.features(s.id());
    for (uint32_t face : f.faces()) {
      const report::FaceClass& k = c.classes[c.face_class[face]];
      if (s.setup() >= 0) {
        ASSERT_TRUE(k.setup.has_value()) << "face " << face;
        EXPECT_EQ(*k.setup, static_cast<uint32_t>(s.setup())) << "face " << face;
        colours.insert(k.color);
      } else {
        EXPECT_EQ(k.label, "unreachable") << "face " << face;
      }
      EXPECT_EQ(c.face_surface[face], static_cast<int32_t>(s.id()));
    }
    EXPECT_EQ(c.surface_class[s.id()], c.face_class[f.faces(0)]);
  }
  EXPECT_EQ(colours.size(), static_cast<size_t>(p.plan.setups_size()));
}

// A feature name is the user's text: it must neither end a script nor be read as a
// placeholder of the page.
TEST(HtmlReport, NamesCannotBreakThePage) {
  RawMesh raw = test::slot_part();
  auto group = raw.groups.begin();
  raw.groups["</script><script>alert(1)</script>@GVM_SCRIPT@"] = group->second;
  raw.groups.erase(group);
  const Planned p = planned(raw, "names.obj");
  const std::string html = report::plan_report(p.analysis.mesh(), p.analysis_message, p.plan);
  EXPECT_EQ(count(html, "</script>"), 2u);
  // In the data (analysis and plan), escaped every time, never as a script.
  EXPECT_GE(count(html, "alert(1)"), 1u);
  EXPECT_EQ(count(html, "<script>alert"), 0u);
  const google::protobuf::Struct data = page_data(html);
  bool found = false;
  const v1::Analysis analysis = field_as<v1::Analysis>(data, "analysis");
  for (const v1::Feature& f : analysis.features()) {
    found |= f.name() == "</script><script>alert(1)</script>@GVM_SCRIPT@";
  }
  EXPECT_TRUE(found) << "the name arrives intact";
}

TEST(HtmlReport, AnUnwritablePathIsRefusedNamingWhy) {
  namespace fs = std::filesystem;
  const fs::path dir = test::scratch_dir();
  const Status missing = report::check_report_path((dir / "no-such-dir" / "r.html").string());
  EXPECT_FALSE(missing.ok());
  EXPECT_NE(missing.message().find("no-such-dir"), std::string::npos) << missing.message();
  const Status directory = report::check_report_path(dir.string());
  EXPECT_FALSE(directory.ok());
  EXPECT_NE(directory.message().find("is a directory"), std::string::npos) << directory.message();
  const fs::path good = dir / "r.html";
  EXPECT_TRUE(report::check_report_path(good.string()).ok());
  EXPECT_FALSE(fs::exists(good));
  EXPECT_FALSE(fs::exists(good.string() + ".tmp"));
}

TEST(HtmlReport, AnalysisReportShowsSixStaticViews) {
  const Planned p = planned(test::through_hole_part(), "hole-analysis.obj");
  const std::string html = report::analysis_report(p.analysis.mesh(), p.analysis_message);
  EXPECT_EQ(count(html, "<figure class=\"snapshot\""), 6u);
  EXPECT_EQ(page_data(html).fields().count("plan"), 0u);
}

}  // namespace
}  // namespace gvm
