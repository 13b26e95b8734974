// The STEP tessellation's report as gvm.v1.StepTessellation: for the analysis message and
// for the STEP worker's reply (compiled into both).
#include "gvm/analysis_proto.h"

namespace gvm {

void to_proto(const StepTessellation& t, v1::StepTessellation* out) {
  out->set_faithful(t.faithful);
  for (const ExactDirection& d : t.directions) {
    v1::StepTessellation::ExactDirection* m = out->add_directions();
    m->mutable_brep()->set_x(d.brep[0]);
    m->mutable_brep()->set_y(d.brep[1]);
    m->mutable_brep()->set_z(d.brep[2]);
    for (int64_t c : d.exact) m->add_exact(c);
    m->set_angle_radians(d.angle);
    m->set_cad_faces(d.faces);
  }
  out->set_max_direction_angle_radians(t.max_direction_angle);
  out->set_max_node_displacement_mm(t.max_node_displacement);
  out->set_grid_mm(t.grid);
  out->set_inserted_points(t.inserted_points);
  out->set_ruled_faces(t.ruled_faces);
  for (const InexactRelation& r : t.inexact) {
    v1::StepTessellation::InexactRelation* m = out->add_inexact();
    m->set_cad_face(r.cad_face);
    m->set_ruling(r.ruling);
    m->set_points(r.points);
    m->set_distance_mm(r.distance_mm);
  }
  for (const auto& [face, why] : t.brepmesh_faces) {
    v1::StepTessellation::BrepMeshFace* m = out->add_brepmesh_faces();
    m->set_cad_face(face);
    m->set_reason(why);
  }
}

}  // namespace gvm
