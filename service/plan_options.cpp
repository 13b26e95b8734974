#include "plan_options.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <map>
#include <sstream>

#include "cli_common.h"

namespace gvm::cli {
namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string part; std::getline(in, part, sep);) out.push_back(part);
  if (!s.empty() && s.back() == sep) out.push_back("");
  return out;
}

// Exactly N numbers separated by `sep`.
template <size_t N>
bool parse_numbers(const std::string& text, char sep, double (&v)[N]) {
  const std::vector<std::string> f = split(text, sep);
  if (f.size() != N) return false;
  for (size_t i = 0; i < N; ++i) {
    if (!parse_number(f[i], v[i])) return false;
  }
  return true;
}

bool parse_head(const std::string& text, v1::ProbeHead* head) {
  double v[5];
  if (!parse_numbers(text, ':', v)) return false;
  head->set_a_min_degrees(v[0]);
  head->set_a_max_degrees(v[1]);
  head->set_b_min_degrees(v[2]);
  head->set_b_max_degrees(v[3]);
  head->set_step_degrees(v[4]);
  return true;
}

// "+z", "-x", "y" or "X,Y,Z".
bool parse_axis(const std::string& text, v1::Vec3* out) {
  std::string t = text;
  double sign = 1;
  if (!t.empty() && (t[0] == '+' || t[0] == '-') && t.size() == 2) {
    sign = t[0] == '-' ? -1 : 1;
    t = t.substr(1);
  }
  if (t == "x" || t == "y" || t == "z") {
    out->set_x(t == "x" ? sign : 0);
    out->set_y(t == "y" ? sign : 0);
    out->set_z(t == "z" ? sign : 0);
    return true;
  }
  double v[3];
  if (!parse_numbers(text, ',', v)) return false;
  out->set_x(v[0]);
  out->set_y(v[1]);
  out->set_z(v[2]);
  return true;
}

// A number that is finite, read as every number of gvm (see add_value).
bool finite_number(const std::string& text, double& out) { return parse_number(text, out) && std::isfinite(out); }

bool read_mode(const std::string& text, v1::PlanOptions& o) {
  static const std::map<std::string, v1::PlanMode> kModes = {
      {"setup", v1::PLAN_MODE_SETUP}, {"rotary", v1::PLAN_MODE_ROTARY}, {"probe", v1::PLAN_MODE_PROBE}};
  const auto it = kModes.find(text);
  if (it != kModes.end()) o.set_mode(it->second);
  return it != kModes.end();
}

bool read_surfaces(const std::string& text, v1::PlanOptions& o) {
  if (text != "features" && text != "regions") return false;
  o.set_surfaces(text == "features" ? v1::PLAN_SURFACES_FEATURES : v1::PLAN_SURFACES_REGIONS);
  return true;
}

// "1e-6" or "1e-6rad" in radians, "0.001deg" in degrees.
bool parse_angle_radians(const std::string& text, double& out) {
  std::string number = text;
  double scale = 1;
  for (const auto& [suffix, factor] : {std::pair<std::string, double>{"deg", M_PI / 180}, {"rad", 1.0}}) {
    if (number.size() > suffix.size() && number.compare(number.size() - suffix.size(), suffix.size(), suffix) == 0) {
      number.resize(number.size() - suffix.size());
      scale = factor;
      break;
    }
  }
  if (!finite_number(number, out)) return false;
  out *= scale;
  return true;
}

// Adds a finite number option whose value `set` stores; the planner checks its range.
void add_finite(CLI::App& plan, const std::string& name, const std::string& meta, const std::string& needs,
                std::function<void(double)> set) {
  add_value(plan, name, meta, needs, [set = std::move(set)](const std::string& v) {
    double x = 0;
    if (!finite_number(v, x)) return false;
    set(x);
    return true;
  });
}

// What is planned, and how: every mode.
void add_plan_choices(CLI::App& plan, v1::PlanOptions& o) {
  add_value(plan, "--mode", "M", "setup, rotary or probe", [&o](const std::string& v) { return read_mode(v, o); });
  add_value(plan, "--surfaces", "S", "features or regions", [&o](const std::string& v) { return read_surfaces(v, o); });
  plan.add_flag_callback("--concave-only", [&o] { o.set_concave_only(true); });
  plan.add_flag_callback("--planar-normal", [&o] { o.set_planar_normal(true); });
  plan.add_flag_callback("--split", [&o] { o.set_split(true); });
  plan.add_flag_callback("--no-split", [&o] { o.set_no_split(true); });
  add_value(plan, "--split-max-faces", "N", "a whole number of faces (0: no limit)", [&o](const std::string& v) {
    double x = 0;
    if (!finite_number(v, x) || x < 0 || x > 4294967295.0 || x != std::floor(x)) return false;
    o.set_split_max_faces(static_cast<uint32_t>(x));
    return true;
  });
  add_value(plan, "--tolerance", "ANGLE", "an angle in radians, or in degrees with 'deg' (1e-6, 0.001deg)",
            [&o](const std::string& v) {
              double x = 0;
              if (!parse_angle_radians(v, x)) return false;
              o.set_tolerance_radians(x);
              return true;
            });
  add_finite(plan, "--time-limit", "SEC", "a number of seconds", [&o](double x) { o.set_time_limit_seconds(x); });
  add_finite(plan, "--min-clearance", "DEG", "an angle in degrees", [&o](double x) { o.set_min_clearance_degrees(x); });
}

// The probe head and the part on it: probe mode (the planner says so when they are given
// in another mode).
void add_probe_options(CLI::App& plan, v1::PlanOptions& o) {
  add_value(plan, "--head", "A0:A1:B0:B1:S", "A_MIN:A_MAX:B_MIN:B_MAX:STEP in degrees, e.g. 0:105:-180:180:7.5",
            [&o](const std::string& v) { return parse_head(v, o.mutable_head()); });
  add_value(plan, "--part-up", "AXIS", "an axis (+x, -y, z, ...) or a vector X,Y,Z",
            [&o](const std::string& v) { return parse_axis(v, o.mutable_part_up()); });
  add_finite(plan, "--cone", "DEG", "an angle in degrees", [&o](double x) { o.set_cone_degrees(x); });
}

}  // namespace

void add_plan_options(CLI::App& plan, v1::PlanOptions& o) {
  add_plan_choices(plan, o);
  add_probe_options(plan, o);
}

std::string with_flag_names(const std::string& message) {
  static const std::pair<const char*, const char*> kFlags[] = {
      {"head", "--head"}, {"part_up", "--part-up"}, {"cone_degrees", "--cone"},
      {"min_clearance_degrees", "--min-clearance"}, {"time_limit_seconds", "--time-limit"},
      {"threads", "--threads"}, {"mode", "--mode"}, {"tolerance_radians", "--tolerance"}};
  for (const auto& [field, flag] : kFlags) {
    if (message.rfind(field, 0) == 0) return std::string(flag) + " (" + field + ")" + message.substr(std::string(field).size());
  }
  return message;
}


}  // namespace gvm::cli
