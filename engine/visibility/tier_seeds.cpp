#include "visibility/tier_seeds.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "visibility/face_tree.h"

namespace gvm {
namespace {

using sphere::D3;

// The directions of a Fibonacci lattice with about `count` points per `area` steradians
// that lie within acos(min_cos) of `pole`.
std::vector<D3> lattice_in_cap(const D3& pole, double min_cos, double area, size_t count) {
  const size_t n = std::min<size_t>(size_t{1} << 22, static_cast<size_t>(count * 4 * M_PI / area) + 1);
  const D3 helper = std::abs(pole[0]) < 0.6 ? D3{1, 0, 0} : D3{0, 1, 0};
  const D3 e1 = sphere::normalized(sphere::cross(pole, helper)), e2 = sphere::cross(pole, e1);
  const double golden = M_PI * (3 - std::sqrt(5.0));
  std::vector<D3> out;
  for (size_t i = 0; i < n; ++i) {
    const double z = 1 - (2 * i + 1.0) / n;  // the lattice's rows go down from the pole
    if (z < min_cos) break;
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    const double c = r * std::cos(golden * static_cast<double>(i)), s = r * std::sin(golden * static_cast<double>(i));
    out.push_back({z * pole[0] + c * e1[0] + s * e2[0], z * pole[1] + c * e1[1] + s * e2[1],
                   z * pole[2] + c * e1[2] + s * e2[2]});
  }
  return out;
}

// A cap around the vertices of `needed` (a pole and the cosine of its radius), or the
// whole sphere (-1) for curves, points, full circles and anything near a hemisphere.
std::pair<D3, double> cap_around(const sphere::SphericalImage& needed) {
  std::vector<D3> corners;
  bool whole = needed.is_full_sphere() || !needed.curves().empty() || !needed.points().empty();
  for (const sphere::Face& f : needed.faces()) {
    for (const sphere::Loop& loop : f.loops) {
      for (const sphere::Arc& arc : loop.arcs) {
        whole = whole || arc.full;
        if (!arc.full) corners.push_back(exact::unit_estimate(arc.start).unit);
      }
    }
  }
  D3 pole{0, 0, 0};
  for (const D3& c : corners) pole = sphere::add(pole, c);
  if (whole || !(sphere::norm(pole) > 1e-3)) return {{0, 0, 1}, -1};
  pole = sphere::normalized(pole);
  double min_cos = 1;
  for (const D3& c : corners) min_cos = std::min(min_cos, sphere::dot(pole, c));
  // A convex face within a cap of less than 90 degrees lies inside it, its sides too.
  return {pole, min_cos > 0.01 ? min_cos - 1e-6 : -1};
}

// The inward unit normals of `needed` when it is one convex face, else none.
std::vector<D3> convex_sides(const sphere::SphericalImage& needed) {
  std::vector<D3> sides;
  if (needed.faces().size() != 1 || !needed.faces()[0].convex || !needed.curves().empty() ||
      !needed.points().empty()) {
    return sides;
  }
  for (const sphere::Loop& loop : needed.faces()[0].loops) {
    for (const sphere::Arc& arc : loop.arcs) sides.push_back(exact::unit_estimate(arc.normal).unit);
  }
  return sides;
}

}  // namespace

std::vector<uint32_t> tier_seeds(std::span<const FaceEstimate> faces, std::span<const uint32_t> largest,
                                 std::span<const uint32_t> rest, const sphere::SphericalImage& needed,
                                 size_t samples) {
  const FaceTree first(faces, largest), others(faces, rest);
  const double area = needed.is_full_sphere() ? 4 * M_PI : needed.area();
  if (others.empty() || !(area > 0)) return {};
  const auto [pole, min_cos] = cap_around(needed);
  // A direction outside `needed` (certainly, when it is convex) asks for no face.
  const std::vector<D3> sides = convex_sides(needed);
  auto outside = [&](const D3& x) {
    return std::any_of(sides.begin(), sides.end(), [&](const D3& n) { return sphere::dot(n, x) < -kSlack; });
  };
  // Box tests allowed per face of `rest`: the Prusa parts' surfaces take 60-120.
  constexpr size_t kTestsPerFace = 512;
  size_t tested = 0;
  std::vector<uint32_t> seeds;
  for (const D3& x : lattice_in_cap(pole, min_cos, area, samples)) {
    if (outside(x) || first.holds(x)) continue;
    if (tested > kTestsPerFace * rest.size()) {
      // A guard against sliver faces over a wide LVM, thousands of boxes around each
      // direction (the pocket floor of gvm_make_pocket_part, which TierPolicy::seed_until
      // keeps out): the seeds found so far order the faces; the tiers do the rest.
      spdlog::debug("tier seeds: budget of {} box tests spent, {} seeds", tested, seeds.size());
      break;
    }
    const int64_t best = others.largest_holding(x, tested);
    if (best >= 0 && (!sides.empty() || needed.contains(exact::ExactVec::from_point({x[0], x[1], x[2]})))) {
      seeds.push_back(static_cast<uint32_t>(best));
    }
  }
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  return seeds;
}

}  // namespace gvm
