// A ruled B-rep face (cylinder, cone, extrusion) for the faithful tessellation: its
// boundary in the face's (u, v) parameters, u across the rulings, the u of its boundary
// points grouped into rulings, the edge points that must be added so that every boundary
// segment joins neighbouring rulings, and the triangles between the rulings
// (faithful/ruled_strips.h).
#pragma once

#include <BRepAdaptor_Curve.hxx>
#include <Geom2d_Curve.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Cone.hxx>
#include <gp_Cylinder.hxx>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "step/faithful/ruled_strips.h"
#include "step/step_edge_points.h"
#include "step/step_face_boundary.h"
#include "step/step_internal.h"

namespace gvm::step_internal {

class RuledFace {
 public:
  // tolerance: mm; boundary points whose rulings are closer than that share one ruling, and
  // a B-rep vertex's ruling takes those within four times its tolerance (up to `cap`).
  RuledFace(const TopoDS_Face& face, const Weld& weld, double tolerance, double cap);

  // Groups the u of the boundary points (as the edges are discretised now) into rulings.
  void find_rulings(const Weld& weld);
  // The points each boundary segment that skips rulings needs, one per ruling skipped.
  void insertions(const Weld& weld, uint32_t face, std::vector<EdgeInsertion>& out) const;
  // Triangles between the rulings over welded points (roots), oriented as the face.
  bool strips(Weld& weld, std::vector<std::vector<uint32_t>>& out, std::string& why) const;
  // The points of each ruling (roots).
  std::vector<std::vector<uint32_t>> ruling_points(Weld& weld) const;

 private:
  struct Cluster {
    double lo, hi;  // the u of its members; hi - lo <= tolerance
  };
  std::pair<double, double> uv_at(const EdgeUse& use, double parameter, const gp_Pnt& p) const;
  std::pair<double, double> uv_of_node(const Weld& weld, const EdgeUse& use, uint32_t node) const;
  const BRepAdaptor_Curve& curve(const Weld& weld, int edge) const;
  int ruling_of(double u) const;  // -1: none
  bool strip_loop(const std::vector<LoopPoint>& loop, const std::vector<EdgeUse>& wire, Weld& weld,
                  std::vector<faithful::StripPoint>& out, std::string& why) const;
  bool parameter_of(const Weld& weld, const EdgeUse& use, double p0, double p1, double u, double& out) const;

  bool reversed_face_;
  std::optional<gp_Cylinder> cylinder_;
  std::optional<gp_Cone> cone_;
  std::vector<std::vector<EdgeUse>> wires_;
  mutable std::map<int, std::unique_ptr<BRepAdaptor_Curve>> curves_;
  double tol_u_, tol_vertex_u_;
  std::vector<Cluster> rulings_;
};

}  // namespace gvm::step_internal
