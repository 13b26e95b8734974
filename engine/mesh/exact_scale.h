// A part scaled by a power of two has the same exact predicates and the same directions:
// the engine works on the part scaled so that its largest coordinate lies in [1, 2), so
// that every filter sees the same doubles whatever the file's unit or scale (a part and
// its copy scaled by 2^k give identical maps, equally fast), and no filtered value of a
// predicate of high degree over- or underflows for a part of ordinary proportions.
#pragma once

#include <span>
#include <vector>

#include "gvm/geometry.h"

namespace gvm::mesh_internal {

// The k with the largest |coordinate| in [2^k, 2^(k+1)); 0 when every coordinate is zero.
int magnitude_exponent(std::span<const Point3> points);

// Multiplies every coordinate by 2^-k, exactly; false, leaving the points as they were,
// when a coordinate would lose bits (nonzero coordinates more than about 2^1000 apart).
bool scale_exactly(std::vector<Point3>& points, int k);

}  // namespace gvm::mesh_internal
