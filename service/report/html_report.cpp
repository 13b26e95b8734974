#include "html_report.h"

#include <google/protobuf/util/json_util.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "base64.h"
#include "escape.h"
#include "face_classes.h"
#include "png.h"
#include "report_assets.h"
#include "setup_views.h"

namespace gvm::report {
namespace {

namespace fs = std::filesystem;

std::string message_json(const google::protobuf::Message& message) {
  google::protobuf::util::JsonPrintOptions options;
  options.always_print_primitive_fields = true;
  std::string out;
  (void)google::protobuf::util::MessageToJsonString(message, &out, options);
  return out;
}

// Typed arrays go to the page as their bytes (little-endian, as every platform we build
// for), zlib-compressed and base64: a fifth of the size of JSON numbers and no parsing (the
// 190k-triangle part's mesh: 7.6 MB of base64 uncompressed, 2.5 MB so).
template <class T>
std::string array_base64(const std::vector<T>& v) {
  return json_string(base64(zlib_deflate({reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T)})));
}

std::string mesh_json(const SolidMesh& mesh, const FaceClasses& classes) {
  std::vector<float> positions;
  positions.reserve(3 * mesh.points.size());
  for (const Point3& p : mesh.points) positions.insert(positions.end(), {float(p.x), float(p.y), float(p.z)});
  std::vector<uint32_t> triangles;
  triangles.reserve(3 * mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) triangles.insert(triangles.end(), t.begin(), t.end());
  return "{\"positions\":" + array_base64(positions) + ",\"triangles\":" + array_base64(triangles) +
         ",\"triangleFace\":" + array_base64(mesh.triangle_face) + ",\"faceClass\":" +
         array_base64(classes.face_class) + ",\"faceSurface\":" + array_base64(classes.face_surface) + "}";
}

std::string classes_json(const FaceClasses& classes) {
  std::string out = "[";
  for (const FaceClass& c : classes.classes) {
    if (out.size() > 1) out += ",";
    out += "{\"label\":" + json_string(c.label) + ",\"color\":" + json_string(c.color) +
           ",\"faded\":" + json_string(faded(c.color));
    if (c.setup) out += ",\"setup\":" + std::to_string(*c.setup);
    out += "}";
  }
  out += "],\"surfaceClass\":[";
  for (size_t i = 0; i < classes.surface_class.size(); ++i) {
    if (i) out += ',';
    out += std::to_string(classes.surface_class[i]);
  }
  return out + "]";
}

// Inside <script> the text must never hold "</": every "<" is written as its JSON escape
// (only strings can contain one).
std::string script_safe(const std::string& json) {
  std::string out;
  out.reserve(json.size());
  for (char c : json) {
    if (c == '<') out += "\\u003c";
    else out += c;
  }
  return out;
}

std::string title_of(const char* kind, const v1::PartSummary& part) {
  return std::string(kind) + ": " + fs::path(part.source()).filename().string();
}

struct Page {
  std::string title, data, snapshots;  // title HTML-escaped
};

// One pass over the template, so that no inserted text is ever read as a placeholder.
std::string fill(const Page& page) {
  const std::pair<std::string_view, std::string_view> values[] = {
      {"@GVM_TITLE@", page.title}, {"@GVM_STYLE@", page_style()}, {"@GVM_SNAPSHOTS@", page.snapshots},
      {"@GVM_DATA@", page.data}, {"@GVM_SCRIPT@", page_script()}};
  const std::string_view in = page_template();
  std::string html;
  html.reserve(in.size() + page.data.size() + page.snapshots.size() + page_script().size());
  size_t at = 0;
  for (size_t next = in.find("@GVM_"); next != std::string_view::npos; next = in.find("@GVM_", at)) {
    html += in.substr(at, next - at);
    at = next + 1;
    for (const auto& [key, value] : values) {
      if (in.substr(next, key.size()) == key) {
        html += value;
        at = next + key.size();
        break;
      }
    }
    if (at == next + 1) html += '@';
  }
  return html += in.substr(at);
}

std::string data_json(const std::string& title, const SolidMesh& mesh, const FaceClasses& classes,
                      const v1::Analysis& analysis, const v1::Plan* plan) {
  std::string out = "{\"title\":" + json_string(title) + ",\"classes\":" + classes_json(classes) +
                    ",\"mesh\":" + mesh_json(mesh, classes) + ",\"analysis\":" + message_json(analysis);
  if (plan) out += ",\"plan\":" + message_json(*plan);
  return script_safe(out + "}");
}

std::array<double, 3> xyz(const v1::Vec3& v) { return {v.x(), v.y(), v.z()}; }

std::string direction_text(const v1::Vec3& v) {
  char out[96];
  std::snprintf(out, sizeof out, "(%.4g, %.4g, %.4g)", v.x(), v.y(), v.z());
  return out;
}

std::vector<StaticView> plan_views(const v1::Plan& plan) {
  std::vector<StaticView> views;
  const bool rotary = plan.mode() == v1::PLAN_MODE_ROTARY;
  for (int i = 0; i < plan.setups_size(); ++i) {
    const v1::Vec3& d = plan.setups(i).direction();
    const std::string what = rotary ? "along rotary axis " : "u = ";
    views.push_back({(rotary ? "Axis " : "Setup ") + std::to_string(i + 1) + ", " + what + direction_text(d), xyz(d),
                     i, static_cast<uint32_t>(i)});
  }
  return views;
}

std::vector<StaticView> axis_views() {
  return {{"From +z", {0, 0, 1}, {}, {}}, {"From -z", {0, 0, -1}, {}, {}}, {"From +x", {1, 0, 0}, {}, {}},
          {"From -x", {-1, 0, 0}, {}, {}}, {"From +y", {0, 1, 0}, {}, {}}, {"From -y", {0, -1, 0}, {}, {}}};
}

}  // namespace

Status check_report_path(const std::string& path) {
  std::error_code ec;
  const fs::path p(path);
  if (path.empty()) return InvalidArgument("--report needs a file name");
  if (fs::is_directory(p, ec)) return InvalidArgument("cannot write the report to '" + path + "': it is a directory");
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec)) {
    return InvalidArgument("cannot write the report to '" + path + "': no directory '" + dir.string() + "'");
  }
  // The report is written through a temporary file beside it: try that file now.
  const std::string probe = path + ".tmp";
  const bool existed = fs::exists(probe, ec);
  if (!std::ofstream(probe, std::ios::app)) {
    return InvalidArgument("cannot write the report to '" + path + "': the directory '" + dir.string() +
                           "' does not take new files (permissions?)");
  }
  if (!existed) fs::remove(probe, ec);
  return Status::Ok();
}

std::string plan_report(const SolidMesh& mesh, const v1::Analysis& analysis, const v1::Plan& plan) {
  const FaceClasses classes = plan_classes(analysis, plan, mesh.input_face_count);
  const std::string title = title_of("Plan", analysis.part());
  return fill({html_escape(title), data_json(title, mesh, classes, analysis, &plan), static_views(mesh, classes, plan_views(plan))});
}

std::string analysis_report(const SolidMesh& mesh, const v1::Analysis& analysis) {
  const FaceClasses classes = analysis_classes(analysis, mesh.input_face_count);
  const std::string title = title_of("Analysis", analysis.part());
  return fill({html_escape(title), data_json(title, mesh, classes, analysis, nullptr), static_views(mesh, classes, axis_views())});
}

}  // namespace gvm::report
