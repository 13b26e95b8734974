// Part analysis on the shared real parts: every part analyzes; hull facets agree with a
// brute force on the small ones; per-part counts and timings are printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <span>

#include "exact/predicates.h"
#include "gvm/part.h"
#include "support/shared_parts.h"

namespace gvm {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> shared_parts() {
  std::vector<std::string> out;
  const fs::path dir = fs::path(GVM_SHARED_DIR) / "data" / "parts";
  if (!fs::is_directory(dir)) return out;
  for (const auto& e : fs::directory_iterator(dir)) {
    std::string ext = e.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    if (ext == ".off" || ext == ".stl" || ext == ".obj" || ext == ".ply")
      out.push_back(e.path().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// O_S by conditions (i) and (ii) of Def. 5 over every pair of S and the part, no pruning.
std::vector<uint32_t> occluders_by_definition(const Part& p, std::span<const uint32_t> s,
                                              std::span<const uint32_t> n) {
  const SolidMesh& m = p.mesh();
  auto pt = [&](uint32_t t, int i) -> const Point3& { return m.points[m.triangles[t][i]]; };
  std::vector<uint32_t> expect;
  for (uint32_t c = 0; c < m.triangles.size(); ++c) {
    if (p.is_hull(c) || std::binary_search(s.begin(), s.end(), c) || std::binary_search(n.begin(), n.end(), c))
      continue;
    bool found = false;
    for (size_t i = 0; i < s.size() && !found; ++i) {
      const uint32_t fs = s[i];
      if (p.region_of(fs) != p.region_of(c)) continue;
      bool c1 = false, c2 = false;
      for (int k = 0; k < 3; ++k) {
        c1 |= exact::orient3d(pt(c, 0), pt(c, 1), pt(c, 2), pt(fs, k)) == Sign::kPositive;
        c2 |= exact::orient3d(pt(fs, 0), pt(fs, 1), pt(fs, 2), pt(c, k)) != Sign::kNegative;
      }
      found = c1 && c2;
    }
    if (found) expect.push_back(c);
  }
  return expect;
}

TEST(PartShared, EveryPartAnalyzes) {
  auto files = shared_parts();
  if (files.empty()) GTEST_SKIP() << "no shared parts in " << GVM_SHARED_DIR;
  std::printf("%-36s %8s %8s %7s %8s %9s %9s\n", "part", "tris", "hull", "regions",
              "features", "load s", "analyze s");
  for (const std::string& path : files) {
    const std::string name = fs::path(path).filename().string();
    auto t0 = std::chrono::steady_clock::now();
    auto mesh = load_solid(path);
    double t_load = seconds_since(t0);
    if (!mesh.ok()) {
      ADD_FAILURE() << name << ": load_solid failed: " << mesh.status().message();
      continue;
    }
    SolidMesh copy = mesh.value();
    t0 = std::chrono::steady_clock::now();
    auto part = Part::analyze(std::move(mesh).value(), {});
    double t_analyze = seconds_since(t0);
    ASSERT_TRUE(part.ok()) << name << ": " << part.status().message();
    const Part& p = part.value();
    const size_t nt = p.mesh().triangles.size();
    size_t hull = 0;
    for (uint32_t t = 0; t < nt; ++t) hull += p.is_hull(t);
    std::printf("%-36s %8zu %8zu %7zu %8zu %9.3f %9.3f\n", name.c_str(), nt, hull,
                p.regions().size(), p.features().size(), t_load, t_analyze);
    std::fflush(stdout);

    // Consistency: regions partition the non-hull triangles, features partition all.
    std::vector<int> seen(nt, 0);
    for (const auto& r : p.regions())
      for (uint32_t t : r.triangles) {
        EXPECT_FALSE(p.is_hull(t));
        EXPECT_EQ(p.region_of(t), int32_t(r.id));
        ++seen[t];
      }
    for (uint32_t t = 0; t < nt; ++t) EXPECT_EQ(seen[t], p.is_hull(t) ? 0 : 1) << name;
    std::fill(seen.begin(), seen.end(), 0);
    for (const auto& f : p.features())
      for (uint32_t t : f.triangles) ++seen[t];
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; })) << name;

    // Brute-force hull check on the small parts.
    if (nt <= 10000) {
      const auto& m = p.mesh();
      std::vector<uint32_t> used;
      for (const Triangle& t : m.triangles) used.insert(used.end(), t.begin(), t.end());
      std::sort(used.begin(), used.end());
      used.erase(std::unique(used.begin(), used.end()), used.end());
      size_t wrong = 0;
      for (uint32_t t = 0; t < nt; ++t) {
        const Triangle& tr = m.triangles[t];
        bool bf = true;
        for (uint32_t v : used)
          if (exact::orient3d(m.points[tr[0]], m.points[tr[1]], m.points[tr[2]], m.points[v]) ==
              Sign::kPositive) {
            bf = false;
            break;
          }
        wrong += bf != p.is_hull(t);
      }
      EXPECT_EQ(wrong, 0u) << name;

      // O_S of a few non-hull features against the definition (no pruning).
      int checked = 0;
      for (const Feature& f : p.features()) {
        if (f.on_hull || checked == 3) continue;
        ++checked;
        const std::vector<uint32_t> n = p.neighbor_occluders(f.triangles);
        EXPECT_EQ(p.potential_occluders(f.triangles, n, [](uint32_t) { return true; }),
                  occluders_by_definition(p, f.triangles, n))
            << name << " feature " << f.id;
      }
    }
  }
}

// Feature counts against the angle, on the parts that show the typical CAD surfaces.
// A larger feature angle only merges: every feature at a smaller angle lies inside one
// feature at a larger angle, so the counts never grow (docs/method.md's feature counts
// came from this sweep).
TEST(PartShared, FeaturesCoarsenAsTheAngleGrows) {
  const std::vector<std::string> names = {"trimesh_featuretype_from_step.off", "occt_sh1.stl",
                                          "trimesh_20mm-xyz-cube.stl"};
  for (const std::string& n : names) {
    auto mesh = load_solid(std::string(GVM_SHARED_DIR) + "/data/parts/" + n);
    ASSERT_TRUE(mesh.ok()) << mesh.status().message();
    std::vector<uint32_t> coarser;  // feature of each triangle at the previous angle
    size_t previous = SIZE_MAX;
    for (double angle : {5.0, 10.0, 20.0, 30.0, 40.0, 60.0}) {
      PartOptions opt;
      opt.feature_angle_degrees = angle;
      auto p = Part::analyze(mesh.value(), opt);
      ASSERT_TRUE(p.ok());
      std::vector<uint32_t> feature_of(mesh->triangles.size());
      for (const Feature& f : p->features()) {
        for (uint32_t t : f.triangles) feature_of[t] = f.id;
      }
      EXPECT_LE(p->features().size(), previous) << n << " at " << angle << " deg";
      if (!coarser.empty()) {
        // Triangles together at the smaller angle stay together.
        std::vector<uint32_t> image(previous, UINT32_MAX);
        for (size_t t = 0; t < feature_of.size(); ++t) {
          uint32_t& at = image[coarser[t]];
          if (at == UINT32_MAX) at = feature_of[t];
          EXPECT_EQ(at, feature_of[t]) << n << ": triangle " << t << " left its feature at " << angle << " deg";
        }
      }
      previous = p->features().size();
      coarser = std::move(feature_of);
    }
    EXPECT_LT(previous, mesh->triangles.size()) << n;  // something merged at all
  }
}

// The search prunes by both conditions on bounds of S's triangles (boxes for (i), the
// planes' coefficients for (ii)); curved features of many triangles on a threaded part are
// where the bounds of (ii) cut most.
TEST(PartShared, OccluderSearchOfCurvedFeaturesIsTheDefinition) {
  if (!test::has_shared_part("occt_TR12J_OCC.stl")) GTEST_SKIP() << "no occt_TR12J_OCC.stl";
  auto part = test::analyze_shared_part("occt_TR12J_OCC.stl");
  ASSERT_TRUE(part.ok()) << part.status().message();
  int checked = 0;
  size_t found = 0;
  for (const Feature& f : part->features()) {
    if (f.on_hull || f.triangles.size() < 16 || f.triangles.size() > 200 || checked == 3) continue;
    ++checked;
    const std::vector<uint32_t> n = part->neighbor_occluders(f.triangles);
    const std::vector<uint32_t> expect = occluders_by_definition(*part, f.triangles, n);
    EXPECT_EQ(part->potential_occluders(f.triangles, n, [](uint32_t) { return true; }), expect) << f.name;
    found += expect.size();
  }
  EXPECT_EQ(checked, 3);
  EXPECT_GT(found, 0u);
}

}  // namespace
}  // namespace gvm
