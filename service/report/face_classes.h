// What colour each face of the part gets in a report: the setup that reaches it, the
// unreachable warning, or neutral. Decided once, here, for both the interactive view and
// the static snapshots; the page reads the classes from the report's data.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gvm/v1/gvm.pb.h"
#include "gvm/v1/plan.pb.h"
#include "snapshot.h"

namespace gvm::report {

struct FaceClass {
  std::string label;                 // for the legend: "setup 2", "unreachable", ...
  std::string color;                 // "#rrggbb"
  std::optional<uint32_t> setup;     // the setup index, for setup classes
};

struct FaceClasses {
  std::vector<FaceClass> classes;
  std::vector<int32_t> face_class;       // per input face, an index into classes
  std::vector<int32_t> face_surface;     // per input face, the surface (feature or region) id, -1 for none
  std::vector<int32_t> surface_class;    // per surface id, an index into classes
};

// A plan report: one class per setup (in setup order), then "unreachable" and "not
// planned" when some face is so.
FaceClasses plan_classes(const v1::Analysis& analysis, const v1::Plan& plan, uint32_t input_faces);

// An analysis report: the features by what their GVM is (2-cells, arcs only, points only,
// empty, not computed), hull features neutral.
FaceClasses analysis_classes(const v1::Analysis& analysis, uint32_t input_faces);

// The colour of a face that is not the one selected: faded towards white.
std::string faded(const std::string& color);

// "#rrggbb" as its three bytes.
Rgb rgb_of(const std::string& color);

}  // namespace gvm::report
