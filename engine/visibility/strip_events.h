// Rays in a plane of S: the directions where what they meet may change.
//
// For a triangle F_S of S and a direction u in its plane P, the rays from F_S along u sweep
// a planar strip. Whether the strip enters the solid through or around a triangle T of O
// (occlusion_probe.h says how that is decided) is constant while u turns in P, except at
// the directions where
//  - a side ray of the strip (from a corner p of F_S) passes an end of T's trace on P: a
//    corner q of T on P (q - p), or where an edge (a, b) of T crosses P
//    (n_P x ((a - p) x (b - p)));
//  - T, or a triangle across one of its edges, turns from being met from the front to not:
//    u . n = 0 (n_P x n);
//  - u crosses the cone of the solid at a corner of T on P: a plane of the corner's star
//    (n_P x n_F), or an edge of the star lying in P.
// So on an arc of directions in P the answer is constant between consecutive events.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "exact/exact_vec.h"
#include "gvm/mesh.h"

namespace gvm {

// The triangles around corner `corner` of triangle t (its vertex's star), t first, in
// order across the edges (v, next vertex of the current triangle).
std::vector<uint32_t> vertex_star(const SolidMesh& mesh, uint32_t t, int corner);

// A plane holding triangles of S, whose rays along directions in it sweep strips.
struct StripPlane {
  exact::ExactVec normal, origin;  // a normal and a point of the plane
  std::vector<uint32_t> corners;   // the distinct corners of its triangles of S
};

// The planes of `triangles` (triangles of S), each with the triangles in it.
std::vector<std::pair<StripPlane, std::vector<uint32_t>>> strip_planes(const SolidMesh& mesh,
                                                                      std::span<const uint32_t> triangles);

// Whether triangle t touches the plane (a corner on it, or corners on both sides): the
// strips in it never meet a triangle that does not.
bool touches(const SolidMesh& mesh, const StripPlane& plane, uint32_t t);

// An event as a line through the origin in the plane (the direction stands for itself
// and its opposite), with what it is built from: neighbouring triangles of O share most
// of their events (a corner, an edge, a face of a star), and equal keys are equal lines,
// found without exact arithmetic.
struct StripEvent {
  exact::ExactVec line;
  std::array<uint32_t, 4> key;  // a kind, then the vertices or triangle it is built from
};

// Appends the events of triangle t (which touches the plane); zero vectors are left out.
void add_strip_events(const SolidMesh& mesh, const StripPlane& plane, uint32_t t, std::vector<StripEvent>& out);

}  // namespace gvm
