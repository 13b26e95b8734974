// Mesh points placed on integer lattices so that the B-rep's relations hold exactly: every
// point of a planar face on one plane n . p = const (n the face's class vector), every
// point of one ruling of a cylinder or extrusion on one line parallel to the class vector
// of its axis.
//
// The points are integers times 2^grid_exponent mm (a grid fine enough that a grid step
// is about 2^-50 of the part's size). A point takes the coordinates of one frame
// (exact_directions.h): its coordinate along axis a is a . p / |a|^2, and a planar face of
// class a fixes that coordinate for its points, a ruling of class c fixes the other two of
// c's frame. Coordinates fixed by several faces are one variable (a union-find over
// point coordinates, faces and rulings), whose value is rounded from the B-rep (a plane's
// offset) or from the points' positions (a ruling's). Then a point with three fixed
// coordinates is sum x_k a_k; with two, it is on their line at the grid point nearest its
// B-rep position; with one, on the plane's lattice; with none, rounded to the grid.
//
// What cannot hold exactly (a point on faces of two frames, such as an edge between a
// wall at 25 degrees and one along x) is kept as closely as the grid allows and reported
// as a miss, with the face and the distance.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "step/faithful/exact_directions.h"

namespace gvm::faithful {

struct PlacementProblem {
  int grid_exponent = 0;                    // one grid unit is 2^grid_exponent mm
  std::vector<std::array<double, 3>> target;  // each point's position on the B-rep, mm
  const ExactDirections* directions = nullptr;
  struct Plane {
    uint32_t cls = 0;                  // class of the normal
    std::array<double, 3> point{};     // a point of the B-rep plane, mm
    std::vector<uint32_t> points;
    uint32_t face = 0;                 // for reports
  };
  struct Ruling {
    uint32_t cls = 0;                  // class of the axis
    std::vector<uint32_t> points;      // on one line parallel to the axis
    uint32_t face = 0;
  };
  std::vector<Plane> planes;
  std::vector<Ruling> rulings;
};

// A relation not kept exactly, per face and kind.
struct Miss {
  uint32_t face = 0;
  bool ruling = false;     // a ruling's line, else the face's plane
  uint32_t points = 0;     // points off it
  double distance_mm = 0;  // the largest distance of one from it
};

struct Placement {
  std::vector<IVec> grid;           // per point, grid units
  double max_displacement_mm = 0;   // from the B-rep positions
  std::vector<Miss> misses;
};

Placement place_on_lattices(const PlacementProblem& problem);

}  // namespace gvm::faithful
