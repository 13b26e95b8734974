#include "support/real_feature.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>

#include "gvm/mesh.h"
#include "visibility/surface_visibility.h"

namespace gvm::bench {
namespace {

// The first of these found is used, unless GVM_BENCH_PART names another part file.
constexpr const char* kDefaultParts[] = {"occt_TR12J_OCC.stl", "trimesh_featuretype_from_step.off"};
// One envelope of |S| * |O_S| below this takes well under a second.
constexpr uint64_t kMaxWork = 300000;

std::string part_path(std::string* error) {
  const char* env_dir = std::getenv("GVM_SHARED_DIR");
  const std::string dir = std::string(env_dir && *env_dir ? env_dir : "../shared") + "/data/parts/";
  const char* env_part = std::getenv("GVM_BENCH_PART");
  std::vector<std::string> names(std::begin(kDefaultParts), std::end(kDefaultParts));
  if (env_part && *env_part) names = {env_part};
  for (const std::string& name : names) {
    if (std::filesystem::exists(dir + name)) return dir + name;
  }
  *error = "part " + names[0] + " not found in " + dir + " (set GVM_SHARED_DIR to the shared directory)";
  return {};
}

RealFeature load_real_feature() {
  RealFeature r;
  const std::string path = part_path(&r.error);
  if (path.empty()) return r;
  StatusOr<SolidMesh> mesh = load_solid(path);
  if (!mesh.ok()) {
    r.error = mesh.status().message();
    return r;
  }
  StatusOr<Part> part = Part::analyze(std::move(mesh).value(), PartOptions{});
  if (!part.ok()) {
    r.error = part.status().message();
    return r;
  }
  r.part.emplace(std::move(part).value());
  // O_S lies in the concave regions of S's triangles, so |S| times their size bounds
  // |S| * |O_S|: features are tried by decreasing bound until no better one can follow
  // (computing O_S of every feature of a large part takes seconds).
  const Part& pt = *r.part;
  std::vector<std::pair<uint64_t, const Feature*>> order;
  for (const Feature& f : pt.features()) {
    std::set<int32_t> regions;
    for (uint32_t t : f.triangles) regions.insert(pt.region_of(t));
    uint64_t region_triangles = 0;
    for (int32_t id : regions) region_triangles += id < 0 ? 0 : pt.regions()[id].triangles.size();
    if (region_triangles) order.push_back({f.triangles.size() * region_triangles, &f});
  }
  std::stable_sort(order.begin(), order.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  uint64_t best = 0;
  for (const auto& [bound, f] : order) {
    if (bound <= best) break;
    SurfaceVisibility sv = compute_surface_visibility(pt, f->triangles, false);
    if (sv.status != GvmStatus::kGlobalOcclusionNotComputed) continue;  // no occlusion to compute
    const uint64_t work = uint64_t(f->triangles.size()) * sv.occluders.potential.size();
    if (work >= kMaxWork || work <= best) continue;
    best = work;
    r.feature = f->id;
    r.s = f->triangles;
    r.o = std::move(sv.occluders.potential);
    r.lvm = std::move(sv.lvm);
  }
  if (best == 0) {
    r.error = "no feature of " + path + " with potential occluders and |S| * |O_S| < 300000";
    return r;
  }
  r.window = std::make_unique<DirectionWindow>(r.lvm, coordinate_bound(r.part->mesh(), r.s, r.o));
  return r;
}

}  // namespace

const RealFeature& real_feature() {
  static const RealFeature r = load_real_feature();
  return r;
}

}  // namespace gvm::bench
