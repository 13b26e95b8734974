#include "analysis_report.h"

#include <iomanip>
#include <sstream>
#include <string>

namespace gvm {
namespace {

std::string map_line(const v1::SphericalImage& map) {
  std::ostringstream s;
  s << map.description();
  if (map.dimension() == 2) s << " [" << std::fixed << std::setprecision(4) << map.area() << " sr]";
  return s.str();
}

std::string gvm_line(const v1::SphericalImage& gvm, const v1::SurfaceInfo& info) {
  switch (info.gvm_status()) {
    case v1::GVM_STATUS_EXACT_NO_POTENTIAL_OCCLUDERS:
      return "GVM = LVM(S + N_S) exactly (O_S is empty)";
    case v1::GVM_STATUS_EMPTY_VOID:
      return "GVM empty (faces of an internal void)";
    case v1::GVM_STATUS_GLOBAL_OCCLUSION_COMPUTED:
      return "GVM: " + map_line(gvm) + "  (#GOM " +
             std::to_string(info.envelope_border_arcs() + info.pairwise_map_arcs()) +
             ", #Arrng " + std::to_string(info.arrangement_vertices()) + ")";
    case v1::GVM_STATUS_GLOBAL_OCCLUSION_NOT_COMPUTED:
      return "GVM not computed (--lvm-only); LVM(S + N_S) is an outer bound";
    default:
      return gvm.description();
  }
}

template <class Msg>
void print_surface(const Msg& m, const std::string& label, std::ostream& out) {
  out << "  " << std::left << std::setw(18) << label << " faces " << std::setw(6)
      << m.faces_size() << " |N_S| " << std::setw(5) << m.info().neighbor_occluders()
      << " |O_S| " << std::setw(6) << m.info().potential_occluders() << "\n"
      << "      LVM(S + N_S): " << map_line(m.lvm()) << "\n"
      << "      " << gvm_line(m.gvm(), m.info()) << "\n";
}

}  // namespace

std::string step_line(const v1::PartSummary& part) {
  if (part.cad_faces() == 0) return "";
  std::ostringstream line;
  line << "  STEP: " << part.cad_faces() << " B-rep faces, file unit " << part.file_unit()
       << " (coordinates in mm), tessellated at " << part.linear_deflection() << " mm and "
       << part.angular_deflection_degrees() << " deg\n"
       << "  tessellation: " << tessellation_text(part.step_tessellation()) << "\n";
  return line.str();
}

std::string tessellation_text(const v1::StepTessellation& t) {
  if (!t.faithful()) return "BRepMesh's triangles as they are (--brepmesh-only)";
  std::ostringstream s;
  s << "faithful: " << t.directions_size() << " B-rep directions kept exactly (" << std::setprecision(2);
  if (t.max_direction_angle_radians() == 0) s << "as the B-rep gives them";
  else s << "within " << t.max_direction_angle_radians() << " rad of the B-rep's";
  s << "), " << t.ruled_faces()
    << " ruled faces meshed along their rulings, points moved at most " << t.max_node_displacement_mm() << " mm";
  if (t.inexact_size() > 0) {
    double worst = 0;
    for (const auto& r : t.inexact()) worst = std::max(worst, r.distance_mm());
    s << "; " << t.inexact_size() << " relations kept within " << worst << " mm only (where faces of two frames meet)";
  }
  if (t.brepmesh_faces_size() > 0) {
    s << "; " << t.brepmesh_faces_size() << " faces as BRepMesh made them (face " << t.brepmesh_faces(0).cad_face()
      << ": " << t.brepmesh_faces(0).reason() << (t.brepmesh_faces_size() > 1 ? "; ..." : "") << ")";
  }
  return s.str();
}

void print_report(const v1::Analysis& a, std::ostream& out) {
  const v1::PartSummary& p = a.part();
  out << "Part " << p.source() << "\n" << step_line(p)
      << "  " << p.input_faces() << " faces (" << p.triangles() << " triangles), "
      << p.input_vertices() << " vertices, " << p.shells() << " shell(s)";
  if (p.void_shells() > 0) out << " of which " << p.void_shells() << " internal void(s)";
  out << ", " << p.hull_faces() << " faces on the convex hull\n";
  const auto& lo = p.bounding_box().min();
  const auto& hi = p.bounding_box().max();
  out << "  bounding box (" << lo.x() << ", " << lo.y() << ", " << lo.z() << ") - (" << hi.x()
      << ", " << hi.y() << ", " << hi.z() << ")\n"
      << "  validation: " << p.validation() << "\n"
      << "Directions are those along which rays leave the surface (a tool approaches along -u).\n\n";

  out << "Concave regions: " << a.regions_size() << "\n";
  for (const v1::Region& r : a.regions()) {
    std::string label = "R";  // appended: GCC 12 warns falsely on "R" + std::string
    label += std::to_string(r.id()) + (r.is_void() ? " (void)" : "");
    print_surface(r, label, out);
  }
  out << "\nFeatures: " << a.features_size() << "\n";
  for (const v1::Feature& f : a.features()) {
    std::string label = f.name() + (f.on_hull() ? " (hull)" : " (R" + std::to_string(f.region()) + ")");
    print_surface(f, label, out);
  }
  const v1::Timing& t = a.timing();
  out << "\nTiming: read " << std::fixed << std::setprecision(3) << t.read_seconds()
      << " s, validate " << t.validate_seconds() << " s, regions/features/occluders "
      << t.part_seconds() << " s, visibility maps " << t.visibility_seconds() << " s on "
      << t.threads() << " thread(s), total " << t.total_seconds() << " s\n";
}

}  // namespace gvm
