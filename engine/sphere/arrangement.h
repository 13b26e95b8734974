// An exact arrangement of great-circle arcs on the sphere, with per-layer coverage of its
// faces: the structure in which LVM(S + N_S) and the projected occlusion are overlaid
// (paper Sec. 5.2). Every vertex is an exact direction (an input endpoint or an exact
// cross product of two circle normals), every decision an exact predicate.
//
// Each input arc carries a layer and a weight: the coverage of that layer on the arc's
// left exceeds the coverage on its right by the weight (a polygon's boundary walked
// counter-clockwise has weight 1). The caller gives one reference direction, on no arc,
// with its coverage in every layer; coverage then propagates across edges to all faces.
// Components of the arc graph that do not touch are joined by weightless bridge arcs, so
// that every face has a single boundary cycle and propagation reaches every face.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "exact/exact_vec.h"
#include "sphere/spherical_image.h"

namespace gvm::sphere {

struct ArrangementArc {
  exact::ExactVec from, to;   // distinct, less than 180 degrees apart
  exact::ExactVec normal;     // the arc runs counter-clockwise around it (from x to . normal > 0)
  int layer = 0;
  int weight = 0;
};

struct ArrangementPoint {
  exact::ExactVec p;
  int layer = 0;
};

class Arrangement {
 public:
  static constexpr int kMaxLayers = 8;

  struct Vertex {
    exact::ExactVec p;
    std::vector<uint32_t> out;    // outgoing half-edges, counter-clockwise around p
    uint32_t point_layers = 0;    // bit k: an input point of layer k is here
  };
  struct HalfEdge {
    uint32_t origin = 0, twin = 0, next = 0, face = 0, edge = 0;
    bool forward = true;          // runs along edge.v0 -> edge.v1
  };
  struct Edge {
    uint32_t v0 = 0, v1 = 0;
    exact::ExactVec normal;       // v0 -> v1 counter-clockwise around it
    int weight[kMaxLayers] = {};  // along v0 -> v1
    uint32_t arc_layers = 0;      // bit k: lies on an input arc of layer k
    bool bridge_only = true;      // made of bridges only
  };
  struct FaceInfo {
    uint32_t first_half_edge = 0;
    int coverage[kMaxLayers] = {};
  };

  Arrangement(std::span<const ArrangementArc> arcs, std::span<const ArrangementPoint> points,
              int layers, const exact::ExactVec& reference,
              std::span<const int> reference_coverage);

  const std::vector<Vertex>& vertices() const { return vertices_; }
  const std::vector<HalfEdge>& half_edges() const { return half_; }
  const std::vector<Edge>& edges() const { return edges_; }
  const std::vector<FaceInfo>& faces() const { return faces_; }

  // The closed set made of the cells (faces, edges, vertices) the predicates select, as
  // 2-, 1- and 0-cells: faces merged into polygons with holes, edges not bounding a
  // selected face into arcs, vertices on no selected edge into points. Boundaries are
  // canonical: consecutive arcs on one great circle are merged.
  SphericalImage extract(const std::function<bool(uint32_t face)>& face_in,
                         const std::function<bool(uint32_t edge)>& edge_in,
                         const std::function<bool(uint32_t vertex)>& vertex_in) const;

 private:
  void build(std::span<const ArrangementArc> arcs, std::span<const ArrangementPoint> points,
             const exact::ExactVec& reference);
  void link_half_edges();
  void label_faces(int layers, std::span<const int> reference_coverage);

  std::vector<Vertex> vertices_;
  std::vector<HalfEdge> half_;
  std::vector<Edge> edges_;
  std::vector<FaceInfo> faces_;
  uint32_t reference_vertex_ = 0;
};

}  // namespace gvm::sphere
