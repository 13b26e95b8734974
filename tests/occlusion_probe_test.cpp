// The probe decides an arc in the plane of S between the events of its strips, carrying
// the pair that blocked one stretch over to the next unless the event between them is one
// of that pair's (occlusion_probe.cpp). Checked against the probe's own direction test,
// which asks every pair of S and O and knows nothing of events: along the rim of a flat
// feature's hemisphere, where visible and blocked stretches alternate.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "gvm/part.h"
#include "sphere/d3.h"
#include "support/shared_parts.h"
#include "visibility/occlusion_probe.h"
#include "visibility/strip_events.h"
#include "visibility/surface_visibility.h"

namespace gvm {
namespace {

using exact::ExactVec;

// Directions exactly on the circle with normal n: n x w for w turning around n.
struct Rim {
  ExactVec n;
  sphere::D3 e1, e2;  // orthonormal, orthogonal to n (approximately)

  explicit Rim(const ExactVec& normal) : n(normal) {
    const sphere::D3 u = exact::unit_estimate(n).unit;
    e1 = sphere::normalized(sphere::cross(u, std::fabs(u[0]) < 0.6 ? sphere::D3{1, 0, 0} : sphere::D3{0, 1, 0}));
    e2 = sphere::cross(u, e1);
  }
  ExactVec at(double angle) const {
    const sphere::D3 w = sphere::add(sphere::add(sphere::D3{}, e1, std::cos(angle)), e2, std::sin(angle));
    return exact::cross(n, ExactVec::from_point({w[0], w[1], w[2]}));
  }
};

bool in_pieces(const std::vector<sphere::Arc>& pieces, const ExactVec& u) {
  for (const sphere::Arc& p : pieces) {
    if (exact::same_direction(p.start, p.end) ? exact::same_direction(p.start, u) : sphere::arc_contains(p, u)) {
      return true;
    }
  }
  return false;
}

class RimParts : public testing::TestWithParam<const char*> {};

TEST_P(RimParts, StripsAlongARimAgreeWithEveryPairAsked) {
  if (!test::has_shared_part(GetParam())) GTEST_SKIP() << "no " << GetParam();
  auto part = test::analyze_shared_part(GetParam());
  ASSERT_TRUE(part.ok()) << part.status().message();
  const SolidMesh& mesh = part->mesh();
  int features = 0, visible = 0, blocked = 0, changes = 0;
  for (const Feature& f : part->features()) {
    if (f.triangles.size() < 2) continue;
    const auto planes = strip_planes(mesh, f.triangles);
    if (planes.size() != 1) continue;  // flat features only: every triangle of S sweeps strips
    const SurfaceVisibility sv = compute_surface_visibility(*part, f.triangles);
    if (sv.occluders.potential.empty() || sv.lvm.area() != 2 * M_PI) continue;  // a hemisphere
    ++features;
    const OcclusionProbe probe(mesh, f.triangles, sv.occluders.potential);
    const Rim rim(planes[0].first.normal);
    constexpr int kArcs = 6, kSamples = 40;
    for (int a = 0; a < kArcs; ++a) {
      const double from = 2 * M_PI * a / kArcs, to = 2 * M_PI * (a + 1) / kArcs;
      const sphere::Arc arc{rim.at(from), rim.at(to), rim.n};
      const std::vector<sphere::Arc> pieces = probe.unoccluded(arc);
      bool was_visible = false;
      for (int k = 1; k < kSamples; ++k) {
        const ExactVec u = rim.at(from + (to - from) * k / kSamples);
        const bool expected = !probe.occluded(u);
        ASSERT_EQ(in_pieces(pieces, u), expected) << f.name << " arc " << a << " sample " << k;
        (expected ? visible : blocked) += 1;
        changes += k > 1 && expected != was_visible;
        was_visible = expected;
      }
    }
  }
  EXPECT_GT(features, 0);
  // Not all one answer: the stretches change between blocked and visible along the rims.
  EXPECT_GT(visible, 0);
  EXPECT_GT(blocked, 0);
  EXPECT_GT(changes, 1);
}

// Parts whose flat faces look out along their planes past bosses and through gaps.
INSTANTIATE_TEST_SUITE_P(OcclusionProbe, RimParts,
                         testing::Values("prusa_rpi-zero-frame.stl", "prusa_x-end-motor.stl"));

}  // namespace
}  // namespace gvm
