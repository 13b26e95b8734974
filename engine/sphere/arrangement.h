// An exact arrangement of great-circle arcs on the sphere, with per-layer coverage of its
// faces: the structure in which LVM(S + N_S) and the projected occlusion are overlaid
// (paper Sec. 5.2), and in which the set operations and the N-way coverage overlay
// overlay their operands. Every vertex is an exact direction (an input endpoint or an
// exact cross product of two circle normals), every decision an exact predicate.
//
// Each input arc carries a layer and a weight: the coverage of that layer on the arc's
// left exceeds the coverage on its right by the weight (a polygon's boundary walked
// counter-clockwise has weight 1). Any number of layers: what lies on an edge or a vertex
// is stored sparsely, one (layer, summed weight) entry per layer that has an arc there
// (a zero sum still marks the edge as lying on that layer: curves are weight-0 arcs).
// Components of the arc graph that do not touch are joined by weightless bridge arcs, so
// that every face has a single boundary cycle and a walk across edges reaches every face.
//
// Face coverage is optional: the caller who wants it gives the number of layers and the
// coverage of every layer at a reference direction (on no arc and no point), and it is
// propagated across edges into one dense faces x layers array -- meant for the engine's
// one or two layers on arrangements of millions of vertices. With many layers (the
// coverage overlay) build the geometry only and walk the faces yourself.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "exact/exact_vec.h"
#include "sphere/spherical_image.h"

namespace gvm::sphere {

struct ArrangementArc {
  exact::ExactVec from, to;   // distinct, less than 180 degrees apart
  exact::ExactVec normal;     // the arc runs counter-clockwise around it (from x to . normal > 0)
  int layer = 0;              // >= 0; negative for the arrangement's own bridges
  int weight = 0;
};

struct ArrangementPoint {
  exact::ExactVec p;
  int layer = 0;              // >= 0
};

// One layer's arcs on an edge: their weights summed along the edge's v0 -> v1.
struct LayerWeight {
  int layer = 0;
  int weight = 0;
};

class Arrangement {
 public:
  struct Vertex {
    exact::ExactVec p;
    std::vector<uint32_t> out;    // outgoing half-edges, counter-clockwise around p
  };
  struct HalfEdge {
    uint32_t origin = 0, twin = 0, next = 0, face = 0, edge = 0;
    bool forward = true;          // runs along edge.v0 -> edge.v1
  };
  struct Edge {
    uint32_t v0 = 0, v1 = 0;
    exact::ExactVec normal;       // v0 -> v1 counter-clockwise around it
  };
  struct FaceInfo {
    uint32_t first_half_edge = 0; // UINT32_MAX for the whole sphere (no arcs)
  };

  // The geometry only (vertices, edges, faces, what lies on each edge and vertex); no
  // face coverage. `reference` lies on no arc and no point; it becomes a vertex.
  Arrangement(std::span<const ArrangementArc> arcs, std::span<const ArrangementPoint> points,
              const exact::ExactVec& reference);
  // The geometry and the coverage of every face in the layers 0 .. layers - 1, from their
  // values at `reference` (arcs of higher layers are in the geometry, unlabelled).
  Arrangement(std::span<const ArrangementArc> arcs, std::span<const ArrangementPoint> points,
              int layers, const exact::ExactVec& reference,
              std::span<const int> reference_coverage);

  const std::vector<Vertex>& vertices() const { return vertices_; }
  const std::vector<HalfEdge>& half_edges() const { return half_; }
  const std::vector<Edge>& edges() const { return edges_; }
  const std::vector<FaceInfo>& faces() const { return faces_; }

  // The layers of the arcs on edge e, ascending and distinct, with their summed weights.
  std::span<const LayerWeight> edge_layers(uint32_t e) const {
    return {edge_layer_.data() + edge_layer_begin_[e], edge_layer_.data() + edge_layer_begin_[e + 1]};
  }
  bool edge_on_layer(uint32_t e, int k) const;
  // The weight of layer k along v0 -> v1 (0 when no arc of layer k is on e).
  int edge_weight(uint32_t e, int k) const;
  // Made of the arrangement's bridges only (no input arc lies on it).
  bool is_bridge(uint32_t e) const { return edge_layer_begin_[e] == edge_layer_begin_[e + 1]; }
  // The layers of the input points at vertex v, ascending and distinct.
  std::span<const int> vertex_points(uint32_t v) const {
    return {point_layer_.data() + point_layer_begin_[v], point_layer_.data() + point_layer_begin_[v + 1]};
  }
  bool vertex_has_point(uint32_t v, int k) const;

  // Pairs of arcs whose boxes overlapped, and of a vertex and a representative of a
  // direction, compared exactly (over the builds, bridges included): a measure of the work.
  uint64_t compared_pairs() const { return compared_pairs_; }

  // The vertex at the reference direction, and the face around it.
  uint32_t reference_vertex() const { return reference_vertex_; }
  uint32_t reference_face() const;

  // Number of layers labelled (0 for a geometry-only build) and the coverage of layer k
  // (below that number) on face f.
  int labelled_layers() const { return layers_; }
  int coverage(uint32_t f, int k) const { return coverage_[size_t(f) * size_t(layers_) + size_t(k)]; }

  // The closed set made of the cells (faces, edges, vertices) the predicates select, as
  // 2-, 1- and 0-cells: faces merged into polygons with holes, edges not bounding a
  // selected face into arcs, vertices on no selected edge into points. Boundaries are
  // canonical: consecutive arcs on one great circle are merged.
  SphericalImage extract(const std::function<bool(uint32_t face)>& face_in,
                         const std::function<bool(uint32_t edge)>& edge_in,
                         const std::function<bool(uint32_t vertex)>& vertex_in) const;

 private:
  // What the arcs and points put on edges and vertices, recorded while splitting and
  // indexed once, after the bridges are in.
  struct Contribution {
    uint32_t edge;
    int layer, weight;  // weight along the edge's v0 -> v1
  };
  struct Recorded {
    std::vector<Contribution> on_edges;
    std::vector<std::pair<uint32_t, int>> points;  // (vertex, layer)
  };
  void build_with_bridges(std::span<const ArrangementArc> arcs,
                          std::span<const ArrangementPoint> points, const exact::ExactVec& reference);
  // Pairs of vertices whose bridges join every component of the arc graph.
  std::vector<std::pair<uint32_t, uint32_t>> bridges() const;
  Recorded build(std::span<const ArrangementArc> arcs, std::span<const ArrangementPoint> points,
                 const exact::ExactVec& reference);
  void index_layers(Recorded recorded);
  void link_half_edges();
  void label_faces(int layers, std::span<const int> reference_coverage);

  std::vector<Vertex> vertices_;
  std::vector<HalfEdge> half_;
  std::vector<Edge> edges_;
  std::vector<FaceInfo> faces_;
  uint32_t reference_vertex_ = 0;
  uint64_t compared_pairs_ = 0;
  // Compressed rows: the layers on edge e are edge_layer_[edge_layer_begin_[e] ..
  // edge_layer_begin_[e + 1]), the point layers of vertex v likewise.
  std::vector<uint32_t> edge_layer_begin_;
  std::vector<LayerWeight> edge_layer_;
  std::vector<uint32_t> point_layer_begin_;
  std::vector<int> point_layer_;
  int layers_ = 0;
  std::vector<int> coverage_;  // faces x layers_, row-major
};

}  // namespace gvm::sphere
