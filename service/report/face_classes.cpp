#include "face_classes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace gvm::report {
namespace {

// Setup colours: hues far apart in chromaticity (the browser test tells them apart by
// hue), none red (the warning colour) and none grey (neutral).
constexpr std::array<const char*, 8> kSetupColors = {"#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd",
                                                     "#17becf", "#bcbd22", "#e377c2", "#8c564b"};
constexpr const char* kUnreachable = "#d62728";
constexpr const char* kNeutral = "#c8c8c8";

std::string hex(double r, double g, double b) {
  char out[8];
  std::snprintf(out, sizeof out, "#%02x%02x%02x", static_cast<int>(std::lround(r * 255)),
                static_cast<int>(std::lround(g * 255)), static_cast<int>(std::lround(b * 255)));
  return out;
}

// Past the fixed palette: golden-angle hues at one saturation and value (colours may
// then come close; the labels still tell the setups apart).
std::string setup_color(uint32_t i) {
  if (i < kSetupColors.size()) return kSetupColors[i];
  const double h = std::fmod(30.0 + 137.508 * i, 300.0) + 30.0;  // stays out of red
  const double s = 0.6, v = 0.85, c = v * s, x = c * (1 - std::fabs(std::fmod(h / 60.0, 2.0) - 1)), m = v - c;
  const int k = static_cast<int>(h / 60.0) % 6;
  const double rgb[6][3] = {{c, x, 0}, {x, c, 0}, {0, c, x}, {0, x, c}, {x, 0, c}, {c, 0, x}};
  return hex(rgb[k][0] + m, rgb[k][1] + m, rgb[k][2] + m);
}

template <class Surfaces>
void assign_surfaces(const Surfaces& surfaces, FaceClasses& out) {
  for (const auto& s : surfaces) {
    for (uint32_t f : s.faces()) {
      if (f < out.face_surface.size()) out.face_surface[f] = static_cast<int32_t>(s.id());
    }
    if (out.surface_class.size() <= s.id()) out.surface_class.resize(s.id() + 1, -1);
  }
}

// Returns the new class's index.
int32_t add_class(FaceClasses& out, std::string label, std::string color, std::optional<uint32_t> setup = {}) {
  out.classes.push_back({std::move(label), std::move(color), setup});
  return static_cast<int32_t>(out.classes.size() - 1);
}

void paint(FaceClasses& out, const google::protobuf::RepeatedField<uint32_t>& faces, int32_t cls) {
  for (uint32_t f : faces) {
    if (f < out.face_class.size()) out.face_class[f] = cls;
  }
}

// Drops classes no face and no surface uses, renumbering the rest.
void drop_unused(FaceClasses& out, size_t keep_first) {
  std::vector<bool> used(out.classes.size(), false);
  for (size_t i = 0; i < keep_first; ++i) used[i] = true;
  for (int32_t c : out.face_class) used[c] = true;
  for (int32_t c : out.surface_class) {
    if (c >= 0) used[c] = true;
  }
  std::vector<int32_t> renumber(out.classes.size(), -1);
  std::vector<FaceClass> kept;
  for (size_t i = 0; i < out.classes.size(); ++i) {
    if (!used[i]) continue;
    renumber[i] = static_cast<int32_t>(kept.size());
    kept.push_back(std::move(out.classes[i]));
  }
  out.classes = std::move(kept);
  for (int32_t& c : out.face_class) c = renumber[c];
  for (int32_t& c : out.surface_class) c = c >= 0 ? renumber[c] : c;
}

std::string setup_word(v1::PlanMode mode) {
  if (mode == v1::PLAN_MODE_ROTARY) return "axis";
  if (mode == v1::PLAN_MODE_PROBE) return "orientation";
  return "setup";
}

template <class Surfaces>
void paint_plan(const Surfaces& surfaces, const v1::Plan& plan, int32_t unreachable, FaceClasses& out) {
  std::vector<uint32_t> unreached;
  for (const v1::Unreachable& u : plan.unreachable()) unreached.push_back(u.feature());
  for (const v1::PlannedSurface& p : plan.surfaces()) {
    // A surface reached piece by piece takes its first piece's setup (its faces are
    // painted piece by piece below).
    const bool by_pieces = p.has_pieces() && p.pieces().setups_size() > 0 &&
                           std::find(unreached.begin(), unreached.end(), p.id()) == unreached.end();
    const int32_t cls = p.setup() >= 0 ? p.setup() : by_pieces ? p.pieces().setups(0) : unreachable;
    if (p.id() < out.surface_class.size()) out.surface_class[p.id()] = cls;
    for (const auto& s : surfaces) {
      if (s.id() == p.id()) paint(out, s.faces(), cls);
    }
  }
  // Pieces of split features, each in its own setup.
  for (int i = 0; i < plan.setups_size(); ++i) {
    for (const v1::SetupFeature& r : plan.setups(i).reach()) paint(out, r.faces(), i);
  }
}

}  // namespace

Rgb rgb_of(const std::string& color) {
  const unsigned v = static_cast<unsigned>(std::stoul(color.substr(1), nullptr, 16));
  return {static_cast<uint8_t>(v >> 16), static_cast<uint8_t>(v >> 8), static_cast<uint8_t>(v)};
}

std::string faded(const std::string& color) {
  const Rgb c = rgb_of(color);
  auto f = [](uint8_t x) { return 0.78 + 0.22 * (x / 255.0); };
  return hex(f(c.r), f(c.g), f(c.b));
}

FaceClasses plan_classes(const v1::Analysis& analysis, const v1::Plan& plan, uint32_t input_faces) {
  FaceClasses out;
  out.face_class.assign(input_faces, 0);
  out.face_surface.assign(input_faces, -1);
  const bool regions = plan.surfaces_kind() == v1::PLAN_SURFACES_REGIONS;
  const std::string word = setup_word(plan.mode());
  for (int i = 0; i < plan.setups_size(); ++i) add_class(out, word + " " + std::to_string(i + 1), setup_color(i), i);
  const int32_t unreachable = add_class(out, "unreachable", kUnreachable);
  const int32_t neutral = add_class(out, regions ? "hull (not planned)" : "not planned", kNeutral);
  for (int32_t& c : out.face_class) c = neutral;
  if (regions) {
    assign_surfaces(analysis.regions(), out);
    paint_plan(analysis.regions(), plan, unreachable, out);
  } else {
    assign_surfaces(analysis.features(), out);
    paint_plan(analysis.features(), plan, unreachable, out);
  }
  for (int32_t& c : out.surface_class) c = c < 0 ? neutral : c;
  drop_unused(out, plan.setups_size());
  return out;
}

FaceClasses analysis_classes(const v1::Analysis& analysis, uint32_t input_faces) {
  FaceClasses out;
  out.face_class.assign(input_faces, 0);
  out.face_surface.assign(input_faces, -1);
  const int32_t open = add_class(out, "GVM with open directions", "#2ca02c");
  const int32_t arcs = add_class(out, "GVM arcs only (exact alignment)", "#1f77b4");
  const int32_t points = add_class(out, "GVM points only (exact alignment)", "#9467bd");
  const int32_t empty = add_class(out, "unreachable (GVM empty)", kUnreachable);
  const int32_t unknown = add_class(out, "GVM not computed (LVM only)", "#ff7f0e");
  const int32_t hull = add_class(out, "hull", kNeutral);
  for (int32_t& c : out.face_class) c = hull;
  assign_surfaces(analysis.features(), out);
  for (const v1::Feature& f : analysis.features()) {
    const v1::SphericalImage& g = f.gvm();
    int32_t cls = hull;
    if (!f.on_hull()) {
      if (!f.has_gvm()) cls = unknown;
      else if (g.full_sphere() || g.dimension() == 2) cls = open;
      else cls = g.dimension() == 1 ? arcs : g.dimension() == 0 ? points : empty;
    }
    out.surface_class[f.id()] = cls;
    paint(out, f.faces(), cls);
  }
  drop_unused(out, 0);
  return out;
}

}  // namespace gvm::report
