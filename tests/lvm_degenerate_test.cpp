// LVM (paper Prop. 1) for every degenerate outcome, asserted exactly, on axis-aligned
// normals and again under an exact rational rotation (so that axis-aligned special cases
// cannot pass by accident).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "io/sphere_proto.h"
#include "exact/exact_vec.h"
#include "gvm/v1/gvm.pb.h"
#include "sphere/local_visibility_map.h"
#include "sphere/spherical_image.h"

namespace {

using gvm::exact::ExactVec;
using gvm::sphere::Arc;
using gvm::sphere::local_visibility_map;
using gvm::sphere::SphericalImage;

constexpr double kPi = 3.14159265358979323846;

using I3 = std::array<long long, 3>;

// Rz * Rx, both Pythagorean 3-4-5 rotations scaled by 5: integer entries, so rotated
// integer vectors are exact and directions are preserved (scale 25 > 0).
I3 rotate(const I3& v) {
  I3 x = {5 * v[0], 3 * v[1] - 4 * v[2], 4 * v[1] + 3 * v[2]};
  return {3 * x[0] - 4 * x[1], 4 * x[0] + 3 * x[1], 5 * x[2]};
}

struct Frame {
  bool rotated;
  ExactVec operator()(long long x, long long y, long long z) const {
    I3 v = {x, y, z};
    if (rotated) v = rotate(v);
    return ExactVec::from_point(
        {static_cast<double>(v[0]), static_cast<double>(v[1]), static_cast<double>(v[2])});
  }
};

class LvmDegenerate : public ::testing::TestWithParam<bool> {
 protected:
  Frame V{GetParam()};
  SphericalImage lvm(std::vector<I3> normals) const {
    std::vector<ExactVec> n;
    for (const I3& v : normals) n.push_back(V(v[0], v[1], v[2]));
    return local_visibility_map(n);
  }
  ExactVec v(const I3& a) const { return V(a[0], a[1], a[2]); }
};

// Every expected direction matches exactly one actual one and vice versa.
void expect_same_directions(const std::vector<ExactVec>& actual,
                            const std::vector<ExactVec>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  std::vector<bool> used(actual.size(), false);
  for (const ExactVec& e : expected) {
    bool found = false;
    for (size_t i = 0; i < actual.size() && !found; ++i) {
      if (!used[i] && gvm::exact::same_direction(actual[i], e)) used[i] = found = true;
    }
    EXPECT_TRUE(found) << "missing expected direction";
  }
}

std::vector<ExactVec> face_vertices(const SphericalImage& s) {
  std::vector<ExactVec> out;
  for (const auto& l : s.faces().at(0).loops) {
    for (const Arc& a : l.arcs) out.push_back(a.start);
  }
  return out;
}

void expect_contains(const SphericalImage& s, const ExactVec& u, bool in, const char* what) {
  EXPECT_EQ(s.contains(u), in) << what << " in " << s.description();
}

TEST_P(LvmDegenerate, NoNormalsGiveTheFullSphere) {
  auto s = lvm({});
  EXPECT_TRUE(s.is_full_sphere());
  EXPECT_EQ(s.dimension(), 2);
  EXPECT_DOUBLE_EQ(s.area(), 4 * kPi);
  EXPECT_TRUE(s.contains(v({1, -2, 3})));
  EXPECT_FALSE(s.within_closed_hemisphere(v({0, 0, 1})));
  EXPECT_EQ(s.description(), "full sphere");
}

TEST_P(LvmDegenerate, OneNormalGivesAHemisphere) {
  auto s = lvm({{0, 0, 1}, {0, 0, 2}});  // duplicated direction
  ASSERT_EQ(s.dimension(), 2);
  ASSERT_EQ(s.faces().size(), 1u);
  ASSERT_EQ(s.faces()[0].loops.size(), 1u);
  ASSERT_EQ(s.faces()[0].loops[0].arcs.size(), 1u);
  const Arc& c = s.faces()[0].loops[0].arcs[0];
  EXPECT_TRUE(c.full);
  EXPECT_TRUE(gvm::exact::same_direction(c.normal, v({0, 0, 1})));
  EXPECT_EQ(s.area(), 2 * kPi);
  expect_contains(s, v({0, 0, 1}), true, "pole");
  expect_contains(s, v({1, 0, 0}), true, "boundary x");
  expect_contains(s, v({-3, 4, 0}), true, "boundary");
  expect_contains(s, v({1, 1, -1}), false, "below");
  EXPECT_TRUE(s.within_closed_hemisphere(v({0, 0, 5})));
  EXPECT_FALSE(s.within_closed_hemisphere(v({0, 1, 5})));
  if (!GetParam()) EXPECT_EQ(s.description(), "hemisphere around (0, 0, 1)");
}

TEST_P(LvmDegenerate, AntipodalNormalsGiveAGreatCircle) {
  auto s = lvm({{1, 0, 0}, {-1, 0, 0}, {2, 0, 0}});
  ASSERT_EQ(s.dimension(), 1);
  ASSERT_EQ(s.curves().size(), 1u);
  EXPECT_TRUE(s.curves()[0].full);
  EXPECT_TRUE(gvm::exact::parallel(s.curves()[0].normal, v({1, 0, 0})));
  expect_contains(s, v({0, 1, 0}), true, "y");
  expect_contains(s, v({0, -3, 4}), true, "on circle");
  expect_contains(s, v({1, 1, 0}), false, "off circle");
  EXPECT_EQ(s.area(), 0.0);
  EXPECT_TRUE(s.within_closed_hemisphere(v({-1, 0, 0})));
  EXPECT_FALSE(s.within_closed_hemisphere(v({0, 0, 1})));
}

TEST_P(LvmDegenerate, TwoNormalsGiveALune) {
  auto s = lvm({{1, 0, 0}, {0, 1, 0}});
  ASSERT_EQ(s.dimension(), 2);
  ASSERT_EQ(s.faces().size(), 1u);
  ASSERT_EQ(s.faces()[0].loops.size(), 1u);
  ASSERT_EQ(s.faces()[0].loops[0].arcs.size(), 2u);
  expect_same_directions(face_vertices(s), {v({0, 0, 1}), v({0, 0, -1})});
  EXPECT_NEAR(s.area(), kPi, 1e-12);
  expect_contains(s, v({1, 1, 0}), true, "inside");
  expect_contains(s, v({0, 0, 1}), true, "vertex");
  expect_contains(s, v({0, 0, -1}), true, "vertex");
  expect_contains(s, v({1, 0, 5}), true, "boundary");
  expect_contains(s, v({0, 1, -5}), true, "boundary");
  expect_contains(s, v({-1, 1, 0}), false, "outside");
  expect_contains(s, v({1, -1, 3}), false, "outside");
  EXPECT_EQ(s.description().rfind("lune of 90.0 deg between", 0), 0u) << s.description();
  if (!GetParam()) {
    EXPECT_TRUE(s.description() == "lune of 90.0 deg between (0, 0, 1) and (0, 0, -1)" ||
                s.description() == "lune of 90.0 deg between (0, 0, -1) and (0, 0, 1)")
        << s.description();
  }
  EXPECT_TRUE(s.within_closed_hemisphere(v({1, 1, 0})));
  EXPECT_TRUE(s.within_closed_hemisphere(v({1, 0, 0})));
  EXPECT_FALSE(s.within_closed_hemisphere(v({1, 1, 1})));
  EXPECT_FALSE(s.within_closed_hemisphere(v({0, 0, 1})));
}

TEST_P(LvmDegenerate, ThroughHoleGivesTwoAntipodalPoints) {
  auto s = lvm({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}});
  ASSERT_EQ(s.dimension(), 0);
  expect_same_directions(s.points(), {v({0, 0, 1}), v({0, 0, -1})});
  expect_contains(s, v({0, 0, 7}), true, "+z");
  expect_contains(s, v({0, 0, -1}), true, "-z");
  expect_contains(s, v({0, 1, 7}), false, "near +z");
  EXPECT_TRUE(s.within_closed_hemisphere(v({1, 0, 0})));
  EXPECT_FALSE(s.within_closed_hemisphere(v({0, 0, 1})));
}

TEST_P(LvmDegenerate, BlindPocketGivesAPoint) {
  auto s = lvm({{0, 0, 1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}});
  ASSERT_EQ(s.dimension(), 0);
  expect_same_directions(s.points(), {v({0, 0, 1})});
  expect_contains(s, v({0, 0, 3}), true, "+z");
  expect_contains(s, v({0, 0, -1}), false, "-z");
  expect_contains(s, v({1, 0, 3}), false, "near +z");
  if (!GetParam()) EXPECT_EQ(s.description(), "point (0, 0, 1)");
  EXPECT_TRUE(s.within_closed_hemisphere(v({1, 0, 1})));
  EXPECT_TRUE(s.within_closed_hemisphere(v({1, 0, 0})));
  EXPECT_FALSE(s.within_closed_hemisphere(v({1, 0, -1})));
}

TEST_P(LvmDegenerate, HalfPlaneOfNormalsGivesASemicircle) {
  // u . x = 0 and u . z >= 0: the half great circle from -y over +z to +y.
  auto s = lvm({{1, 0, 0}, {-1, 0, 0}, {0, 0, 1}});
  ASSERT_EQ(s.dimension(), 1);
  ASSERT_EQ(s.curves().size(), 1u);
  const Arc& a = s.curves()[0];
  EXPECT_FALSE(a.full);
  expect_same_directions({a.start, a.end}, {v({0, 1, 0}), v({0, -1, 0})});
  EXPECT_TRUE(gvm::exact::parallel(a.normal, v({1, 0, 0})));
  expect_contains(s, v({0, 0, 1}), true, "+z");
  expect_contains(s, v({0, 1, 0}), true, "+y");
  expect_contains(s, v({0, -1, 0}), true, "-y");
  expect_contains(s, v({0, -4, 3}), true, "on arc");
  expect_contains(s, v({0, -4, -3}), false, "other half");
  expect_contains(s, v({0, 0, -1}), false, "-z");
  expect_contains(s, v({1, 0, 1}), false, "off circle");
  if (!GetParam()) {
    EXPECT_TRUE(s.description() == "arc of 180.0 deg from (0, 1, 0) to (0, -1, 0)" ||
                s.description() == "arc of 180.0 deg from (0, -1, 0) to (0, 1, 0)")
        << s.description();
  }
  EXPECT_TRUE(s.within_closed_hemisphere(v({0, 0, 1})));
  EXPECT_TRUE(s.within_closed_hemisphere(v({1, 0, 0})));
  EXPECT_FALSE(s.within_closed_hemisphere(v({0, 1, 1})));
  // Both ends on the boundary circle, the middle below it.
  EXPECT_FALSE(s.within_closed_hemisphere(v({0, 0, -1})));
  EXPECT_FALSE(s.within_closed_hemisphere(v({1, 0, -1})));
}

TEST_P(LvmDegenerate, ArcShorterThanHalfCircle) {
  // u . x = 0, u . y >= 0, u . z >= 0: the quarter circle from +y to +z.
  auto s = lvm({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
  ASSERT_EQ(s.dimension(), 1);
  ASSERT_EQ(s.curves().size(), 1u);
  const Arc& a = s.curves()[0];
  expect_same_directions({a.start, a.end}, {v({0, 1, 0}), v({0, 0, 1})});
  expect_contains(s, v({0, 3, 4}), true, "inside");
  expect_contains(s, v({0, 1, 0}), true, "end");
  expect_contains(s, v({0, 0, 1}), true, "end");
  expect_contains(s, v({0, -1, 1}), false, "beyond");
  expect_contains(s, v({0, -3, -4}), false, "antipode");
  if (!GetParam()) {
    EXPECT_TRUE(s.description() == "arc of 90.0 deg from (0, 1, 0) to (0, 0, 1)" ||
                s.description() == "arc of 90.0 deg from (0, 0, 1) to (0, 1, 0)")
        << s.description();
  }
  EXPECT_TRUE(s.within_closed_hemisphere(v({0, 1, 1})));
  EXPECT_TRUE(s.within_closed_hemisphere(v({0, 1, 0})));
  EXPECT_FALSE(s.within_closed_hemisphere(v({0, 1, -1})));
}

TEST_P(LvmDegenerate, ThreeNormalsGiveAnOctant) {
  auto s = lvm({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {2, 0, 0}});
  ASSERT_EQ(s.dimension(), 2);
  ASSERT_EQ(s.faces().size(), 1u);
  expect_same_directions(face_vertices(s), {v({1, 0, 0}), v({0, 1, 0}), v({0, 0, 1})});
  EXPECT_NEAR(s.area(), kPi / 2, 1e-12);
  expect_contains(s, v({1, 1, 1}), true, "inside");
  expect_contains(s, v({1, 0, 0}), true, "vertex");
  expect_contains(s, v({1, 1, 0}), true, "edge");
  expect_contains(s, v({-1, 1, 1}), false, "outside");
  EXPECT_TRUE(s == lvm({{0, 0, 3}, {0, 2, 0}, {1, 0, 0}}));
  EXPECT_FALSE(s == lvm({{0, 0, 3}, {0, 2, 0}}));
  EXPECT_FALSE(s == lvm({{0, 0, 3}, {0, 2, 0}, {1, 0, 1}}));
}

TEST_P(LvmDegenerate, SquareConeGivesAQuadrilateral) {
  auto s = lvm({{1, 0, 1}, {-1, 0, 1}, {0, 1, 1}, {0, -1, 1}, {0, 0, 1}});
  ASSERT_EQ(s.dimension(), 2);
  expect_same_directions(face_vertices(s), {v({1, 1, 1}), v({-1, 1, 1}), v({-1, -1, 1}),
                                            v({1, -1, 1})});
  EXPECT_NEAR(s.area(), 2 * kPi / 3, 1e-12);
  expect_contains(s, v({1, 1, 1}), true, "vertex");
  expect_contains(s, v({1, 0, 1}), true, "edge");
  expect_contains(s, v({0, 0, 1}), true, "center");
  expect_contains(s, v({2, 1, 1}), false, "outside");
  if (!GetParam()) EXPECT_EQ(s.description(), "polygon with 4 vertices, 2.09 sr");
  EXPECT_TRUE(s.within_closed_hemisphere(v({0, 0, 1})));
  EXPECT_TRUE(s.within_closed_hemisphere(v({1, 0, 1})));   // a normal: on the hull
  EXPECT_TRUE(s.within_closed_hemisphere(v({1, 1, 2})));   // on an edge of the hull
  EXPECT_FALSE(s.within_closed_hemisphere(v({1, 1, 1})));  // just outside the hull
}

TEST_P(LvmDegenerate, NormalsNotInAHemisphereGiveEmpty) {
  auto s = lvm({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, -1, -1}});
  EXPECT_EQ(s.dimension(), -1);
  EXPECT_TRUE(s.is_empty());
  EXPECT_EQ(s.description(), "empty");
  EXPECT_FALSE(s.contains(v({1, 1, 1})));
  EXPECT_TRUE(s.within_closed_hemisphere(v({0, 0, -1})));
  EXPECT_EQ(s.area(), 0.0);
  auto box = lvm({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}});
  EXPECT_TRUE(box.is_empty());
  EXPECT_TRUE(s == box);
  EXPECT_TRUE(s == SphericalImage::empty());
}

TEST_P(LvmDegenerate, ProtoOfEveryOutcome) {
  std::vector<std::vector<I3>> cases = {
      {},
      {{0, 0, 1}},
      {{1, 0, 0}, {-1, 0, 0}},
      {{1, 0, 0}, {0, 1, 0}},
      {{1, 0, 0}, {-1, 0, 0}, {0, 0, 1}},
      {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}},
      {{0, 0, 1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}},
      {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
      {{1, 0, 1}, {-1, 0, 1}, {0, 1, 1}, {0, -1, 1}},
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, -1, -1}},
  };
  const std::vector<int> dims = {2, 2, 1, 2, 1, 0, 0, 1, 2, -1};
  const std::vector<std::array<int, 3>> counts = {  // polygons, arcs, points
      {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 1, 0},
      {0, 0, 2}, {0, 0, 1}, {0, 1, 0}, {1, 0, 0}, {0, 0, 0}};
  for (size_t i = 0; i < cases.size(); ++i) {
    auto s = lvm(cases[i]);
    gvm::v1::SphericalImage p;
    gvm::io::to_proto(s, &p);
    EXPECT_EQ(p.dimension(), dims[i]) << i;
    EXPECT_EQ(p.full_sphere(), i == 0) << i;
    EXPECT_EQ(p.polygons_size(), counts[i][0]) << i;
    EXPECT_EQ(p.arcs_size(), counts[i][1]) << i;
    EXPECT_EQ(p.points_size(), counts[i][2]) << i;
    EXPECT_EQ(p.description(), s.description()) << i;
    EXPECT_EQ(p.area(), s.canonical_area()) << i;  // written canonically
    EXPECT_NEAR(p.area(), s.area(), 1e-12) << i;
    for (const auto& poly : p.polygons()) {
      for (const auto& loop : poly.loops()) {
        int n = loop.vertices_size();
        EXPECT_GE(n, 3) << i;
        for (int k = 0; k < n; ++k) {
          const auto& a = loop.vertices(k);
          const auto& b = loop.vertices((k + 1) % n);
          double d = a.x() * b.x() + a.y() * b.y() + a.z() * b.z();
          EXPECT_GT(d, -1 + 1e-9) << "arc of 180 degrees in case " << i;
        }
      }
    }
    for (const auto& arc : p.arcs()) {
      for (int k = 0; k + 1 < arc.vertices_size(); ++k) {
        const auto& a = arc.vertices(k);
        const auto& b = arc.vertices(k + 1);
        double d = a.x() * b.x() + a.y() * b.y() + a.z() * b.z();
        EXPECT_GT(d, -1 + 1e-9) << "arc of 180 degrees in case " << i;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Lvm, LvmDegenerate, ::testing::Bool(),
                         [](const ::testing::TestParamInfo<bool>& info) {
                           return info.param ? std::string("Rotated") : std::string("Axes");
                         });

}  // namespace
