// The static pictures of a report: the part seen along given directions, rendered when
// the report is written (so it prints, and needs no WebGL), as inlined PNG figures.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "face_classes.h"
#include "gvm/mesh.h"

namespace gvm::report {

struct StaticView {
  std::string caption;
  std::array<double, 3> toward_viewer;   // the viewer sits on this side of the part
  std::optional<int32_t> highlight;      // this class keeps its colour, the rest fade
  std::optional<uint32_t> setup;         // written as data-setup
};

// <figure class="snapshot"> elements, one per view, rendered in parallel.
std::string static_views(const SolidMesh& mesh, const FaceClasses& classes, const std::vector<StaticView>& views);

}  // namespace gvm::report
