// An independent brute-force visibility oracle for tests: is every ray p + t u (t > 0) from
// every sampled point p of a surface S free of transversal entry into the solid?
//
// It uses nothing of the engine beyond the mesh types (SolidMesh, Point3, Triangle): its own
// bounding volume hierarchy over all triangles and a double-precision ray/triangle test.
//
// Limits (read before trusting an answer):
//  - Double precision with ad-hoc tolerances: a ray that passes within ~1e-12 (relative) of
//    an edge or vertex, or meets a triangle at a nearly grazing angle, may be decided either
//    way. Grazing contact is meant to count as visible, so a ray running exactly along a
//    face or touching a silhouette edge may be misjudged. The oracle is therefore only meant
//    for directions u at an angular margin (e.g. 0.5 degrees) from the boundary of the GVM,
//    where the answer does not depend on such contacts.
//  - It samples S (a finite point set, see OracleOptions), so a direction that is blocked
//    only for a tiny part of S can be reported visible ("visible" is an upper bound; a
//    "blocked" answer comes with a witness ray and is reliable up to the tolerances).
//  - Sample points are moved into the interior of their triangle by a tiny relative amount
//    (`inset`), so that a ray that would leave a boundary point of S straight into the
//    material (touching a neighboring face only at t = 0) still meets that face at t > tmin.
//    Points of S stay points of S, so this cannot turn a truly visible direction blocked.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

#include "gvm/mesh.h"

namespace gvm::oracle {

struct OracleOptions {
  std::size_t max_points = 2000;   // cap on the sample points of one surface
  int max_grid = 8;                // barycentric grid subdivisions per triangle, at most
  double inset = 1e-5;             // barycentric inset of the sample points
  double tmin_relative = 1e-9;     // rays start at t > tmin = tmin_relative * box diagonal
  // A hit blocks iff u . n' < -front_tolerance * |n'| (n' the triangle's area normal).
  double front_tolerance = 1e-9;
  double barycentric_tolerance = 1e-12;  // hit inside iff all barycentrics > -this
  double self_tolerance = 1e-12;   // self-occlusion iff u . n_F < -this * |n_F| for F in S
  // A transversal hit from the back side blocks too: the ray was inside the solid before
  // it (it got in at a corner or an edge, which no front hit of a sampled ray shows).
  bool exits_block = false;
};

using Vec = std::array<double, 3>;

// BVH over all triangles of a mesh; reusable for many surfaces and directions. Keeps a
// reference to the mesh, which must outlive it.
class RayOracle {
 public:
  explicit RayOracle(const SolidMesh& mesh, OracleOptions options = {});

  // Deterministic sample points of S (triangle indices into the mesh): a barycentric grid on
  // every triangle (vertices, edge points and interior points) with the finest level
  // g <= max_grid such that |S| (g+1)(g+2)/2 <= max_points; when even g = 1 is too many,
  // the distinct vertices of S and the triangle centroids, thinned by a fixed stride.
  std::vector<Vec> sample_points(const std::vector<uint32_t>& s_triangles) const;

  // u must be a unit vector (the tolerances are relative to it).
  // False if some triangle of S faces away from u (self-occlusion), if a ray from a point
  // of S's border edges is blocked at once (below), or if a ray from one of `points` along
  // u is blocked; true otherwise.
  //
  // Border edges: sample points are inset, and near an edge where S meets a face F at a
  // concave angle the blocked part of S can be far thinner than any sampling (a 2 µm
  // strip of CAD face beside a wall). A ray from a point of that edge enters the solid at
  // once iff u . n_F < 0, which is decided here from the two planes directly.
  bool surface_visible(const std::vector<uint32_t>& s_triangles, const std::vector<Vec>& points,
                       const Vec& u) const;
  bool surface_visible(const std::vector<uint32_t>& s_triangles, const Vec& u) const {
    return surface_visible(s_triangles, sample_points(s_triangles), u);
  }

  // Rays from every point of S at once: some triangle F of the mesh, met from its front
  // side, and a triangle T of S overlap with positive area when projected along u, with F
  // ahead of T there. This catches blocked parts of S far thinner than any sampling
  // (a shadow edge that just clips a corner of S); candidates come from the BVH.
  bool any_ray_blocked(const std::vector<uint32_t>& s_triangles, const Vec& u) const;

  // The ray p + t u (t > tmin) meets some triangle transversally from its front side (or
  // either side, with exits_block); the first such triangle found is returned in *hit
  // when not null.
  bool ray_blocked(const Vec& p, const Vec& u, uint32_t* hit = nullptr) const;

  double tmin() const { return tmin_; }
  const OracleOptions& options() const { return options_; }

 private:
  struct Node {
    Vec lo, hi;
    uint32_t first = 0, count = 0;  // leaf: range in order_; inner: count == 0
    uint32_t left = 0, right = 0;
  };
  uint32_t build(uint32_t first, uint32_t count, std::vector<Vec>& centroids);

  const SolidMesh& mesh_;
  OracleOptions options_;
  double tmin_ = 0;
  std::vector<Node> nodes_;
  std::vector<uint32_t> order_;     // triangle indices, leaves index ranges of this
  std::vector<Vec> normal_;         // area normal (b-a) x (c-a) of each triangle
  // For each directed edge (a, b) of a triangle: the triangle across it.
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> across_;
};

// One-shot convenience: builds the BVH, samples S and decides visibility along u.
bool surface_visible(const SolidMesh& mesh, const std::vector<uint32_t>& s_triangles,
                     const std::array<double, 3>& u, const OracleOptions& options = {});

}  // namespace gvm::oracle
