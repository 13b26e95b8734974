#include "io/sphere_proto.h"

namespace gvm::io {

void to_proto(const exact::ExactVec& direction, v1::Vec3* out) {
  const std::array<double, 3> u = direction.nearest_unit();
  out->set_x(u[0]);
  out->set_y(u[1]);
  out->set_z(u[2]);
}

void to_proto(const sphere::SphericalImage& image, v1::SphericalImage* out) {
  out->Clear();
  out->set_dimension(image.dimension());
  out->set_area(image.area());
  out->set_description(image.description());
  if (image.is_full_sphere()) {
    out->set_full_sphere(true);
    return;
  }
  for (const sphere::Face& f : image.faces()) {
    v1::SphericalPolygon* polygon = out->add_polygons();
    for (const sphere::Loop& l : f.loops) {
      v1::Loop* loop = polygon->add_loops();
      for (const sphere::Arc& a : l.arcs) {
        // Each arc's end is the next arc's start: written once.
        const std::vector<exact::ExactVec> v = sphere::split_arc_quarters(a);
        for (size_t i = 0; i + 1 < v.size(); ++i) to_proto(v[i], loop->add_vertices());
      }
    }
  }
  for (const sphere::Arc& a : image.curves()) {
    v1::SphericalArc* arc = out->add_arcs();
    for (const exact::ExactVec& v : sphere::split_arc_quarters(a)) to_proto(v, arc->add_vertices());
  }
  for (const exact::ExactVec& p : image.points()) to_proto(p, out->add_points());
}

}  // namespace gvm::io
