// SphericalImage on hand-made cells: arcs of every length, splitting for the proto,
// equality and hemisphere tests of the special shapes.
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>
#include <utility>
#include <vector>

#include "io/sphere_proto.h"
#include "exact/exact_vec.h"
#include "gvm/v1/gvm.pb.h"
#include "sphere/spherical_image.h"

namespace {

using gvm::exact::ExactVec;
using gvm::sphere::Arc;
using gvm::sphere::SphericalImage;

constexpr double kPi = 3.14159265358979323846;

ExactVec V(double x, double y, double z) { return ExactVec::from_point({x, y, z}); }

TEST(SphereArc, ContainsForEveryArcLength) {
  ExactVec z = V(0, 0, 1);
  Arc quarter{V(1, 0, 0), V(0, 1, 0), z, false};
  EXPECT_TRUE(arc_contains(quarter, V(1, 1, 0)));
  EXPECT_TRUE(arc_contains(quarter, V(1, 0, 0)));
  EXPECT_TRUE(arc_contains(quarter, V(0, 2, 0)));
  EXPECT_FALSE(arc_contains(quarter, V(-1, -1, 0)));
  EXPECT_FALSE(arc_contains(quarter, V(1, -1, 0)));
  EXPECT_FALSE(arc_contains(quarter, V(1, 1, 1)));
  Arc half{V(1, 0, 0), V(-1, 0, 0), z, false};
  EXPECT_TRUE(arc_contains(half, V(0, 1, 0)));
  EXPECT_TRUE(arc_contains(half, V(-1, 0, 0)));
  EXPECT_FALSE(arc_contains(half, V(0, -1, 0)));
  Arc three_quarters{V(1, 0, 0), V(0, -1, 0), z, false};
  EXPECT_TRUE(arc_contains(three_quarters, V(-1, 0, 0)));
  EXPECT_TRUE(arc_contains(three_quarters, V(0, -1, 0)));
  EXPECT_TRUE(arc_contains(three_quarters, V(-1, -1, 0)));
  EXPECT_FALSE(arc_contains(three_quarters, V(1, -1, 0)));
  Arc reversed{V(0, 1, 0), V(1, 0, 0), V(0, 0, -1), false};  // the quarter, walked back
  EXPECT_TRUE(arc_contains(reversed, V(1, 1, 0)));
  EXPECT_FALSE(arc_contains(reversed, V(-1, 1, 0)));
}

TEST(SphereArc, SplitGivesPiecesShorterThanHalfCircle) {
  ExactVec z = V(0, 0, 1);
  for (const Arc& a : {Arc{V(1, 0, 0), V(0, 1, 0), z, false},
                       Arc{V(1, 0, 0), V(-1, 0, 0), z, false},
                       Arc{V(1, 0, 0), V(1, -1, 0), z, false}, Arc{{}, {}, z, true}}) {
    auto v = gvm::sphere::split_arc(a);
    ASSERT_GE(v.size(), 2u);
    EXPECT_TRUE(gvm::exact::same_direction(v.front(), a.full ? v.back() : a.start));
    if (!a.full) EXPECT_TRUE(gvm::exact::same_direction(v.back(), a.end));
    for (size_t i = 0; i + 1 < v.size(); ++i) {
      // Strictly shorter than 180 degrees, counter-clockwise around the normal.
      EXPECT_EQ(gvm::exact::sign_det(a.normal, v[i], v[i + 1]), gvm::Sign::kPositive) << i;
      EXPECT_TRUE(arc_contains(a, v[i]));
    }
  }
}

TEST(SphereImage, SpecialShapes) {
  auto e = SphericalImage::empty();
  EXPECT_EQ(e.dimension(), -1);
  EXPECT_EQ(e.description(), "empty");
  auto f = SphericalImage::full_sphere();
  EXPECT_EQ(f.dimension(), 2);
  EXPECT_EQ(f.area(), 4 * kPi);
  EXPECT_FALSE(f == e);
  EXPECT_TRUE(f == SphericalImage::full_sphere());
  auto h = SphericalImage::hemisphere(V(0, 0, 2));
  EXPECT_EQ(h.area(), 2 * kPi);
  EXPECT_TRUE(h == SphericalImage::hemisphere(V(0, 0, 1)));
  EXPECT_FALSE(h == SphericalImage::hemisphere(V(0, 0, -1)));
  EXPECT_TRUE(h.within_closed_hemisphere(V(0, 0, 3)));
  EXPECT_FALSE(h.within_closed_hemisphere(V(0, 0, -1)));
  EXPECT_FALSE(h.within_closed_hemisphere(V(0, 1, 1)));
  auto c = SphericalImage::great_circle(V(0, 0, 1));
  EXPECT_TRUE(c == SphericalImage::great_circle(V(0, 0, -4)));
  EXPECT_EQ(c.description(), "great circle around (0, 0, 1)");
  EXPECT_TRUE(c.within_closed_hemisphere(V(0, 0, -1)));
  EXPECT_FALSE(c.within_closed_hemisphere(V(1, 0, 0)));
  auto p = SphericalImage::point(V(0, 0, 1));
  EXPECT_EQ(p.description(), "point (0, 0, 1)");
  EXPECT_TRUE(p == SphericalImage::point(V(0, 0, 5)));
  EXPECT_FALSE(p == SphericalImage::point(V(0, 0, -1)));
  EXPECT_FALSE(p == c);
}

TEST(SphereImage, ProtoOfAHemisphereIsACounterClockwiseSquare) {
  gvm::v1::SphericalImage m;
  gvm::io::to_proto(SphericalImage::hemisphere(V(0, 0, 1)), &m);
  ASSERT_EQ(m.polygons_size(), 1);
  ASSERT_EQ(m.polygons(0).loops_size(), 1);
  const auto& loop = m.polygons(0).loops(0);
  ASSERT_EQ(loop.vertices_size(), 4);
  for (int i = 0; i < 4; ++i) {
    const auto& a = loop.vertices(i);
    const auto& b = loop.vertices((i + 1) % 4);
    EXPECT_NEAR(a.z(), 0, 1e-15);
    EXPECT_GT(a.x() * b.y() - a.y() * b.x(), 0.5);  // counter-clockwise seen from +z
  }
  EXPECT_EQ(m.dimension(), 2);
  EXPECT_EQ(m.area(), 2 * kPi);
  EXPECT_EQ(m.description(), "hemisphere around (0, 0, 1)");
  gvm::v1::SphericalImage g;
  gvm::io::to_proto(SphericalImage::great_circle(V(1, 0, 0)), &g);
  ASSERT_EQ(g.arcs_size(), 1);
  EXPECT_EQ(g.arcs(0).vertices_size(), 5);  // closed: first vertex repeated
}

// A quadrilateral around (1, 1, 4) with a triangular hole, its loops starting at vertex
// `start`, its circle normals `copies` times as long (the same circles built otherwise),
// and two points, in either order.
SphericalImage square_with_hole(size_t start, int copies, bool points_reversed) {
  const std::vector<ExactVec> outer{V(0, 0, 1), V(3, 0, 4), V(3, 2, 4), V(0, 2, 3)};
  const std::vector<ExactVec> hole{V(1, 1, 4), V(1.5, 1.8, 4), V(2, 1, 4)};  // clockwise: the set on its left
  gvm::sphere::Face face;
  for (const auto* ring : {&outer, &hole}) {
    gvm::sphere::Loop& loop = face.loops.emplace_back();
    for (size_t k = 0; k < ring->size(); ++k) {
      const ExactVec& a = (*ring)[(start + k) % ring->size()];
      const ExactVec& b = (*ring)[(start + k + 1) % ring->size()];
      ExactVec longer = a;
      for (int c = 1; c < copies; ++c) longer = longer + a;
      loop.arcs.push_back({a, b, gvm::exact::cross(longer, b)});
    }
  }
  SphericalImage image;
  image.add_face(std::move(face));
  std::vector<ExactVec> points{V(-1, 0, 0), V(0, -1, 0)};
  if (points_reversed) std::swap(points[0], points[1]);
  for (const ExactVec& p : points) image.add_point(p);
  return image;
}

TEST(SphereImage, OneSetIsWrittenAsTheSameBytesHoweverItWasBuilt) {
  gvm::v1::SphericalImage first;
  gvm::io::to_proto(square_with_hole(0, 1, false), &first);
  ASSERT_EQ(first.polygons_size(), 1);
  ASSERT_EQ(first.polygons(0).loops_size(), 2);
  ASSERT_EQ(first.points_size(), 2);
  EXPECT_GT(first.area(), 0);
  for (size_t start : {1, 2, 3}) {
    for (int copies : {1, 3}) {
      gvm::v1::SphericalImage other;
      gvm::io::to_proto(square_with_hole(start, copies, start % 2 == 1), &other);
      EXPECT_EQ(other.SerializeAsString(), first.SerializeAsString()) << start << " " << copies;
    }
  }
  // Each loop starts at its smallest vertex.
  for (const auto& loop : first.polygons(0).loops()) {
    for (const auto& v : loop.vertices()) {
      const auto& s = loop.vertices(0);
      EXPECT_LE(std::make_tuple(s.x(), s.y(), s.z()), std::make_tuple(v.x(), v.y(), v.z()));
    }
  }
}

}  // namespace
