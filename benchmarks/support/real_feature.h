// The real feature the micro-benchmarks of the global occlusion run on: of a shared part
// (occt_TR12J_OCC.stl, else trimesh_featuretype_from_step.off, or the file named by
// GVM_BENCH_PART, read from $GVM_SHARED_DIR/data/parts, else ../shared/data/parts relative
// to the working directory), the feature with the largest |S| * |O_S| below 300000
// (TR12J: feature 9, 80 x 3440), with its potential occluders, LVM and direction window.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gvm/part.h"
#include "sphere/spherical_image.h"
#include "visibility/direction_window.h"

namespace gvm::bench {

struct RealFeature {
  std::string error;  // set when there is no feature to benchmark
  std::optional<Part> part;
  uint32_t feature = 0;
  std::vector<uint32_t> s, o;
  sphere::SphericalImage lvm;
  std::unique_ptr<DirectionWindow> window;
};

// Loaded once, on first use.
const RealFeature& real_feature();

}  // namespace gvm::bench
