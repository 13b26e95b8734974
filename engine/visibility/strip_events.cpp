#include "visibility/strip_events.h"

#include <algorithm>
#include <array>

namespace gvm {
namespace {

using exact::ExactVec;

ExactVec point(const SolidMesh& mesh, uint32_t v) { return ExactVec::from_point(mesh.points[v]); }

ExactVec normal(const SolidMesh& mesh, uint32_t t) {
  const Triangle& tri = mesh.triangles[t];
  const ExactVec a = point(mesh, tri[0]);
  return exact::cross(point(mesh, tri[1]) - a, point(mesh, tri[2]) - a);
}

}  // namespace

std::vector<uint32_t> vertex_star(const SolidMesh& mesh, uint32_t t, int corner) {
  const uint32_t v = mesh.triangles[t][corner];
  std::vector<uint32_t> star;
  uint32_t current = t;
  do {
    star.push_back(current);
    const Triangle& tri = mesh.triangles[current];
    int i = 0;
    while (tri[i] != v) ++i;
    current = mesh.neighbor[current][i];  // across the edge (v, tri[i + 1])
  } while (current != t && star.size() <= mesh.triangles.size());
  return star;
}

std::vector<std::pair<StripPlane, std::vector<uint32_t>>> strip_planes(const SolidMesh& mesh,
                                                                      std::span<const uint32_t> triangles) {
  std::vector<std::pair<StripPlane, std::vector<uint32_t>>> planes;
  for (uint32_t fs : triangles) {
    const Triangle& tri = mesh.triangles[fs];
    auto same = [&](const StripPlane& p) {
      return exact::parallel(p.normal, normal(mesh, fs)) &&
             exact::sign_dot(p.normal, point(mesh, tri[0]) - p.origin) == Sign::kZero;
    };
    auto it = std::find_if(planes.begin(), planes.end(), [&](const auto& p) { return same(p.first); });
    if (it == planes.end()) it = planes.insert(planes.end(), {StripPlane{normal(mesh, fs), point(mesh, tri[0]), {}}, {}});
    it->second.push_back(fs);
    for (uint32_t v : tri) {
      if (std::find(it->first.corners.begin(), it->first.corners.end(), v) == it->first.corners.end()) {
        it->first.corners.push_back(v);
      }
    }
  }
  return planes;
}

namespace {

std::array<Sign, 3> sides(const SolidMesh& mesh, const StripPlane& plane, uint32_t t) {
  std::array<Sign, 3> side;
  for (int k = 0; k < 3; ++k) side[k] = exact::sign_dot(plane.normal, point(mesh, mesh.triangles[t][k]) - plane.origin);
  return side;
}

}  // namespace

bool touches(const SolidMesh& mesh, const StripPlane& plane, uint32_t t) {
  const std::array<Sign, 3> side = sides(mesh, plane, t);
  const auto has = [&](Sign s) { return std::find(side.begin(), side.end(), s) != side.end(); };
  return has(Sign::kZero) || (has(Sign::kPositive) && has(Sign::kNegative));
}

void add_strip_events(const SolidMesh& mesh, const StripPlane& plane, uint32_t t, std::vector<StripEvent>& out) {
  enum Kind : uint32_t { kFacePlane, kCorner, kEdgeCrossing, kStarEdge };
  const Triangle& tri = mesh.triangles[t];
  const ExactVec& n = plane.normal;
  const std::array<Sign, 3> side = sides(mesh, plane, t);
  std::array<ExactVec, 3> q;
  for (int k = 0; k < 3; ++k) q[k] = point(mesh, tri[k]);
  auto add = [&out](ExactVec d, std::array<uint32_t, 4> key) {
    if (!exact::is_zero(d)) out.push_back({std::move(d), key});
  };
  add(exact::cross(n, normal(mesh, t)), {kFacePlane, t, 0, 0});
  for (int k = 0; k < 3; ++k) {
    const uint32_t across = mesh.neighbor[t][k];
    add(exact::cross(n, normal(mesh, across)), {kFacePlane, across, 0, 0});
  }
  for (uint32_t corner : plane.corners) {
    const ExactVec p = point(mesh, corner);
    for (int k = 0; k < 3; ++k) {
      const int j = (k + 1) % 3;
      if (side[k] == Sign::kZero) add(q[k] - p, {kCorner, tri[k], corner, 0});
      if (side[k] != Sign::kZero && side[j] != Sign::kZero && side[k] != side[j]) {
        add(exact::cross(n, exact::cross(q[k] - p, q[j] - p)),
            {kEdgeCrossing, std::min(tri[k], tri[j]), std::max(tri[k], tri[j]), corner});
      }
    }
  }
  for (int k = 0; k < 3; ++k) {
    if (side[k] != Sign::kZero) continue;
    for (uint32_t f : vertex_star(mesh, t, k)) {
      add(exact::cross(n, normal(mesh, f)), {kFacePlane, f, 0, 0});
      for (uint32_t a : mesh.triangles[f]) {
        if (a != tri[k] && exact::sign_dot(n, point(mesh, a) - plane.origin) == Sign::kZero) {
          add(point(mesh, a) - q[k], {kStarEdge, std::min(a, tri[k]), std::max(a, tri[k]), 0});
        }
      }
    }
  }
}

}  // namespace gvm
