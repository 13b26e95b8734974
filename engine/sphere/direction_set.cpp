#include "gvm/direction_set.h"

#include <algorithm>
#include <cmath>

#include "exact/exact_vec.h"
#include "sphere/clearance.h"
#include "sphere/nearness.h"
#include "sphere/local_visibility_map.h"
#include "sphere/set_operations.h"
#include "sphere/spherical_image.h"

namespace gvm {
namespace {

using exact::ExactVec;
using sphere::SphericalImage;

DirectionSet wrap(SphericalImage image) {
  return DirectionSet(std::make_shared<const SphericalImage>(std::move(image)));
}

Direction wrap(ExactVec v) { return Direction(std::make_shared<const ExactVec>(std::move(v))); }

// Every vertex of the cells, arcs split into minor pieces: the set's directions are all
// non-negative combinations of these (points, and the minor arcs between them).
std::vector<ExactVec> corner_directions(const SphericalImage& image) {
  std::vector<ExactVec> out = image.points();
  auto add = [&](const sphere::Arc& arc) {
    for (const ExactVec& v : sphere::split_arc(arc)) out.push_back(v);
  };
  for (const sphere::Arc& a : image.curves()) add(a);
  for (const sphere::Face& f : image.faces()) {
    for (const sphere::Loop& l : f.loops) {
      for (const sphere::Arc& a : l.arcs) add(a);
    }
  }
  return out;
}

// The 2-cells alone, mapped to their antipodes.
SphericalImage antipodal_faces(const SphericalImage& image) {
  SphericalImage out;
  for (const sphere::Face& f : image.faces()) {
    // u -> -u reverses the orientation of the sphere: each loop is walked backwards,
    // every arc a -> b around n becoming -b -> -a around -n.
    sphere::Face g;
    g.convex = f.convex;
    for (const sphere::Loop& l : f.loops) {
      sphere::Loop m;
      for (auto it = l.arcs.rbegin(); it != l.arcs.rend(); ++it) {
        m.arcs.push_back({-it->end, -it->start, -it->normal, it->full});
      }
      g.loops.push_back(std::move(m));
    }
    out.add_face(std::move(g));
  }
  return out;
}

}  // namespace

DirectionSet::DirectionSet() : image_(std::make_shared<const SphericalImage>()) {}

DirectionSet DirectionSet::full_sphere() { return wrap(SphericalImage::full_sphere()); }

DirectionSet DirectionSet::point(const Direction& d) { return wrap(SphericalImage::point(d.exact())); }

DirectionSet DirectionSet::hemisphere(const Direction& n) {
  return wrap(SphericalImage::hemisphere(n.exact()));
}

DirectionSet DirectionSet::great_circle(const Direction& n) {
  return wrap(SphericalImage::great_circle(n.exact()));
}

DirectionSet DirectionSet::minor_arc(const Direction& from, const Direction& to) {
  SphericalImage image;
  image.add_curve({from.exact(), to.exact(), exact::cross(from.exact(), to.exact())});
  return wrap(std::move(image));
}

DirectionSet DirectionSet::intersection_of_hemispheres(std::span<const Direction> normals) {
  std::vector<ExactVec> n;
  n.reserve(normals.size());
  for (const Direction& d : normals) n.push_back(d.exact());
  return wrap(sphere::local_visibility_map(n));
}

int DirectionSet::dimension() const { return image_->dimension(); }

bool DirectionSet::is_full_sphere() const { return image_->is_full_sphere(); }

bool DirectionSet::contains(const Direction& u) const { return image_->contains(u.exact()); }

Direction DirectionSet::witness() const {
  const SphericalImage& s = *image_;
  if (!s.points().empty()) return wrap(s.points().front());
  if (!s.curves().empty()) return wrap(sphere::split_arc(s.curves().front()).front());
  if (!s.faces().empty()) return wrap(sphere::split_arc(s.faces().front().loops.front().arcs.front()).front());
  return Direction(0, 0, 1);  // the whole sphere
}

DirectionSet DirectionSet::intersection(const DirectionSet& other) const {
  return wrap(sphere::set_intersection(*image_, *other.image_));
}

DirectionSet DirectionSet::union_with(const DirectionSet& other) const {
  return wrap(sphere::set_union(*image_, *other.image_));
}

DirectionSet DirectionSet::difference(const DirectionSet& other) const {
  return wrap(sphere::set_difference(*image_, *other.image_));
}

bool DirectionSet::is_subset_of(const DirectionSet& other) const {
  return sphere::is_subset(*image_, *other.image_);
}

bool operator==(const DirectionSet& a, const DirectionSet& b) {
  return a.is_subset_of(b) && b.is_subset_of(a);
}

DirectionSet DirectionSet::antipodal() const {
  const SphericalImage& s = *image_;
  if (s.is_full_sphere()) return *this;
  SphericalImage out = antipodal_faces(s);
  for (const sphere::Arc& a : s.curves()) out.add_curve({-a.start, -a.end, a.normal, a.full});
  for (const ExactVec& p : s.points()) out.add_point(-p);
  return wrap(std::move(out));
}

DirectionSet DirectionSet::polar() const {
  const SphericalImage& s = *image_;
  if (s.is_full_sphere()) return DirectionSet();
  // K = {a : a . v >= 0 for every corner v} holds every a whose closed hemisphere holds
  // the points, the arcs and the faces' boundaries. A face whose boundary lies in that
  // hemisphere either lies in it too or contains -a (it then covers the whole opposite
  // open hemisphere), and -a is never on such a boundary; so the polar is K minus the
  // antipodes of the faces, which are open there.
  const SphericalImage k = sphere::local_visibility_map(corner_directions(s));
  if (s.faces().empty()) return wrap(k);
  return wrap(sphere::set_difference(k, antipodal_faces(s)));
}

bool DirectionSet::within_closed_hemisphere(const Direction& n) const {
  return image_->within_closed_hemisphere(n.exact());
}

bool DirectionSet::contains_cap(const Direction& center, double sin2) const {
  return sphere::contains_cap(*image_, center.exact(), sin2);
}

bool DirectionSet::within(const Direction& u, double sin2) const {
  return sphere::within_angle(*image_, u.exact(), sin2);
}

bool DirectionSet::within(const DirectionSet& other, double sin2) const {
  return sphere::sets_within_angle(*image_, *other.image_, sin2);
}

std::vector<Direction> DirectionSet::corners() const {
  std::vector<Direction> out;
  for (const ExactVec& v : sphere::corners(*image_)) out.push_back(wrap(v));
  return out;
}

std::optional<DirectionSet> DirectionSet::dilation_cover(double theta, double sin2) const {
  std::optional<SphericalImage> cover = sphere::dilation_cover(*image_, theta, sin2);
  if (!cover) return std::nullopt;
  return wrap(std::move(*cover));
}

double DirectionSet::approx_signed_clearance(const std::array<double, 3>& u) const {
  return sphere::approx_signed_clearance(*image_, u);
}

std::vector<DirectionSet> DirectionSet::cells() const {
  const SphericalImage& s = *image_;
  if (s.is_full_sphere()) return {*this};
  std::vector<DirectionSet> out;
  for (const sphere::Face& f : s.faces()) {
    SphericalImage cell;
    cell.add_face(f);
    out.push_back(wrap(std::move(cell)));
  }
  for (const sphere::Arc& a : s.curves()) {
    SphericalImage cell;
    cell.add_curve(a);
    out.push_back(wrap(std::move(cell)));
  }
  for (const ExactVec& p : s.points()) out.push_back(wrap(SphericalImage::point(p)));
  return out;
}

Direction DirectionSet::snap(const std::array<double, 3>& u) const {
  const Direction d(u[0], u[1], u[2]);
  if (contains(d)) return d;
  // Candidates, each exactly in the set: projections of u onto arcs' circles (exact
  // points of the circle: n x (u x n)) that fall on the arc, the arcs' ends, the points.
  std::vector<ExactVec> candidates = image_->points();
  auto add_arc = [&](const sphere::Arc& a) {
    const ExactVec q = exact::cross(a.normal, exact::cross(d.exact(), a.normal));
    if (!exact::is_zero(q) && sphere::arc_contains(a, q)) candidates.push_back(q);
    if (!a.full) {
      candidates.push_back(a.start);
      candidates.push_back(a.end);
    }
  };
  for (const sphere::Arc& a : image_->curves()) add_arc(a);
  for (const sphere::Face& f : image_->faces()) {
    for (const sphere::Loop& l : f.loops) {
      for (const sphere::Arc& a : l.arcs) add_arc(a);
    }
  }
  if (candidates.empty()) return witness();
  auto closeness = [&](const ExactVec& v) {
    const std::array<double, 3> w = v.unit();
    return w[0] * u[0] + w[1] * u[1] + w[2] * u[2];
  };
  return wrap(*std::max_element(candidates.begin(), candidates.end(),
                                [&](const ExactVec& a, const ExactVec& b) {
                                  return closeness(a) < closeness(b);
                                }));
}

std::vector<std::array<double, 2>> DirectionSet::circle_intervals(const Direction& normal,
                                                                  const Direction& zero) const {
  constexpr double kTwoPi = 6.283185307179586;
  const SphericalImage on_circle =
      sphere::set_intersection(*image_, SphericalImage::great_circle(normal.exact()));
  const std::array<double, 3> e1 = zero.unit(), e2 = cross(normal, zero).unit();
  auto angle = [&](const ExactVec& v) {
    const std::array<double, 3> w = v.unit();
    double a = std::atan2(w[0] * e2[0] + w[1] * e2[1] + w[2] * e2[2],
                          w[0] * e1[0] + w[1] * e1[1] + w[2] * e1[2]);
    return a < 0 ? a + kTwoPi : a;
  };
  std::vector<std::array<double, 2>> out;
  for (const sphere::Arc& a : on_circle.curves()) {
    if (a.full) {
      out.push_back({0, kTwoPi});
      continue;
    }
    // Arcs run counter-clockwise around their own normal, which is +-normal here.
    const bool along = exact::sign_dot(a.normal, normal.exact()) == Sign::kPositive;
    double from = angle(along ? a.start : a.end), to = angle(along ? a.end : a.start);
    if (to < from) to += kTwoPi;
    out.push_back({from, to});
  }
  for (const ExactVec& p : on_circle.points()) out.push_back({angle(p), angle(p)});
  std::sort(out.begin(), out.end());
  return out;
}

double DirectionSet::area() const { return image_->area(); }

std::string DirectionSet::description() const { return image_->description(); }

}  // namespace gvm
