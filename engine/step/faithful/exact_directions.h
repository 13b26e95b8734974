// The directions a faithful tessellation keeps exactly: every plane normal and every axis
// of a ruled face of the B-rep (cylinders, extrusions), grouped into classes of parallel
// directions, each class given one integer vector close to it, and the classes that are
// orthogonal in the B-rep given exactly orthogonal vectors, grouped into frames.
//
// Why integers: a facet contains a hole's axis r exactly when two of its corners differ by
// an integer multiple of r, and two walls are parallel exactly when their points satisfy
// n . p = const for one integer n; both are then identities of integers that hold in the
// doubles the engine reads. The vectors are chosen small (components at most 2^20), so
// that the lattices they span stay fine (lattice_placement.h), and close: within 1e-7 rad
// of the B-rep's direction, usually far closer (a coordinate axis or a rational direction
// such as (2, -1, 2) exactly; a direction in a coordinate plane usually within 1e-10).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "step/faithful/int_vec.h"

namespace gvm::faithful {

using Dir3 = std::array<double, 3>;

// Directions closer than this (radians) are one class: parallel in the B-rep.
inline constexpr double kParallel = 1e-9;
// |cos| of the angle below which two B-rep directions count as orthogonal.
inline constexpr double kOrthogonal = 1e-9;

struct DirectionClass {
  Dir3 brep{};         // the first B-rep direction of the class (unit)
  IVec exact;          // canonical, primitive
  double angle = 0;    // the largest angle between `exact`'s line and a member's, radians
  uint32_t weight = 0;
};

// Three pairwise orthogonal canonical vectors. `real[k]` says whether axis k is a class
// (else it completes the frame).
struct Frame {
  std::array<IVec, 3> axis;
  std::array<bool, 3> real{};
};

struct ExactDirections {
  std::vector<DirectionClass> classes;
  std::vector<uint32_t> class_of;  // per input direction
  // frames[0] is the coordinate frame; every class is an axis of at least one frame.
  std::vector<Frame> frames;
};

// Classes, their exact vectors and frames for B-rep directions (unit vectors; sign does not
// matter) with weights (the number of faces each stands for: heavier classes are snapped
// first, so that the orthogonality they impose is the one kept).
ExactDirections exact_directions(const std::vector<Dir3>& directions, const std::vector<uint32_t>& weights);

// The angle (radians, in [0, pi/2]) between the lines of an integer vector and a direction.
double line_angle(const IVec& v, const Dir3& d);

// A reduced basis of the lattice of integer vectors orthogonal to the primitive vector a.
std::array<IVec, 2> orthogonal_lattice(const IVec& a);

// Small integer vectors along d: the first within 1e-13 rad (a rational direction), else the
// best with components at most 2^16 (typically within 6e-8 rad), or, when that is not within
// 9e-8 rad, the best up to 2^20: larger vectors make coarser lattices, so only when needed.
IVec snap_free(const Dir3& d);
// The integer vector orthogonal to a that is closest to d among those of norm at most 2^20
// (d nearly orthogonal to a): a two-dimensional approximation, usually within 1e-10 rad.
IVec snap_orthogonal(const Dir3& d, const IVec& a);

}  // namespace gvm::faithful
