// Regions and features of every shared part, with LVM(S + N_S) checked against brute
// force: u is in the LVM iff u . n >= 0 for every normal of S + N_S, decided here with GMP
// rationals independently of the engine's spherical code.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <random>

#include "exact/exact_vec.h"
#include "gvm/analysis.h"
#include "gvm/mesh.h"
#include "gvm/part.h"
#include "visibility/surface_visibility.h"

namespace gvm {
namespace {

namespace fs = std::filesystem;

bool brute_force_in_lvm(const SolidMesh& mesh, const std::vector<uint32_t>& tris,
                        const std::array<long, 3>& u) {
  for (uint32_t t : tris) {
    const Triangle& tri = mesh.triangles[t];
    mpq_class a[3], b[3];
    for (int i = 0; i < 3; ++i) {
      a[i] = mpq_class(mesh.points[tri[1]][i]) - mpq_class(mesh.points[tri[0]][i]);
      b[i] = mpq_class(mesh.points[tri[2]][i]) - mpq_class(mesh.points[tri[0]][i]);
    }
    mpq_class n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                      a[0] * b[1] - a[1] * b[0]};
    mpq_class dot = n[0] * u[0] + n[1] * u[1] + n[2] * u[2];
    if (dot < 0) return false;
  }
  return true;
}

std::vector<std::string> shared_parts() {
  std::vector<std::string> parts;
  for (const auto& e : fs::directory_iterator(std::string(GVM_SHARED_DIR) + "/data/parts")) {
    if (e.path().extension() != ".md") parts.push_back(e.path().string());
  }
  std::sort(parts.begin(), parts.end());
  return parts;
}

class SharedPart : public ::testing::TestWithParam<std::string> {};

TEST_P(SharedPart, LocalVisibilityMapsMatchBruteForce) {
  auto solid = load_solid(GetParam());
  ASSERT_TRUE(solid.ok()) << solid.status().message();
  auto t0 = std::chrono::steady_clock::now();
  auto part = Part::analyze(std::move(*solid), PartOptions{});
  ASSERT_TRUE(part.ok()) << part.status().message();
  const SolidMesh& mesh = part->mesh();

  // Directions with small integer coordinates: exact, and often exactly on the boundary
  // of the LVMs of axis-aligned CAD faces.
  const unsigned seed = 7;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(-3, 3);
  std::vector<std::array<long, 3>> dirs;
  while (dirs.size() < 60) {
    std::array<long, 3> u = {coord(rng), coord(rng), coord(rng)};
    if (u[0] || u[1] || u[2]) dirs.push_back(u);
  }
  // Every feature is checked on small parts, a sample of them on large ones.
  const auto& features = part->features();
  const size_t stride = std::max<size_t>(1, features.size() / 150);
  size_t checked = 0, inside = 0, void_surfaces = 0;
  for (size_t i = 0; i < features.size(); i += stride) {
    const Feature& f = features[i];
    SurfaceVisibility vis = compute_surface_visibility(*part, f.triangles);
    std::vector<uint32_t> tris = f.triangles;
    tris.insert(tris.end(), vis.occluders.neighbor.begin(), vis.occluders.neighbor.end());
    for (const auto& u : dirs) {
      bool expected = brute_force_in_lvm(mesh, tris, u);
      auto dir = exact::ExactVec::from_point({double(u[0]), double(u[1]), double(u[2])});
      ASSERT_EQ(vis.lvm.contains(dir), expected)
          << "feature " << f.id << " u (" << u[0] << "," << u[1] << "," << u[2]
          << ") seed " << seed << " lvm " << vis.lvm.description();
      inside += expected;
      ++checked;
    }
    if (vis.status == GvmStatus::kEmptyVoid) {
      ASSERT_TRUE(vis.gvm.has_value());
      EXPECT_TRUE(vis.gvm->is_empty()) << "a void face is never visible";
      ++void_surfaces;
    } else if (vis.occluders.potential.empty()) {
      ASSERT_TRUE(vis.gvm.has_value());
      EXPECT_TRUE(*vis.gvm == vis.lvm);
    } else {
      EXPECT_FALSE(vis.gvm.has_value()) << "no GVM is claimed while O_S is not handled";
    }
  }
  double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  RecordProperty("directions_checked", static_cast<int>(checked));
  if (fs::path(GetParam()).filename() == "prusa_y-motor-holder.stl") EXPECT_GT(void_surfaces, 0u);
  std::printf("%-40s %7zu triangles %5zu regions %6zu features, %zu checks (%zu inside), %.2f s\n",
              fs::path(GetParam()).filename().c_str(), mesh.triangles.size(),
              part->regions().size(), features.size(), checked, inside, secs);
}

INSTANTIATE_TEST_SUITE_P(Parts, SharedPart, ::testing::ValuesIn(shared_parts()),
                         [](const auto& info) {
                           std::string name = fs::path(info.param).stem().string();
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace gvm
