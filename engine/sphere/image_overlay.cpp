#include "sphere/image_overlay.h"

namespace gvm::sphere {

using exact::ExactVec;

void add_image(const SphericalImage& image, int layer, std::vector<ArrangementArc>& arcs,
               std::vector<ArrangementPoint>& points) {
  auto add_arc = [&](const Arc& arc, int weight) {
    std::vector<ExactVec> v = split_arc(arc);
    for (size_t i = 0; i + 1 < v.size(); ++i) arcs.push_back({v[i], v[i + 1], arc.normal, layer, weight});
  };
  for (const Face& f : image.faces()) {
    for (const Loop& loop : f.loops) {
      for (const Arc& arc : loop.arcs) add_arc(arc, 1);
    }
  }
  for (const Arc& arc : image.curves()) add_arc(arc, 0);
  for (const ExactVec& p : image.points()) points.push_back({p, layer});
}

ExactVec generic_direction(std::span<const ExactVec> circles, std::span<const ExactVec> points) {
  for (int k = 1;; ++k) {
    ExactVec r = ExactVec::from_point({double(2 * k + 1), double(-3 * k - 5), double(7 * k + 2)});
    bool ok = true;
    for (const ExactVec& n : circles) {
      if (exact::sign_dot(r, n) == Sign::kZero) {
        ok = false;
        break;
      }
    }
    for (size_t i = 0; ok && i < points.size(); ++i) ok = !exact::parallel(r, points[i]);
    if (ok) return r;
  }
}

ExactVec generic_direction(std::span<const ArrangementArc> arcs,
                           std::span<const ArrangementPoint> points) {
  std::vector<ExactVec> circles, dirs;
  circles.reserve(arcs.size());
  for (const ArrangementArc& a : arcs) circles.push_back(a.normal);
  for (const ArrangementPoint& p : points) dirs.push_back(p.p);
  return generic_direction(circles, dirs);
}

int face_winding(const SphericalImage& image, const ExactVec& r) {
  if (image.is_full_sphere()) return 1;
  int n = 0;
  for (const Face& f : image.faces()) n += face_contains(f, r) ? 1 : 0;
  return n;
}

}  // namespace gvm::sphere
