#include "gvm/analysis_proto.h"

#include <google/protobuf/util/json_util.h>

#include "exact/exact_vec.h"
#include "io/sphere_proto.h"

namespace gvm {
namespace {

void set(v1::Vec3* out, const Point3& p) {
  out->set_x(p.x);
  out->set_y(p.y);
  out->set_z(p.z);
}

void fill_info(const SurfaceMaps& maps, v1::SurfaceInfo* info) {
  const SurfaceStatistics& s = maps.statistics;
  info->set_gvm_status(to_proto(maps.status));
  info->set_neighbor_occluders(s.neighbor_occluders);
  info->set_potential_occluders(s.potential_occluders);
  info->set_seconds(s.seconds);
  if (s.envelope_ran) {
    info->set_envelope_border_arcs(s.envelope_border_arcs);
    info->set_envelope_faces(s.envelope_faces);
    info->set_envelope_patches(s.envelope_patches);
    info->set_first_pass_occluders(s.first_pass_occluders);
  }
  if (s.pairwise_ran) {
    info->set_pairwise_maps(s.pairwise_maps);
    info->set_pairwise_map_arcs(s.pairwise_map_arcs);
  }
  if (s.envelope_ran || s.pairwise_ran) {
    info->set_arrangement_vertices(s.arrangement_vertices);
    info->set_occluded_boundary_arcs(s.occluded_boundary_arcs);
  }
}

// The faces, maps and facts of one surface, into a Region or a Feature message.
template <class Msg>
void fill_surface(const Surface& s, Msg* msg) {
  for (uint32_t f : s.faces) msg->add_faces(f);
  to_proto(s.maps.lvm, msg->mutable_lvm());
  if (s.maps.gvm) to_proto(*s.maps.gvm, msg->mutable_gvm());
  fill_info(s.maps, msg->mutable_info());
}

}  // namespace

void to_proto(const PartSummary& p, v1::PartSummary* out) {
  out->set_source(p.source);
  out->set_input_faces(p.input_faces);
  out->set_input_vertices(p.input_vertices);
  out->set_triangles(p.triangles);
  out->set_shells(p.shells);
  out->set_void_shells(p.void_shells);
  out->set_hull_faces(p.hull_faces);
  set(out->mutable_bounding_box()->mutable_min(), p.box_min);
  set(out->mutable_bounding_box()->mutable_max(), p.box_max);
  out->set_validation("valid");
  out->set_file_unit(p.file_unit);
  out->set_cad_faces(p.cad_faces);
  out->set_linear_deflection(p.linear_deflection);
  out->set_angular_deflection_degrees(p.angular_deflection_degrees);
  if (p.cad_faces > 0) to_proto(p.tessellation, out->mutable_step_tessellation());
}

namespace {

void fill_cad_face(const CadFace& f, v1::CadFace* out) {
  out->set_index(f.index);
  out->set_surface_type(std::string(name_of(f.type)));
  if (f.axis) set(out->mutable_axis(), {(*f.axis)[0], (*f.axis)[1], (*f.axis)[2]});
  if (f.location) set(out->mutable_location(), {(*f.location)[0], (*f.location)[1], (*f.location)[2]});
  out->set_radius(f.radius);
}

void fill_cad_hole(const CadHole& h, v1::CadHole* out) {
  for (uint32_t f : h.faces) out->add_faces(f);
  set(out->mutable_axis(), {h.axis[0], h.axis[1], h.axis[2]});
  set(out->mutable_location(), {h.location[0], h.location[1], h.location[2]});
  out->set_radius(h.radius);
}

void fill_timing(const AnalysisTiming& t, v1::Timing* out) {
  out->set_read_seconds(t.read);
  out->set_validate_seconds(t.validate);
  out->set_part_seconds(t.part);
  out->set_visibility_seconds(t.visibility);
  out->set_total_seconds(t.total);
  out->set_threads(t.threads);
}

}  // namespace

v1::GvmStatus to_proto(GvmStatus status) {
  switch (status) {
    case GvmStatus::kExactNoPotentialOccluders:
      return v1::GVM_STATUS_EXACT_NO_POTENTIAL_OCCLUDERS;
    case GvmStatus::kGlobalOcclusionNotComputed:
      return v1::GVM_STATUS_GLOBAL_OCCLUSION_NOT_COMPUTED;
    case GvmStatus::kEmptyVoid:
      return v1::GVM_STATUS_EMPTY_VOID;
    case GvmStatus::kGlobalOcclusionComputed:
      return v1::GVM_STATUS_GLOBAL_OCCLUSION_COMPUTED;
  }
  return v1::GVM_STATUS_UNSPECIFIED;
}

void to_proto(const DirectionSet& set, v1::SphericalImage* out) { io::to_proto(set.image(), out); }

void to_proto(const Direction& d, v1::Vec3* out) { io::to_proto(d.exact(), out); }

v1::Analysis to_proto(const Analysis& analysis) {
  v1::Analysis out;
  out.set_engine_version(GVM_VERSION);
  to_proto(analysis.part(), out.mutable_part());
  for (const Surface& r : analysis.regions()) {
    v1::Region* msg = out.add_regions();
    msg->set_id(r.id);
    msg->set_is_void(r.is_void);
    fill_surface(r, msg);
    for (uint32_t f : r.features) msg->add_features(f);
  }
  for (const Surface& f : analysis.features()) {
    v1::Feature* msg = out.add_features();
    msg->set_id(f.id);
    msg->set_name(f.name);
    msg->set_on_hull(f.on_hull);
    msg->set_region(f.region);
    if (f.cad_face) fill_cad_face(*f.cad_face, msg->mutable_cad_face());
    if (f.cad_hole) fill_cad_hole(*f.cad_hole, msg->mutable_cad_hole());
    fill_surface(f, msg);
  }
  fill_timing(analysis.timing(), out.mutable_timing());
  v1::Statistics* stats = out.mutable_statistics();
  stats->set_regions(static_cast<uint32_t>(analysis.regions().size()));
  stats->set_features(static_cast<uint32_t>(analysis.features().size()));
  stats->set_surfaces_with_potential_occluders(analysis.surfaces_with_potential_occluders());
  return out;
}

std::string to_json(const google::protobuf::Message& message) {
  google::protobuf::util::JsonPrintOptions options;
  options.add_whitespace = true;
  options.always_print_primitive_fields = true;
  std::string out;
  // Serializing a message we built ourselves cannot fail.
  (void)google::protobuf::util::MessageToJsonString(message, &out, options);
  return out;
}

}  // namespace gvm
