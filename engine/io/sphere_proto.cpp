#include "io/sphere_proto.h"

#include <algorithm>
#include <array>
#include <vector>

namespace gvm::io {
namespace {

using Vertex = std::array<double, 3>;
using Chain = std::vector<Vertex>;

// The written vertices of a loop: each arc in pieces of at most 90 degrees, each arc's
// end being the next one's start (written once).
Chain loop_vertices(const sphere::Loop& loop) {
  Chain out;
  for (const sphere::Arc& a : loop.arcs) {
    const std::vector<exact::ExactVec> v = sphere::split_arc_quarters(a);
    for (size_t i = 0; i + 1 < v.size(); ++i) out.push_back(v[i].nearest_unit());
  }
  return out;
}

// The loop started at its smallest rotation: a loop is a cycle, and where the
// arrangement's walk happened to start it depends on the order of the construction.
Chain canonical_rotation(const Chain& loop) {
  Chain best = loop;
  for (size_t k = 1; k < loop.size(); ++k) {
    if (loop[k] > best[0]) continue;
    Chain rotated(loop.begin() + k, loop.end());
    rotated.insert(rotated.end(), loop.begin(), loop.begin() + k);
    best = std::min(best, rotated);
  }
  return best;
}

void write(const Vertex& u, v1::Vec3* out) {
  out->set_x(u[0]);
  out->set_y(u[1]);
  out->set_z(u[2]);
}

}  // namespace

void to_proto(const exact::ExactVec& direction, v1::Vec3* out) { write(direction.nearest_unit(), out); }

void to_proto(const sphere::SphericalImage& image, v1::SphericalImage* out) {
  out->Clear();
  out->set_dimension(image.dimension());
  out->set_area(image.canonical_area());
  out->set_description(image.description());
  if (image.is_full_sphere()) {
    out->set_full_sphere(true);
    return;
  }
  // Cells, loops and vertices in one order whatever the construction's: the same set is
  // written as the same bytes (loops from their smallest rotation, each kind of cell and
  // the loops of a polygon in ascending order).
  std::vector<std::vector<Chain>> polygons;
  for (const sphere::Face& f : image.faces()) {
    std::vector<Chain>& loops = polygons.emplace_back();
    for (const sphere::Loop& l : f.loops) loops.push_back(canonical_rotation(loop_vertices(l)));
    std::sort(loops.begin(), loops.end());
  }
  std::vector<Chain> arcs;
  for (const sphere::Arc& a : image.curves()) {
    Chain& vertices = arcs.emplace_back();
    for (const exact::ExactVec& v : sphere::split_arc_quarters(a)) vertices.push_back(v.nearest_unit());
  }
  Chain points;
  for (const exact::ExactVec& p : image.points()) points.push_back(p.nearest_unit());
  std::sort(polygons.begin(), polygons.end());
  std::sort(arcs.begin(), arcs.end());
  std::sort(points.begin(), points.end());
  for (const std::vector<Chain>& loops : polygons) {
    v1::SphericalPolygon* polygon = out->add_polygons();
    for (const Chain& vertices : loops) {
      v1::Loop* loop = polygon->add_loops();
      for (const Vertex& u : vertices) write(u, loop->add_vertices());
    }
  }
  for (const Chain& vertices : arcs) {
    v1::SphericalArc* arc = out->add_arcs();
    for (const Vertex& u : vertices) write(u, arc->add_vertices());
  }
  for (const Vertex& u : points) write(u, out->add_points());
}

}  // namespace gvm::io
