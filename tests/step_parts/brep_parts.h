// Machined test parts built as exact B-reps with Open CASCADE's modelling API (boxes,
// cylinders, cones, Boolean cuts), optionally rotated, and written as STEP: through and
// blind holes, a counterbore, a countersink, a through slot, an L-bracket with holes on
// two axes, a hole whose axis is blocked at one end. Dimensions in mm; each part is built
// in its own frame (x, y, z) and then rotated by `rotation`, so that every expected
// direction is rotation * (a direction of the part's frame).
#pragma once

#include <array>
#include <string>

namespace gvm::test {

using Vec = std::array<double, 3>;
// Row-major orthogonal matrix with determinant 1.
using Rotation = std::array<std::array<double, 3>, 3>;

inline constexpr Rotation kIdentity = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
// Rational rotations, as exact fractions rounded to doubles: (1, 2, 2 | 2, 1, -2 | -2, 2,
// -1) / 3 turns every axis oblique; (5, 0, 0 | 0, 3, -4 | 0, 4, 3) / 5 is a turn about x.
inline constexpr Rotation kOblique = {{{1.0 / 3, 2.0 / 3, 2.0 / 3}, {2.0 / 3, 1.0 / 3, -2.0 / 3}, {-2.0 / 3, 2.0 / 3, -1.0 / 3}}};
inline constexpr Rotation kAboutX = {{{1, 0, 0}, {0, 0.6, -0.8}, {0, 0.8, 0.6}}};
// 25 degrees about (1, 2, 3): no rational direction near any axis.
Rotation generic_rotation();

Vec rotate(const Rotation& r, const Vec& v);

enum class Part {
  kThroughHole,   // 40 x 30 x 10 block, hole d8 along z at (20, 15)
  kBlindHole,     // the same block, hole d8 from the top, 6 deep, flat bottom
  kCounterbore,   // through hole d6, counterbore d12 4 deep from the top
  kCountersink,   // through hole d6, 90-degree countersink d12 at the top
  kThroughSlot,   // slot 8 wide (y 11..19), 4 deep from the top, along x through the block
  kLBracket,      // base 40 x 30 x 6 with a hole along z, upright 40 x 6 x 30 with one along y
  kBlockedHole,   // a through hole along z under a roof 10 mm above the block
};

const char* name_of(Part part);

// The part rotated, as the bytes of a STEP file (AP214).
std::string step_bytes(Part part, const Rotation& rotation);

}  // namespace gvm::test
