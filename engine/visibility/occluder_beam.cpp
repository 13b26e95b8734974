#include "visibility/occluder_beam.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "parallel/interrupt.h"
#include "sphere/d3.h"

namespace gvm {
namespace {

using namespace sphere;  // D3

// Pruning margins. kMargin is the angle (radians) within which a face is always kept; any
// positive value gives the same GVM. kSlack absorbs the rounding of the bounds below
// (each is accurate to about 1e-15), so that a face is dropped only when its directions
// are certainly farther than kMargin - kSlack > 0 from L.
constexpr double kMargin = 1e-4;
constexpr double kSlack = 1e-9;


struct Ball {
  D3 c;
  double r;
};

// A ball that contains the triangle: centroid and largest vertex distance, inflated.
Ball ball_of(const SolidMesh& mesh, uint32_t t) {
  const Triangle& tri = mesh.triangles[t];
  D3 c{0, 0, 0};
  for (uint32_t v : tri) {
    for (int i = 0; i < 3; ++i) c[i] += mesh.points[v][i] / 3;
  }
  double r = 0;
  for (uint32_t v : tri) {
    double d = 0;
    for (int i = 0; i < 3; ++i) d += (mesh.points[v][i] - c[i]) * (mesh.points[v][i] - c[i]);
    r = std::max(r, std::sqrt(d));
  }
  double scale = std::max({std::fabs(c[0]), std::fabs(c[1]), std::fabs(c[2]), r});
  return {c, r * (1 + 1e-12) + scale * 1e-12};
}

// A ball that contains every ball of `balls` (not empty), inflated.
Ball enclosing(const std::vector<Ball>& balls) {
  D3 c{0, 0, 0};
  for (const Ball& b : balls) c = add(c, b.c, 1.0 / balls.size());
  double r = 0;
  for (const Ball& b : balls) r = std::max(r, norm(add(b.c, c, -1)) + b.r);
  const double scale = std::max({std::fabs(c[0]), std::fabs(c[1]), std::fabs(c[2]), r});
  return {c, r * (1 + 1e-12) + scale * 1e-12};
}

// A lower bound of the angular distance from a unit vector to L, cell by cell: a convex
// 2-cell is inside the hemispheres of its arcs, a 1-cell on its great circle.
class LvmBound {
 public:
  explicit LvmBound(const sphere::SphericalImage& lvm) {
    for (const sphere::Face& f : lvm.faces()) {
      std::vector<D3> normals;
      for (const sphere::Loop& loop : f.loops) {
        for (const sphere::Arc& arc : loop.arcs) normals.push_back(arc.normal.unit());
      }
      faces_.push_back(std::move(normals));
    }
    for (const sphere::Arc& arc : lvm.curves()) circles_.push_back(arc.normal.unit());
    for (const auto& p : lvm.points()) points_.push_back(p.unit());
    full_ = lvm.is_full_sphere();
  }

  // asin and acos are monotone, so the extreme sines and cosines are found first and each
  // kind of cell costs one call (asin per normal showed in profiles:
  // docs/performance-history.md).
  double distance_lower_bound(const D3& w) const {
    if (full_) return 0;
    double best = 4;
    if (!faces_.empty()) {
      double nearest = 1;  // the sine of the nearest face's distance
      for (const auto& normals : faces_) {
        double farthest_side = 0;
        for (const D3& n : normals) farthest_side = std::max(farthest_side, std::clamp(-dot(w, n), 0.0, 1.0));
        nearest = std::min(nearest, farthest_side);
      }
      best = std::asin(nearest);
    }
    if (!circles_.empty()) {
      double sine = 1;
      for (const D3& n : circles_) sine = std::min(sine, std::fabs(dot(w, n)));
      best = std::min(best, std::asin(sine));
    }
    if (!points_.empty()) {
      double cosine = -1;
      for (const D3& p : points_) cosine = std::max(cosine, std::clamp(dot(w, p), -1.0, 1.0));
      best = std::min(best, std::acos(cosine));
    }
    return best;
  }

 private:
  std::vector<std::vector<D3>> faces_;
  std::vector<D3> circles_, points_;
  bool full_ = false;
};

}  // namespace

std::vector<uint32_t> occluders_in_beam(const SolidMesh& mesh, std::span<const uint32_t> s,
                                        std::span<const uint32_t> o,
                                        const sphere::SphericalImage& lvm) {
  if (s.empty()) return {};
  const LvmBound bound(lvm);
  std::vector<Ball> sources;
  sources.reserve(s.size());
  for (uint32_t t : s) sources.push_back(ball_of(mesh, t));
  const Ball all_sources = enclosing(sources);
  std::vector<uint32_t> kept;
  Interruptions interruptions(16);  // one t runs over every triangle of S
  for (uint32_t t : o) {
    interruptions.tick();
    const Ball target = ball_of(mesh, t);
    // Directions from a source ball to the target ball lie in a cone around w of half
    // angle asin((r_s + r_t) / |w|).
    auto reaches = [&](const Ball& src) {
      D3 w{target.c[0] - src.c[0], target.c[1] - src.c[1], target.c[2] - src.c[2]};
      double len = std::sqrt(dot(w, w));
      double reach = src.r + target.r;
      if (!(len > reach * (1 + 1e-9))) return true;  // overlapping balls: any direction
      for (double& x : w) x /= len;
      double half_angle = std::asin(std::min(1.0, reach / len));
      return bound.distance_lower_bound(w) - half_angle <= kMargin - kSlack;
    };
    // The cone from the ball around all of S holds every source's cone: most triangles
    // far from the beam are left out by one test instead of one per triangle of S.
    if (reaches(all_sources) && std::any_of(sources.begin(), sources.end(), reaches)) kept.push_back(t);
  }
  return kept;
}

}  // namespace gvm
