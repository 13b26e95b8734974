// The probe's strip events carry what they are built from, so that the events neighbouring
// triangles of O share are found by their keys alone (occlusion_probe.cpp merges them and
// tags each with every triangle that has it). A key must name one line: checked exactly on
// the planes of real features and every occluder touching them.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "gvm/part.h"
#include "support/shared_parts.h"
#include "visibility/strip_events.h"
#include "visibility/surface_visibility.h"

namespace gvm {
namespace {

TEST(StripEvents, EqualKeysAreEqualLines) {
  if (!test::has_shared_part("prusa_x-end-idler.stl")) GTEST_SKIP() << "no prusa_x-end-idler.stl";
  auto part = test::analyze_shared_part("prusa_x-end-idler.stl");
  ASSERT_TRUE(part.ok()) << part.status().message();
  const SolidMesh& mesh = part->mesh();
  size_t events = 0, shared = 0, planes = 0;
  for (const Feature& f : part->features()) {
    if (f.triangles.size() < 4 || planes >= 12) continue;
    const std::vector<uint32_t> o = compute_surface_visibility(*part, f.triangles).occluders.potential;
    for (const auto& [plane, triangles] : strip_planes(mesh, f.triangles)) {
      ++planes;
      std::map<std::array<uint32_t, 4>, exact::ExactVec> line_of;
      for (uint32_t t : o) {
        if (!touches(mesh, plane, t)) continue;
        std::vector<StripEvent> mine;
        add_strip_events(mesh, plane, t, mine);
        for (const StripEvent& e : mine) {
          ++events;
          // Every event is a direction in the plane.
          ASSERT_EQ(exact::sign_dot(e.line, plane.normal), Sign::kZero) << f.name;
          const auto [it, inserted] = line_of.emplace(e.key, e.line);
          if (inserted) continue;
          ++shared;
          ASSERT_TRUE(exact::parallel(it->second, e.line))
              << f.name << ": key " << e.key[0] << " " << e.key[1] << " " << e.key[2] << " " << e.key[3];
        }
      }
    }
  }
  EXPECT_GT(planes, 0u);
  // Events met again under one key were compared above (4,643 of 11,881 when written).
  EXPECT_GT(shared, 0u) << events << " events";
}

}  // namespace
}  // namespace gvm
