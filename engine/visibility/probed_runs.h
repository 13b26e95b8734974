// Runs of arrangement edges along one circle that the occlusion probe decides as one arc.
//
// The GVM's arrangement splits an arc of the LVM at every arc that crosses it: the
// occluded directions' boundary, seam candidates, other arcs of the LVM. Where the arc
// runs inside Int(GOM), each of its edges was probed on its own, and each vertex between
// two of them once more (prusa_extruder-idler: 319 such edges, 241 vertices shared by two
// of them); each probe enumerates the pairs of S and O near its arc, which costs about
// the same for a short arc as for a long one. The probe's answer for an open arc is the
// exact visible set of every direction in it, so one probe of a run decides its edges and
// the vertices inside it alike.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sphere/arrangement.h"
#include "sphere/spherical_image.h"

namespace gvm {

struct ProbedRun {
  std::vector<uint32_t> edges;  // along the run, in order
  std::vector<uint32_t> inner;  // the vertices between them (edges.size() - 1)
  sphere::Arc arc;              // from the first edge's start to the last one's end, shorter than 180 degrees
};

// The maximal runs of the selected edges (`selected[e]`) that continue one another along
// one circle through vertices where exactly two selected edges meet, cut where a run
// would reach 180 degrees. Every selected edge lies in exactly one run.
std::vector<ProbedRun> probed_runs(const sphere::Arrangement& arr, std::span<const uint8_t> selected);

}  // namespace gvm
