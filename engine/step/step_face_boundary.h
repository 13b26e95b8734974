// A B-rep face's boundary over the welded points, for the faithful tessellation: its wires
// as edge uses with the face's pcurves, and as closed loops of points. The loops follow the
// edges' connections, not only the orientations the B-rep states (a wire of one closed
// edge, or an inner wire, may state the opposite of how it runs); which way round a loop
// runs is then decided by the caller from areas.
#pragma once

#include <Geom2d_Curve.hxx>
#include <TopoDS_Face.hxx>

#include <cstdint>
#include <vector>

#include "step/step_internal.h"

namespace gvm::step_internal {

// One use of an edge in a face's wire, with the face's pcurve of it.
struct EdgeUse {
  int edge = -1;          // 0-based, Weld::edges order
  bool reversed = false;  // runs against the edge's parameter, as the wire states it
  bool degenerated = false;
  Handle(Geom2d_Curve) pcurve;
  double first = 0, last = 0;  // the edge's parameter range on the face
};

// The face's wires (the face taken forward), edges in the order the wire explorer gives.
std::vector<std::vector<EdgeUse>> face_wires(const TopoDS_Face& face, const Weld& weld);

struct LoopPoint {
  uint32_t id;    // welded point (root)
  uint32_t use;   // index into the wire
  uint32_t node;  // index into the edge's points
};

// Each wire as a closed loop of points (the last joins the first), every edge run in the
// direction that joins it to the next: in (u, v) when `by_uv` (the uses are then reordered
// in `wires`, so that LoopPoint::use indexes them as they are after the call), else in space.
std::vector<std::vector<LoopPoint>> boundary_loops(std::vector<std::vector<EdgeUse>>& wires, Weld& weld, bool by_uv);

}  // namespace gvm::step_internal
