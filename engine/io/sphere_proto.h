// The proto edge for the sphere module's cells (engine internals and tests).
#pragma once

#include "gvm/v1/gvm.pb.h"
#include "sphere/spherical_image.h"

namespace gvm::io {

// Loops and arcs are written with every piece at most 90 degrees long (vertices added
// exactly on the circle, then rounded), so the doubles decide each piece unambiguously.
void to_proto(const sphere::SphericalImage& image, v1::SphericalImage* out);
void to_proto(const exact::ExactVec& direction, v1::Vec3* out);

}  // namespace gvm::io
