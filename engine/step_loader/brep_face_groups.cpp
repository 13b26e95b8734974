// The names of CAD surface types and the face groups of a STEP part: plain data, no Open
// CASCADE, so built into the engine and into the STEP module alike (step/step_module.h).
#include <string>

#include "gvm/step.h"

namespace gvm {

std::string_view name_of(CadSurfaceType t) {
  switch (t) {
    case CadSurfaceType::kPlane: return "plane";
    case CadSurfaceType::kCylinder: return "cylinder";
    case CadSurfaceType::kCone: return "cone";
    case CadSurfaceType::kSphere: return "sphere";
    case CadSurfaceType::kTorus: return "torus";
    case CadSurfaceType::kBezier: return "bezier";
    case CadSurfaceType::kBSpline: return "bspline";
    case CadSurfaceType::kRevolution: return "revolution";
    case CadSurfaceType::kExtrusion: return "extrusion";
    case CadSurfaceType::kOffset: return "offset";
    case CadSurfaceType::kOther: return "other";
  }
  return "other";
}

std::map<std::string, std::vector<uint32_t>> brep_face_groups(const StepPart& part) {
  std::vector<std::string> name(part.cad_faces.size());
  for (const CadFace& cad : part.cad_faces)
    name[cad.index] = "face " + std::to_string(cad.index) + " (" + std::string(name_of(cad.type)) + ")";
  for (size_t h = 0; h < part.holes.size(); ++h) {
    std::string faces;
    for (uint32_t f : part.holes[h].faces) {
      if (!faces.empty()) faces += '+';
      faces += std::to_string(f);
    }
    for (uint32_t f : part.holes[h].faces) name[f] = "hole " + std::to_string(h) + " (faces " + faces + ")";
  }
  std::map<std::string, std::vector<uint32_t>> groups;
  for (uint32_t f = 0; f < part.face_cad.size(); ++f) groups[name[part.face_cad[f]]].push_back(f);
  return groups;
}

}  // namespace gvm
