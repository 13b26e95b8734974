#include "step_loader/step_worker_messages.h"

#include "gvm/analysis_proto.h"

namespace gvm::step_internal {
namespace {

void set(v1::Vec3* out, const std::array<double, 3>& v) {
  out->set_x(v[0]);
  out->set_y(v[1]);
  out->set_z(v[2]);
}

std::array<double, 3> get(const v1::Vec3& v) { return {v.x(), v.y(), v.z()}; }

StatusOr<StepTessellation> take_tessellation(const v1::StepTessellation& m) {
  StepTessellation t;
  t.faithful = m.faithful();
  for (const auto& d : m.directions()) {
    if (d.exact_size() != 3) return Internal("STEP worker: a direction without three coordinates");
    t.directions.push_back({get(d.brep()), {d.exact(0), d.exact(1), d.exact(2)}, d.angle_radians(), d.cad_faces()});
  }
  t.max_direction_angle = m.max_direction_angle_radians();
  t.max_node_displacement = m.max_node_displacement_mm();
  t.grid = m.grid_mm();
  t.inserted_points = m.inserted_points();
  t.ruled_faces = m.ruled_faces();
  for (const auto& r : m.inexact()) t.inexact.push_back({r.cad_face(), r.ruling(), r.points(), r.distance_mm()});
  for (const auto& b : m.brepmesh_faces()) t.brepmesh_faces.emplace_back(b.cad_face(), b.reason());
  return t;
}

void put_part(const StepPart& part, v1::StepWorkerPart* out) {
  for (const Point3& p : part.mesh.points) {
    out->add_points(p.x);
    out->add_points(p.y);
    out->add_points(p.z);
  }
  for (const std::vector<uint32_t>& f : part.mesh.faces) {
    out->add_face_sizes(static_cast<uint32_t>(f.size()));
    for (uint32_t v : f) out->add_face_points(v);
  }
  for (uint32_t c : part.face_cad) out->add_face_cad(c);
  for (const CadFace& f : part.cad_faces) {
    v1::StepWorkerCadFace* m = out->add_cad_faces();
    m->set_index(f.index);
    m->set_type(static_cast<uint32_t>(f.type));
    if (f.axis) set(m->mutable_axis(), *f.axis);
    if (f.location) set(m->mutable_location(), *f.location);
    m->set_radius(f.radius);
  }
  for (const CadHole& h : part.holes) {
    v1::CadHole* m = out->add_holes();
    for (uint32_t f : h.faces) m->add_faces(f);
    set(m->mutable_axis(), h.axis);
    set(m->mutable_location(), h.location);
    m->set_radius(h.radius);
  }
  out->set_file_unit(part.file_unit);
  out->set_linear_deflection(part.linear_deflection);
  out->set_angular_deflection_degrees(part.angular_deflection_degrees);
  to_proto(part.tessellation, out->mutable_tessellation());
}

StatusOr<StepPart> take_part(const v1::StepWorkerPart& m) {
  StepPart part;
  if (m.points_size() % 3 != 0) return Internal("STEP worker: a point without three coordinates");
  for (int i = 0; i + 2 < m.points_size(); i += 3) part.mesh.points.push_back({m.points(i), m.points(i + 1), m.points(i + 2)});
  int next = 0;
  for (uint32_t size : m.face_sizes()) {
    if (size < 3 || next + static_cast<int64_t>(size) > m.face_points_size()) return Internal("STEP worker: a face out of range");
    std::vector<uint32_t> face;
    for (uint32_t k = 0; k < size; ++k, ++next) {
      const uint32_t v = m.face_points(next);
      if (v >= part.mesh.points.size()) return Internal("STEP worker: a face point out of range");
      face.push_back(v);
    }
    part.mesh.faces.push_back(std::move(face));
  }
  if (next != m.face_points_size() || m.face_cad_size() != static_cast<int>(part.mesh.faces.size())) {
    return Internal("STEP worker: faces and their B-rep faces do not match");
  }
  part.face_cad.assign(m.face_cad().begin(), m.face_cad().end());
  for (const auto& f : m.cad_faces()) {
    if (f.type() > static_cast<uint32_t>(CadSurfaceType::kOther)) return Internal("STEP worker: an unknown surface type");
    CadFace c;
    c.index = f.index();
    c.type = static_cast<CadSurfaceType>(f.type());
    if (f.has_axis()) c.axis = get(f.axis());
    if (f.has_location()) c.location = get(f.location());
    c.radius = f.radius();
    part.cad_faces.push_back(c);
  }
  for (uint32_t c : part.face_cad) {
    if (c >= part.cad_faces.size()) return Internal("STEP worker: a face of a B-rep face that does not exist");
  }
  for (const auto& h : m.holes()) {
    part.holes.push_back({{h.faces().begin(), h.faces().end()}, get(h.axis()), get(h.location()), h.radius()});
  }
  part.file_unit = m.file_unit();
  part.linear_deflection = m.linear_deflection();
  part.angular_deflection_degrees = m.angular_deflection_degrees();
  StatusOr<StepTessellation> t = take_tessellation(m.tessellation());
  if (!t.ok()) return t.status();
  part.tessellation = std::move(*t);
  return part;
}

}  // namespace

v1::StepWorkerRequest worker_request(std::string_view bytes, const StepOptions& options, const std::string& source) {
  v1::StepWorkerRequest r;
  r.set_data(std::string(bytes));
  r.set_source(source);
  r.set_linear_deflection(options.linear_deflection);
  r.set_angular_deflection_degrees(options.angular_deflection_degrees);
  r.set_solid(options.solid);
  r.set_group_holes(options.group_holes);
  r.set_max_triangles(options.max_triangles);
  r.set_faithful(options.faithful);
  return r;
}

StepOptions options_of(const v1::StepWorkerRequest& r) {
  StepOptions o;
  o.linear_deflection = r.linear_deflection();
  o.angular_deflection_degrees = r.angular_deflection_degrees();
  o.solid = r.solid();
  o.group_holes = r.group_holes();
  o.max_triangles = r.max_triangles();
  o.faithful = r.faithful();
  return o;
}

v1::StepWorkerReply worker_reply(const StatusOr<StepPart>& result) {
  v1::StepWorkerReply r;
  if (!result.ok()) {
    r.set_status_code(static_cast<uint32_t>(result.status().code()));
    r.set_message(result.status().message());
    return r;
  }
  put_part(*result, r.mutable_part());
  return r;
}

StatusOr<StepPart> result_of(const v1::StepWorkerReply& reply) {
  if (reply.status_code() == 0) return take_part(reply.part());
  if (reply.message().empty()) return Internal("STEP worker: an error without a message");
  return Status(static_cast<StatusCode>(reply.status_code()), reply.message());
}

}  // namespace gvm::step_internal
