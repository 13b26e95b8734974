// The robust mode of the oracle that checks the arcs and points of GVMs: rays along such
// directions often graze the part, which it must count as visible, while a ray that gets
// into the solid at a concave corner (no front hit a sampled ray could show) must count
// as blocked.
#include <gtest/gtest.h>

#include "gvm/mesh.h"
#include "support/ray_oracle.h"
#include "support/test_parts.h"

namespace gvm {
namespace {

oracle::OracleOptions robust_options() {
  oracle::OracleOptions o;
  o.barycentric_tolerance = -1e-7;
  o.front_tolerance = o.self_tolerance = 1e-7;
  o.exits_block = true;
  return o;
}

struct Grooved {
  RawMesh raw = test::grooved_pocket_part();
  SolidMesh mesh = *build_solid(raw);
  std::vector<uint32_t> of(std::initializer_list<std::string> names) const {
    return test::triangles_of(mesh, raw, names);
  }
};

TEST(RayOracle, RobustModeCountsGrazingRaysVisible) {
  const Grooved g;
  const oracle::RayOracle robust(g.mesh, robust_options());
  const oracle::Vec up{0, 0, 1};
  // Along the axis the floor's rays pass the groove's rims, the lower walls' rays run
  // along the upper walls: grazing only.
  EXPECT_TRUE(robust.surface_visible(g.of({"floor"}), up));
  EXPECT_TRUE(robust.surface_visible(g.of({"lower_x0", "lower_x1", "lower_y0", "lower_y1"}), up));
  EXPECT_TRUE(robust.surface_visible(g.of({"upper_x0", "upper_x1", "upper_y0", "upper_y1"}), up));
}

TEST(RayOracle, ExitsBlockRaysThatGetInAtAConcaveCorner) {
  const Grooved g;
  const auto upper = g.of({"upper_x0", "upper_x1", "upper_y0", "upper_y1"});
  const oracle::Vec down{0, 0, -1};
  // Straight down, the upper walls' rays run along the lower walls into the floor's
  // concave rim and on through the material: only their exit shows it.
  EXPECT_FALSE(oracle::RayOracle(g.mesh, robust_options()).surface_visible(upper, down));
  oracle::OracleOptions front_only = robust_options();
  front_only.exits_block = false;
  EXPECT_TRUE(oracle::RayOracle(g.mesh, front_only).surface_visible(upper, down))
      << "without exits the robust oracle could not see this corner";
  // Tilted into the groove, the floor is blocked by a front hit as before.
  EXPECT_FALSE(oracle::RayOracle(g.mesh, robust_options()).surface_visible(g.of({"floor"}), {0.6, 0, 0.8}));
}

}  // namespace
}  // namespace gvm
