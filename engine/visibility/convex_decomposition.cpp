#include "visibility/convex_decomposition.h"

#include <tbb/concurrent_unordered_map.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "parallel/interrupt.h"
#include "sphere/local_visibility_map.h"
#include "visibility/direction_window.h"

namespace gvm {
namespace {

using exact::ExactVec;
using sphere::Arc;
using sphere::Loop;
using sphere::SphericalImage;

SphericalImage face_of(Loop loop) {
  SphericalImage img;
  img.add_face({{std::move(loop)}, true});
  return img;
}

}  // namespace

SphericalImage pairwise_occlusion_map(std::span<const ExactVec> differences) {
  const SphericalImage dual = sphere::local_visibility_map(differences);
  if (dual.is_full_sphere()) return {};  // no non-zero difference
  if (dual.is_empty()) return SphericalImage::full_sphere();
  if (dual.dimension() == 0) {
    // One point p: the cone is the half-space x . p >= 0. Two antipodal points: a plane.
    return dual.points().size() == 1 ? SphericalImage::hemisphere(dual.points()[0])
                                     : SphericalImage();
  }
  if (dual.dimension() == 1) {
    // An arc from a to b shorter than 180 degrees: the cone is {x . a >= 0, x . b >= 0},
    // the lune between the half circles through w = a x b and -w. Longer arcs, half and
    // full circles: a half-plane or a line.
    const Arc& arc = dual.curves()[0];
    if (dual.curves().size() != 1 || arc.full ||
        exact::sign_det(arc.normal, arc.start, arc.end) != Sign::kPositive) {
      return {};
    }
    const ExactVec w = exact::cross(arc.start, arc.end);
    return face_of(Loop{{Arc{-w, w, arc.start}, Arc{w, -w, arc.end}}});
  }
  // A polygon dual: the cone is pointed and full-dimensional, its edges the polygon's
  // arc normals, which are the extreme differences. A hemisphere or lune dual: a ray or
  // a planar wedge.
  const Loop& dual_loop = dual.faces()[0].loops[0];
  if (dual_loop.arcs.size() < 3) return {};
  std::vector<ExactVec> v;
  for (const Arc& a : dual_loop.arcs) v.push_back(a.normal);
  if (exact::sign_det(v[0], v[1], v[2]) == Sign::kNegative) std::reverse(v.begin(), v.end());
  Loop loop;
  for (size_t i = 0; i < v.size(); ++i) {
    const ExactVec& a = v[i];
    const ExactVec& b = v[(i + 1) % v.size()];
    loop.arcs.push_back({a, b, exact::cross(a, b)});
  }
  return face_of(std::move(loop));
}

std::vector<SphericalImage> pairwise_occlusion_maps(const SolidMesh& mesh,
                                                    std::span<const uint32_t> s,
                                                    std::span<const uint32_t> o,
                                                    const DirectionWindow* window,
                                                    ConvexDecompositionStatistics* stats) {
  const size_t K = window ? window->row_size() : 0;
  // Window values at the vertices of each triangle of O (max) and of S (min).
  const WindowRows o_max(window, o.size(), K ? window->extremes(mesh, o, true) : std::vector<double>{},
                         WindowRows::Side::occluder);
  const std::vector<double> s_min = K ? window->extremes(mesh, s, false) : std::vector<double>{};

  struct Chunk {
    std::vector<SphericalImage> maps;
    uint64_t outside_window = 0;
  };
  // Each difference q - p is built once and shared by the maps that use it: the exact
  // predicates then see the many zeros between neighbouring maps by construction.
  tbb::concurrent_unordered_map<uint64_t, ExactVec> differences;
  auto difference = [&](uint32_t q, uint32_t p) {
    const uint64_t key = uint64_t(q) << 32 | p;
    auto it = differences.find(key);
    if (it != differences.end()) return it->second;
    const ExactVec d = exact::point_difference(mesh.points[q], mesh.points[p]);
    return differences.emplace(key, d).first->second;
  };
  std::vector<Chunk> chunks(s.size());
  tbb::parallel_for(size_t{0}, s.size(), [&](size_t si) {
    const Triangle& fs = mesh.triangles[s[si]];
    Interruptions interruptions(16);
    size_t visited = 0;
    o_max.for_each_meeting(s_min.data() + si * K, [&](size_t oi) {
      interruptions.tick();
      ++visited;
      const Triangle& fo = mesh.triangles[o[oi]];
      std::vector<ExactVec> d;
      for (uint32_t q : fo) {
        for (uint32_t p : fs) {
          if (q != p) d.push_back(difference(q, p));
        }
      }
      SphericalImage map = pairwise_occlusion_map(d);
      if (map.dimension() == 2) chunks[si].maps.push_back(std::move(map));
      return true;
    });
    chunks[si].outside_window = o.size() - visited;
  });
  interruption_point();  // triangles of S left undone when cancelled
  std::vector<SphericalImage> maps;
  for (Chunk& c : chunks) {
    if (stats) stats->outside_window += c.outside_window;
    for (SphericalImage& m : c.maps) maps.push_back(std::move(m));
  }
  if (stats) {
    stats->pairs += uint64_t(s.size()) * o.size();
    stats->maps += maps.size();
    for (const SphericalImage& m : maps) {
      for (const sphere::Face& f : m.faces()) {
        for (const Loop& l : f.loops) stats->map_arcs += l.arcs.size();
      }
    }
  }
  return maps;
}

}  // namespace gvm
