// Points the faithful tessellation adds on B-rep edges (so that a ruled face's rulings meet
// both of its rims), and BRepMesh's triangles cut along the edges that got them.
#pragma once

#include <TopoDS_Face.hxx>

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "step/step_internal.h"

namespace gvm::step_internal {

using Polygons = std::vector<std::vector<uint32_t>>;

// A point to add on an edge, by the edge curve's parameter.
struct EdgeInsertion {
  int edge;
  double parameter;
  uint32_t face;  // whose rulings ask for it
};

// The points (roots) along each edge as they are now: what BRepMesh's triangles use.
std::vector<std::vector<uint32_t>> edge_chains(Weld& weld);

// Adds the points on their edges in parameter order (one the other face asked for too is
// added once), noting which face asked for each; how many were new.
uint32_t insert_points(std::vector<EdgeInsertion>& insertions, Weld& weld, std::map<uint32_t, uint32_t>& asked_by);

// For each consecutive pair of an edge's points in `before` that got points between them:
// those points, from the first of the pair to the second (both directions keyed).
using Splits = std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>>;
Splits splits_of(const std::vector<std::vector<uint32_t>>& before, Weld& weld);

// BRepMesh's triangles with every edge that got points cut into a fan from the opposite
// corner.
Polygons fan_split(const Polygons& triangles, const Splits& splits, Weld& weld);

// Some edge of the face got points since `before`.
bool touches_splits(const TopoDS_Face& face, const Weld& weld, const std::vector<std::vector<uint32_t>>& before);

}  // namespace gvm::step_internal
