// gvm_plan_check: the planner on real parts, checked against what it claims.
//
//   gvm_plan_check PART... [--mode setup|rotary|probe] [--planar-normal] [--threads N]
//
// For each part: the analysis (all threads), then the plan with 1 and with 2 threads,
// which must be the same message but for timings; every (setup, feature) assignment is
// verified exactly (the setup's exact direction lies in the feature's tool directions)
// and, in setup and probe modes, by the ray-casting oracle: a direction with at least 1
// degree of certified clearance must be visible to the oracle, and so must the directions
// half that clearance away around it (at most 5 degrees); a direction with less (exact
// alignment: through holes, slots, grazing boundaries) must not be blocked robustly --
// by a ray crossing a triangle well inside it and well off its plane (doubles cannot
// decide grazing rays, so that side is one-way, as in gvm_oracle_sweep). Also: every arc
// of every map in the analysis JSON is at most 90 degrees long, and the plan's proof is
// consistent (lower bound <= setups, optimal iff equal).
// Exit status: 0 all checks pass, 1 some fail, 2 usage or load errors.
#include <google/protobuf/util/message_differencer.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "gvm/analysis.h"
#include "gvm/analysis_proto.h"
#include "gvm/mesh.h"
#include "gvm/planner/plan.h"
#include "support/ray_oracle.h"

namespace {

using Vec = std::array<double, 3>;
constexpr double kDeg = M_PI / 180;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

Vec unit(const gvm::v1::Vec3& v) {
  const double n = std::sqrt(v.x() * v.x() + v.y() * v.y() + v.z() * v.z());
  return {v.x() / n, v.y() / n, v.z() / n};
}

double angle_deg(const gvm::v1::Vec3& a, const gvm::v1::Vec3& b) {
  const Vec u = unit(a), w = unit(b);
  const Vec c = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  return std::atan2(std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]),
                    u[0] * w[0] + u[1] * w[1] + u[2] * w[2]) / kDeg;
}

// The longest arc between consecutive vertices of any loop or polyline of the map.
double longest_arc(const gvm::v1::SphericalImage& m) {
  double longest = 0;
  for (const auto& p : m.polygons()) {
    for (const auto& l : p.loops()) {
      for (int i = 0; i < l.vertices_size(); ++i) {
        longest = std::max(longest, angle_deg(l.vertices(i), l.vertices((i + 1) % l.vertices_size())));
      }
    }
  }
  for (const auto& a : m.arcs()) {
    for (int i = 0; i + 1 < a.vertices_size(); ++i) longest = std::max(longest, angle_deg(a.vertices(i), a.vertices(i + 1)));
  }
  return longest;
}

double longest_arc(const gvm::v1::Analysis& a) {
  double longest = 0;
  for (const auto& r : a.regions()) longest = std::max({longest, longest_arc(r.lvm()), longest_arc(r.gvm())});
  for (const auto& f : a.features()) longest = std::max({longest, longest_arc(f.lvm()), longest_arc(f.gvm())});
  return longest;
}

// Directions at `angle` around u.
std::vector<Vec> ring(const Vec& u, double angle) {
  const Vec a = std::fabs(u[0]) < 0.6 ? Vec{1, 0, 0} : Vec{0, 1, 0};
  Vec t1 = {u[1] * a[2] - u[2] * a[1], u[2] * a[0] - u[0] * a[2], u[0] * a[1] - u[1] * a[0]};
  const double n = std::sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
  for (double& x : t1) x /= n;
  const Vec t2 = {u[1] * t1[2] - u[2] * t1[1], u[2] * t1[0] - u[0] * t1[2], u[0] * t1[1] - u[1] * t1[0]};
  std::vector<Vec> out;
  for (int k = 0; k < 8; ++k) {
    const double phi = k * M_PI / 4, c = std::cos(angle), s = std::sin(angle);
    out.push_back({c * u[0] + s * (std::cos(phi) * t1[0] + std::sin(phi) * t2[0]),
                   c * u[1] + s * (std::cos(phi) * t1[1] + std::sin(phi) * t2[1]),
                   c * u[2] + s * (std::cos(phi) * t1[2] + std::sin(phi) * t2[2])});
  }
  return out;
}

struct Options {
  std::vector<std::string> parts;
  gvm::v1::PlanOptions plan;
  unsigned threads = 0;
};

struct Failures {
  int count = 0;
  void operator()(const std::string& what) {
    ++count;
    std::printf("    FAIL %s\n", what.c_str());
  }
};

void strip_timing(gvm::v1::Plan& p) { p.clear_timing(); }

std::vector<uint32_t> triangles_of(const gvm::SolidMesh& mesh, const std::vector<uint32_t>& faces) {
  std::vector<char> in(mesh.input_face_count, 0);
  for (uint32_t f : faces) in[f] = 1;
  std::vector<uint32_t> out;
  for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    if (in[mesh.triangle_face[t]]) out.push_back(t);
  }
  return out;
}

// The oracle's verdict on one assignment; returns false with a message on disagreement.
bool oracle_agrees(const gvm::oracle::RayOracle& oracle, const gvm::oracle::RayOracle& robust,
                   const std::vector<uint32_t>& tris, const Vec& u, double clearance, std::string* why) {
  if (clearance >= 1) {
    if (!oracle.surface_visible(tris, u)) return *why = "oracle: blocked at the setup direction", false;
    for (const Vec& v : ring(u, 0.5 * std::min(clearance, 10.0) * kDeg)) {
      if (!oracle.surface_visible(tris, v)) return *why = "oracle: blocked inside the clearance", false;
    }
    return true;
  }
  if (!robust.surface_visible(tris, u)) return *why = "oracle: blocked robustly at an exact-alignment direction", false;
  return true;
}

int check_part(const std::string& path, const Options& opt, Failures& fail) {
  const auto t0 = std::chrono::steady_clock::now();
  gvm::AnalyzeRequest request;
  request.part_path = path;
  request.options.set_threads(opt.threads);
  auto analysis = gvm::analyze(request);
  if (!analysis.ok()) {
    std::printf("%s: analysis failed: %s\n", path.c_str(), analysis.status().message().c_str());
    return 2;
  }
  const double analysis_seconds = seconds_since(t0);
  const double arc = longest_arc(gvm::to_proto(*analysis));
  if (arc > 90 + 1e-9) fail(path + ": an arc of " + std::to_string(arc) + " degrees in the analysis JSON");

  gvm::v1::PlanOptions one = opt.plan, two = opt.plan;
  one.set_threads(1);
  two.set_threads(2);
  auto t1 = std::chrono::steady_clock::now();
  auto plan = gvm::planner::plan(*analysis, one);
  const double plan_seconds = seconds_since(t1);
  auto again = gvm::planner::plan(*analysis, two);
  if (!plan.ok() || !again.ok()) {
    std::printf("%s: planning failed: %s\n", path.c_str(), (plan.ok() ? again : plan).status().message().c_str());
    return 2;
  }
  gvm::v1::Plan a = plan->message, b = again->message;
  strip_timing(a), strip_timing(b);
  a.mutable_options()->clear_threads(), b.mutable_options()->clear_threads();
  if (!google::protobuf::util::MessageDifferencer::Equals(a, b)) fail(path + ": different plans with 1 and 2 threads");
  const gvm::v1::Plan& p = plan->message;
  if (p.lower_bound() > uint32_t(p.setups_size()) || p.optimal() != (p.lower_bound() == uint32_t(p.setups_size()))) {
    fail(path + ": inconsistent proof");
  }

  auto mesh = gvm::load_solid(path);
  if (!mesh.ok()) return 2;
  const gvm::oracle::RayOracle oracle(*mesh);
  gvm::oracle::OracleOptions robust_options;
  robust_options.barycentric_tolerance = -1e-7;
  robust_options.front_tolerance = robust_options.self_tolerance = 1e-7;
  robust_options.exits_block = true;
  const gvm::oracle::RayOracle robust(*mesh, robust_options);
  const bool regions = p.surfaces_kind() == gvm::v1::PLAN_SURFACES_REGIONS;
  const auto& surfaces = regions ? analysis->regions() : analysis->features();
  int exact = 0, oracle_checked = 0;
  for (int k = 0; k < p.setups_size(); ++k) {
    const gvm::Direction& d = plan->directions[k];
    for (const auto& r : p.setups(k).reach()) {
      if (r.faces_size() > 0) continue;  // pieces of split features: not planned here
      const gvm::Surface& s = surfaces[r.feature()];
      const std::string where = path + " setup " + std::to_string(k + 1) + " " + s.name + "#" + std::to_string(s.id);
      const bool in = p.mode() == gvm::v1::PLAN_MODE_ROTARY
                          ? !s.maps.gvm->intersection(gvm::DirectionSet::great_circle(d)).is_empty()
                          : s.maps.gvm->contains(d);
      ++exact;
      if (!in) fail(where + ": the direction is not in its GVM (exact)");
      if (p.mode() == gvm::v1::PLAN_MODE_ROTARY) continue;
      std::string why;
      ++oracle_checked;
      const double clearance = s.maps.gvm->dimension() == 2 && !r.exact_alignment() ? r.clearance_degrees() : 0;
      if (!oracle_agrees(oracle, robust, triangles_of(*mesh, s.faces), d.unit(), clearance, &why)) fail(where + ": " + why);
    }
  }
  std::printf("%s: %d %s, %u reached, %u unreachable; %d setups, bound %u (%s), greedy %u, packing %u; "
              "%d assignments exact, %d by the oracle; longest JSON arc %.3f deg; analysis %.2f s, plan %.3f s\n",
              path.c_str(), p.surfaces_size(), regions ? "regions" : "features", p.reached(), p.unreachable_count(),
              p.setups_size(), p.lower_bound(), p.optimal() ? "optimal" : "not proven", p.solver().greedy_setups(),
              p.solver().packing_bound(), exact, oracle_checked, arc, analysis_seconds, plan_seconds);
  std::fflush(stdout);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  spdlog::set_level(spdlog::level::warn);  // the analyses' progress lines would drown the report
  Options opt;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--mode" && i + 1 < argc) {
      const std::string m = argv[++i];
      opt.plan.set_mode(m == "rotary" ? gvm::v1::PLAN_MODE_ROTARY
                                      : m == "probe" ? gvm::v1::PLAN_MODE_PROBE : gvm::v1::PLAN_MODE_SETUP);
    } else if (a == "--planar-normal") {
      opt.plan.set_planar_normal(true);
    } else if (a == "--threads" && i + 1 < argc) {
      opt.threads = static_cast<unsigned>(std::stoul(argv[++i]));
    } else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "usage: gvm_plan_check PART... [--mode setup|rotary|probe] [--planar-normal] [--threads N]\n");
      return 2;
    } else {
      opt.parts.push_back(a);
    }
  }
  Failures fail;
  int status = 0;
  for (const std::string& part : opt.parts) status = std::max(status, check_part(part, opt, fail));
  std::printf("%zu parts, %d failures\n", opt.parts.size(), fail.count);
  return status ? status : (fail.count ? 1 : 0);
}
