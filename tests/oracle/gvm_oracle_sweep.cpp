// gvm_oracle_sweep: checks GVMs computed by the engine (global occlusion on) against the
// brute-force ray-casting oracle of tests/support/ray_oracle.h.
//
//   gvm_oracle_sweep PART... [--directions N] [--margin DEG] [--max-features K] [--seed S]
//                    [--feature ID]... [--region ID]... [--no-features] [--no-regions]
//                    [--max-points P] [--max-grid G] [--method eme|convex] [--probe x,y,z]... [--negate] [--verbose]
//
// For every feature and every concave region S of each part, N random directions u
// uniform on the sphere and N more within 10 degrees of a corner of the GVM or the LVM
// (the seed is printed, each surface has its own stream derived from
// it so that --feature/--region reproduce the same directions) are tested: u is skipped when
// its angular distance to the boundary of the GVM (loop edges, arcs, points) is below the
// margin; otherwise engine_visible(u) (u inside a 2-cell of the GVM, decided by the parity of
// crossings with a reference direction w outside the GVM) is compared with the oracle.
// The arcs and points of the GVM (directions no random sample hits) are checked on their
// own: a point, and the midpoint of every piece of an arc, must not be blocked robustly --
// by a ray that crosses a triangle (front or back) well inside it and well off its plane.
// Rays along these directions often graze the part exactly, which the doubles of the
// oracle cannot decide; the check is one-sided, it catches a cell wrongly called visible.
// --probe adds fixed directions (never skipped; the distance is printed). --negate evaluates
// the engine side at -u: a deliberately wrong GVM, to see that the sweep notices.
// Exit status: 0 all agree, 1 some disagreement, 2 usage or load errors.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "io/sphere_proto.h"
#include "gvm/mesh.h"
#include "gvm/part.h"
#include "gvm/v1/gvm.pb.h"
#include "sphere/spherical_image.h"
#include "support/ray_oracle.h"
#include "visibility/surface_visibility.h"

namespace {

using gvm::oracle::Vec;
constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec add(const Vec& a, const Vec& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec scale(const Vec& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double norm(const Vec& a) { return std::sqrt(dot(a, a)); }
Vec normalized(const Vec& a) { return scale(a, 1.0 / norm(a)); }
Vec neg(const Vec& a) { return {-a[0], -a[1], -a[2]}; }
// Angle between two directions (radians), accurate near 0 and pi.
double angle(const Vec& a, const Vec& b) { return std::atan2(norm(cross(a, b)), dot(a, b)); }

// The GVM as plain unit vectors, from the proto.
struct Image {
  bool full = false;
  std::vector<std::vector<std::vector<Vec>>> polygons;  // polygon -> loops -> vertices
  std::vector<std::vector<Vec>> arcs;                   // polylines
  std::vector<Vec> points;
  double area = 0;
  std::string description;
};

Vec from_proto(const gvm::v1::Vec3& v) { return normalized(Vec{v.x(), v.y(), v.z()}); }

Image image_of(const gvm::v1::SphericalImage& m) {
  Image im;
  im.full = m.full_sphere();
  im.area = m.area();
  im.description = m.description();
  for (const auto& poly : m.polygons()) {
    auto& out = im.polygons.emplace_back();
    for (const auto& loop : poly.loops()) {
      auto& l = out.emplace_back();
      for (const auto& v : loop.vertices()) l.push_back(from_proto(v));
    }
  }
  for (const auto& arc : m.arcs()) {
    auto& a = im.arcs.emplace_back();
    for (const auto& v : arc.vertices()) a.push_back(from_proto(v));
  }
  for (const auto& p : m.points()) im.points.push_back(from_proto(p));
  return im;
}

// Every vertex of the image: loop vertices, polyline vertices, points.
std::vector<Vec> corners(const Image& im) {
  std::vector<Vec> out = im.points;
  for (const auto& poly : im.polygons) {
    for (const auto& loop : poly) out.insert(out.end(), loop.begin(), loop.end());
  }
  for (const auto& arc : im.arcs) out.insert(out.end(), arc.begin(), arc.end());
  return out;
}

// Angular distance from u to the minor great-circle arc a-b (radians).
double distance_to_arc(const Vec& u, const Vec& a, const Vec& b) {
  const Vec c = cross(a, b);
  const double cn = norm(c);
  const double ends = std::min(angle(u, a), angle(u, b));
  if (cn < 1e-15) return ends;  // (nearly) a point
  const Vec n = scale(c, 1.0 / cn);
  const double h = dot(u, n);
  const Vec q = add(u, scale(n, -h));  // projection onto the circle's plane
  if (norm(q) < 1e-15) return std::min(ends, kPi / 2);
  if (dot(cross(a, q), n) >= 0 && dot(cross(q, b), n) >= 0) {
    return std::atan2(std::fabs(h), norm(q));
  }
  return ends;
}

// Distance from u to the 1-cells and 0-cells only.
double distance_to_lower_cells(const Image& im, const Vec& u) {
  double d = std::numeric_limits<double>::infinity();
  for (const auto& arc : im.arcs) {
    if (arc.size() == 1) d = std::min(d, angle(u, arc[0]));
    for (std::size_t i = 0; i + 1 < arc.size(); ++i) {
      d = std::min(d, distance_to_arc(u, arc[i], arc[i + 1]));
    }
  }
  for (const Vec& p : im.points) d = std::min(d, angle(u, p));
  return d;
}

double distance_to_boundary(const Image& im, const Vec& u) {
  double d = std::numeric_limits<double>::infinity();
  for (const auto& poly : im.polygons) {
    for (const auto& loop : poly) {
      for (std::size_t i = 0; i < loop.size(); ++i) {
        d = std::min(d, distance_to_arc(u, loop[i], loop[(i + 1) % loop.size()]));
      }
    }
  }
  for (const auto& arc : im.arcs) {
    if (arc.size() == 1) d = std::min(d, angle(u, arc[0]));
    for (std::size_t i = 0; i + 1 < arc.size(); ++i) {
      d = std::min(d, distance_to_arc(u, arc[i], arc[i + 1]));
    }
  }
  for (const Vec& p : im.points) d = std::min(d, angle(u, p));
  return d;
}

// Proper crossing of the minor arcs p-q and a-b. Sets *ambiguous when a sign is too close to
// zero to be trusted (the path passes (nearly) through a vertex or along an edge).
bool arcs_cross(const Vec& p, const Vec& q, const Vec& a, const Vec& b, bool* ambiguous) {
  const Vec m = cross(p, q), n = cross(a, b);
  const double mn = norm(m), nn = norm(n);
  const double tol = 1e-12;
  const double sa = dot(m, a) / mn, sb = dot(m, b) / mn;
  const double sp = dot(n, p) / nn, sq = dot(n, q) / nn;
  if ((sa > tol && sb > tol) || (sa < -tol && sb < -tol)) return false;
  if ((sp > tol && sq > tol) || (sp < -tol && sq < -tol)) return false;
  const Vec x = cross(m, n);
  const double xp = dot(x, add(p, q)), xa = dot(x, add(a, b));
  if (std::fabs(sa) <= tol || std::fabs(sb) <= tol || std::fabs(sp) <= tol ||
      std::fabs(sq) <= tol || norm(x) < tol * mn * nn) {
    // Only ambiguous when the crossing would be on the same side (near-contact).
    if (xp * xa >= 0) *ambiguous = true;
    return false;
  }
  return (xp > 0) == (xa > 0);
}

// Count of crossings of the path (polyline of minor arcs) with the loops of one polygon.
int crossings(const std::vector<std::vector<Vec>>& polygon, const std::vector<Vec>& path,
              bool* ambiguous) {
  int count = 0;
  for (std::size_t s = 0; s + 1 < path.size(); ++s) {
    for (const auto& loop : polygon) {
      for (std::size_t i = 0; i < loop.size(); ++i) {
        if (arcs_cross(path[s], path[s + 1], loop[i], loop[(i + 1) % loop.size()], ambiguous)) {
          ++count;
        }
      }
    }
  }
  return count;
}

// u inside some 2-cell of the image, w a direction outside the image. nullopt when every
// tried path was ambiguous.
std::optional<bool> inside(const Image& im, const Vec& u, const Vec& w, std::mt19937_64& rng) {
  if (im.full) return true;
  std::normal_distribution<double> gauss;
  for (int attempt = 0; attempt < 20; ++attempt) {
    std::vector<Vec> path{u};
    if (attempt > 0 || dot(u, w) < -0.9) {
      // Through an intermediate direction m (legs well short of 180 degrees).
      Vec m;
      do {
        m = normalized(Vec{gauss(rng), gauss(rng), gauss(rng)});
      } while (dot(m, u) < -0.8 || dot(m, w) < -0.8);
      path.push_back(m);
    }
    path.push_back(w);
    bool ambiguous = false;
    bool in = false;
    for (const auto& poly : im.polygons) {
      if (crossings(poly, path, &ambiguous) % 2 == 1) in = true;
    }
    if (!ambiguous) return in;
  }
  return std::nullopt;
}

Vec random_direction(std::mt19937_64& rng) {
  std::normal_distribution<double> gauss;
  for (;;) {
    Vec v{gauss(rng), gauss(rng), gauss(rng)};
    double n = norm(v);
    if (n > 1e-6) return scale(v, 1.0 / n);
  }
}

struct Options {
  std::vector<std::string> parts;
  int directions = 200;
  double margin_deg = 0.5;
  long max_features = -1;
  uint64_t seed = 1;
  std::set<uint32_t> only_features, only_regions;
  bool features = true, regions = true;
  std::size_t max_points = 2000;
  int max_grid = 8;
  gvm::OcclusionMethod method = gvm::OcclusionMethod::kEffectiveMinkowskiEnvelope;
  std::vector<Vec> probes;
  bool negate = false;
  bool verbose = false;
};

void usage() {
  std::fprintf(stderr,
               "usage: gvm_oracle_sweep PART... [--directions N] [--margin DEG] "
               "[--max-features K] [--seed S] [--feature ID]... [--region ID]... "
               "[--no-features] [--no-regions] [--max-points P] [--max-grid G] [--method eme|convex] "
               "[--probe x,y,z]... "
               "[--negate] [--verbose]\n");
}

const char* kind_name(gvm::GvmStatus k) {
  switch (k) {
    case gvm::GvmStatus::kExactNoPotentialOccluders: return "exact, O_S empty";
    case gvm::GvmStatus::kGlobalOcclusionNotComputed: return "global occlusion not computed";
    case gvm::GvmStatus::kGlobalOcclusionComputed: return "global occlusion computed";
    case gvm::GvmStatus::kEmptyVoid: return "empty (void)";
  }
  return "?";
}

struct Surface {
  std::string label;  // "feature 3 'name'" or "region 2"
  std::vector<uint32_t> triangles;
  uint64_t stream;    // per-surface random stream id
};

struct PartTotals {
  int surfaces = 0, surfaces_checked = 0, surfaces_skipped = 0;
  long tested = 0, visible = 0, skipped_near_boundary = 0, agree = 0, disagree = 0, undecided = 0;
  long cells = 0;  // arcs' midpoints and points of GVMs checked against robust blocking
};

// Explains an oracle "blocked" answer: self-occluding triangle or blocked ray.
std::string witness(const gvm::oracle::RayOracle& oracle, const gvm::SolidMesh& mesh,
                    const Surface& s, const std::vector<Vec>& points, const Vec& u) {
  char buf[512];
  for (uint32_t t : s.triangles) {
    const auto& tri = mesh.triangles[t];
    const auto& a = mesh.points[tri[0]];
    const auto& b = mesh.points[tri[1]];
    const auto& c = mesh.points[tri[2]];
    Vec n = cross(Vec{b.x - a.x, b.y - a.y, b.z - a.z}, Vec{c.x - a.x, c.y - a.y, c.z - a.z});
    if (dot(u, n) < -oracle.options().self_tolerance * norm(n)) {
      std::snprintf(buf, sizeof buf, "self-occluded by triangle %u (face %u), u.n/|n| = %.3g",
                    t, mesh.triangle_face[t], dot(u, n) / norm(n));
      return buf;
    }
  }
  for (const Vec& p : points) {
    uint32_t hit = 0;
    if (oracle.ray_blocked(p, u, &hit)) {
      std::snprintf(buf, sizeof buf,
                    "ray from (%.17g, %.17g, %.17g) blocked by triangle %u (face %u)", p[0], p[1],
                    p[2], hit, mesh.triangle_face[hit]);
      return buf;
    }
  }
  return "no witness";
}

// The features and regions the options ask for, each with its own random stream.
std::vector<Surface> surfaces_of(const gvm::Part& part, const Options& opt) {
  std::vector<Surface> surfaces;
  if (opt.features) {
    long n = 0;
    for (const gvm::Feature& f : part.features()) {
      if (!opt.only_features.empty() && !opt.only_features.count(f.id)) continue;
      if (opt.max_features >= 0 && n >= opt.max_features) break;
      ++n;
      surfaces.push_back({"feature " + std::to_string(f.id) + " '" + f.name + "'", f.triangles,
                          (uint64_t{1} << 32) + f.id});
    }
  }
  if (opt.regions) {
    long n = 0;
    for (const gvm::ConcaveRegion& r : part.regions()) {
      if (!opt.only_regions.empty() && !opt.only_regions.count(r.id)) continue;
      if (opt.max_features >= 0 && n >= opt.max_features) break;
      ++n;
      surfaces.push_back({"region " + std::to_string(r.id), r.triangles, (uint64_t{2} << 32) + r.id});
    }
  }
  return surfaces;
}

// Reference w outside the GVM, at a margin from its boundary: -n_F of a triangle F of S
// (self-occluded), else a random self-occluded direction.
std::optional<Vec> reference_outside(const Image& im, const gvm::SolidMesh& m, const Surface& s, double margin,
                                     std::mt19937_64& rng) {
  std::vector<Vec> normals;
  for (uint32_t t : s.triangles) {
    const auto& tri = m.triangles[t];
    const auto& a = m.points[tri[0]];
    const auto& b = m.points[tri[1]];
    const auto& c = m.points[tri[2]];
    normals.push_back(normalized(cross(Vec{b.x - a.x, b.y - a.y, b.z - a.z}, Vec{c.x - a.x, c.y - a.y, c.z - a.z})));
  }
  auto self_occluded = [&](const Vec& v) {
    for (const Vec& n : normals) if (dot(v, n) < -1e-9) return true;
    return false;
  };
  for (std::size_t i = 0; i < normals.size() && i < 64; ++i) {
    const Vec c = neg(normals[i]);
    if (distance_to_boundary(im, c) > margin) return c;
  }
  for (int i = 0; i < 1000; ++i) {
    const Vec c = random_direction(rng);
    if (self_occluded(c) && distance_to_boundary(im, c) > margin) return c;
  }
  return std::nullopt;
}

// The directions one surface is checked along: the probes, uniform ones, as many again
// near the corners of the GVM and of the LVM (where the answer changes: uniform directions
// alone rarely land in a small GVM). check(u, probe) for each.
template <class Check>
void sweep_directions(const Options& opt, const Image& im, const gvm::sphere::SphericalImage& lvm, std::mt19937_64& rng,
                      const Check& check) {
  for (const Vec& u : opt.probes) check(u, true);
  for (int i = 0; i < opt.directions; ++i) check(random_direction(rng), false);
  gvm::v1::SphericalImage lvm_proto;
  gvm::io::to_proto(lvm, &lvm_proto);
  std::vector<Vec> anchors = corners(im);
  for (const Vec& v : corners(image_of(lvm_proto))) anchors.push_back(v);
  for (int i = 0; i < opt.directions && !anchors.empty(); ++i) {
    const Vec& a = anchors[rng() % anchors.size()];
    const Vec t = normalized(cross(a, random_direction(rng)));
    const double theta = std::uniform_real_distribution<double>(0, 10 * kDeg)(rng);
    check(normalized(add(scale(a, std::cos(theta)), scale(t, std::sin(theta)))), false);
  }
}

// The GVM's own arcs (their midpoints) and points against the robust oracle (see the top
// of the file); the disagreements.
long check_lower_cells(const std::string& path, const Surface& s, const Image& im, const gvm::SolidMesh& m,
                       const gvm::oracle::RayOracle& robust, PartTotals& totals) {
  std::vector<Vec> cells = im.points;
  for (const auto& arc : im.arcs) {
    for (std::size_t i = 0; i + 1 < arc.size(); ++i) cells.push_back(normalized(add(arc[i], arc[i + 1])));
  }
  const std::vector<Vec> robust_points = cells.empty() ? std::vector<Vec>{} : robust.sample_points(s.triangles);
  long dis = 0;
  for (const Vec& u : cells) {
    ++totals.cells;
    if (robust.surface_visible(s.triangles, robust_points, u)) continue;
    ++dis;
    std::printf("    DISAGREE part=%s %s |S|=%zu u=(%.17g, %.17g, %.17g) engine=visible (an arc or "
                "point of the GVM) oracle=blocked robustly [%s]\n",
                path.c_str(), s.label.c_str(), s.triangles.size(), u[0], u[1], u[2],
                witness(robust, m, s, robust_points, u).c_str());
  }
  return dis;
}

// One surface: its GVM, then every direction of sweep_directions against the ray oracle.
void sweep_surface(const std::string& path, const gvm::Part& part, const Surface& s, const Options& opt,
                   const gvm::oracle::RayOracle& oracle, const gvm::oracle::RayOracle& robust, PartTotals& totals) {
  const gvm::SolidMesh& m = part.mesh();
  const double margin = opt.margin_deg * kDeg;
  ++totals.surfaces;
  std::printf("  %s |S|=%zu: computing GVM...\n", s.label.c_str(), s.triangles.size());
  std::fflush(stdout);
  const auto t0 = std::chrono::steady_clock::now();
  gvm::SurfaceVisibility vis = gvm::compute_surface_visibility(part, s.triangles, true, opt.method);
  const double gvm_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!vis.gvm) {
    std::printf("  %s: skipped, no GVM (%s) [%.2fs]\n", s.label.c_str(), kind_name(vis.status), gvm_seconds);
    ++totals.surfaces_skipped;
    return;
  }
  gvm::v1::SphericalImage proto;
  gvm::io::to_proto(*vis.gvm, &proto);
  const Image im = image_of(proto);
  std::size_t loop_edges = 0;
  for (const auto& p : im.polygons) for (const auto& l : p) loop_edges += l.size();

  std::mt19937_64 rng(opt.seed * 0x9E3779B97F4A7C15ull ^ s.stream);
  std::optional<Vec> w;
  if (!im.full) {
    w = reference_outside(im, m, s, margin, rng);
    if (!w) {
      std::printf("  %s: skipped, no reference direction outside the GVM found\n", s.label.c_str());
      ++totals.surfaces_skipped;
      return;
    }
  }
  ++totals.surfaces_checked;
  const std::vector<Vec> points = oracle.sample_points(s.triangles);
  long tested = 0, skipped = 0, dis = 0, visible_count = 0;
  auto check = [&](const Vec& u, bool probe) {
    const double d = distance_to_boundary(im, u);
    if (!probe && d < margin) {
      ++skipped;
      return;
    }
    const Vec ue = opt.negate ? neg(u) : u;
    // Inside a 2-cell, or (only reachable by probes: random directions keep the margin)
    // on a 1-cell or 0-cell.
    std::optional<bool> e = im.full ? std::optional<bool>(true) : inside(im, ue, *w, rng);
    if (e && !*e && distance_to_lower_cells(im, ue) < 1e-9) e = true;
    const bool o = oracle.surface_visible(s.triangles, points, u);
    if (!e) {
      ++totals.undecided;
      std::printf("    UNDECIDED %s u=(%.17g, %.17g, %.17g): parity paths ambiguous\n", s.label.c_str(), u[0], u[1],
                  u[2]);
      return;
    }
    ++tested;
    visible_count += o;
    if (probe) {
      std::printf("    PROBE %s u=(%.17g, %.17g, %.17g) engine=%d oracle=%d dist=%.4f deg%s\n", s.label.c_str(), u[0],
                  u[1], u[2], int(*e), int(o), d / kDeg,
                  o ? "" : (" [" + witness(oracle, m, s, points, u) + "]").c_str());
    }
    if (*e == o) {
      ++totals.agree;
      return;
    }
    ++dis;
    std::printf(
        "    DISAGREE part=%s %s |S|=%zu u=(%.17g, %.17g, %.17g) engine=%s oracle=%s "
        "dist_to_boundary=%.4f deg seed=%llu%s\n",
        path.c_str(), s.label.c_str(), s.triangles.size(), u[0], u[1], u[2], *e ? "visible" : "blocked",
        o ? "visible" : "blocked", d / kDeg, static_cast<unsigned long long>(opt.seed),
        o ? "" : (" [" + witness(oracle, m, s, points, u) + "]").c_str());
  };
  const auto t1 = std::chrono::steady_clock::now();
  sweep_directions(opt, im, vis.lvm, rng, check);
  dis += check_lower_cells(path, s, im, m, robust, totals);
  const double oracle_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  totals.tested += tested;
  totals.visible += visible_count;
  totals.skipped_near_boundary += skipped;
  totals.disagree += dis;
  std::printf(
      "  %s |S|=%zu: %s, GVM %s (area %.4f sr, %zu polygons, %zu loop edges, %zu arcs, %zu "
      "points), %zu sample points; tested %ld (oracle visible %ld), skipped %ld, "
      "disagreements %ld [GVM %.2fs, oracle %.2fs]\n",
      s.label.c_str(), s.triangles.size(), kind_name(vis.status),
      im.full ? "full sphere"
              : (im.polygons.empty() && im.arcs.empty() && im.points.empty() ? "empty" : "non-empty"),
      im.area, im.polygons.size(), loop_edges, im.arcs.size(), im.points.size(), points.size(), tested,
      visible_count, skipped, dis, gvm_seconds, oracle_seconds);
  if (opt.verbose) {
    std::printf("    description: %s\n    triangles:", im.description.c_str());
    for (uint32_t t : s.triangles) std::printf(" %u", t);
    std::printf("\n");
  }
  std::fflush(stdout);
}

PartTotals sweep_part(const std::string& path, const Options& opt, bool* failed) {
  PartTotals totals;
  auto mesh = gvm::load_solid(path);
  if (!mesh.ok()) {
    std::printf("%s: load failed: %s\n", path.c_str(), mesh.status().message().c_str());
    *failed = true;
    return totals;
  }
  auto part = gvm::Part::analyze(std::move(*mesh), gvm::PartOptions{});
  if (!part.ok()) {
    std::printf("%s: analysis failed: %s\n", path.c_str(), part.status().message().c_str());
    *failed = true;
    return totals;
  }
  const gvm::SolidMesh& m = part->mesh();
  gvm::oracle::OracleOptions oracle_options;
  oracle_options.max_points = opt.max_points;
  oracle_options.max_grid = opt.max_grid;
  const gvm::oracle::RayOracle oracle(m, oracle_options);
  gvm::oracle::OracleOptions robust_options = oracle_options;
  robust_options.barycentric_tolerance = -1e-7;
  robust_options.front_tolerance = robust_options.self_tolerance = 1e-7;
  robust_options.exits_block = true;
  const gvm::oracle::RayOracle robust(m, robust_options);
  std::printf("%s: %zu triangles, %zu features, %zu regions\n", path.c_str(), m.triangles.size(),
              part->features().size(), part->regions().size());
  for (const Surface& s : surfaces_of(*part, opt)) sweep_surface(path, *part, s, opt, oracle, robust, totals);
  return totals;
}

bool parse_vec(const std::string& s, Vec* v) {
  double x, y, z;
  if (std::sscanf(s.c_str(), "%lf,%lf,%lf", &x, &y, &z) != 3) return false;
  Vec r{x, y, z};
  if (norm(r) == 0) return false;
  *v = normalized(r);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) {
        usage();
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--directions") opt.directions = std::stoi(next());
    else if (a == "--margin") opt.margin_deg = std::stod(next());
    else if (a == "--max-features") opt.max_features = std::stol(next());
    else if (a == "--seed") opt.seed = std::stoull(next());
    else if (a == "--feature") opt.only_features.insert(std::stoul(next()));
    else if (a == "--region") opt.only_regions.insert(std::stoul(next()));
    else if (a == "--no-features") opt.features = false;
    else if (a == "--no-regions") opt.regions = false;
    else if (a == "--max-points") opt.max_points = std::stoul(next());
    else if (a == "--max-grid") opt.max_grid = std::stoi(next());
    else if (a == "--method") {
      const std::string m = next();
      if (m != "eme" && m != "convex") {
        usage();
        return 2;
      }
      opt.method = m == "convex" ? gvm::OcclusionMethod::kConvexDecomposition
                                 : gvm::OcclusionMethod::kEffectiveMinkowskiEnvelope;
    }
    else if (a == "--negate") opt.negate = true;
    else if (a == "--verbose") opt.verbose = true;
    else if (a == "--probe") {
      Vec v;
      if (!parse_vec(next(), &v)) {
        usage();
        return 2;
      }
      opt.probes.push_back(v);
    } else if (a == "-h" || a == "--help") {
      usage();
      return 0;
    } else if (!a.empty() && a[0] == '-') {
      usage();
      return 2;
    } else {
      opt.parts.push_back(a);
    }
  }
  if (opt.parts.empty()) {
    usage();
    return 2;
  }
  // Only features given: do not also sweep every region (and vice versa).
  if (!opt.only_features.empty() && opt.only_regions.empty()) opt.regions = false;
  if (!opt.only_regions.empty() && opt.only_features.empty()) opt.features = false;
  std::printf("gvm_oracle_sweep: seed %llu, %d directions per surface, margin %.3f deg%s\n",
              static_cast<unsigned long long>(opt.seed), opt.directions, opt.margin_deg,
              opt.negate ? ", NEGATED engine side (sanity check)" : "");
  bool failed = false;
  long total_disagree = 0;
  for (const std::string& path : opt.parts) {
    const auto t0 = std::chrono::steady_clock::now();
    PartTotals t = sweep_part(path, opt, &failed);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf(
        "SUMMARY %s: surfaces %d (checked %d, skipped %d), directions tested %ld (oracle "
        "visible %ld), skipped near boundary %ld, undecided %ld, agreements %ld, arcs and "
        "points of GVMs checked %ld, disagreements %ld, %.2f s\n",
        path.c_str(), t.surfaces, t.surfaces_checked, t.surfaces_skipped, t.tested, t.visible,
        t.skipped_near_boundary, t.undecided, t.agree, t.cells, t.disagree, seconds);
    std::fflush(stdout);
    total_disagree += t.disagree;
  }
  if (total_disagree > 0) return 1;
  return failed ? 2 : 0;
}
