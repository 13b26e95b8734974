// Cost of the effective Minkowski envelope (paper Sec. 4) of a real feature: generating
// the tentative VF, FV and EE faces, filtering them by their critical sets and keeping the
// back-facing ones, with and without the direction window of LVM(S + N_S).
//
// The part (occt_TR12J_OCC.stl, else trimesh_featuretype_from_step.off, or the file named
// by GVM_BENCH_PART) is read from $GVM_SHARED_DIR/data/parts, else ../shared/data/parts
// relative to the working directory; without it these benchmarks are skipped with an
// error. The feature: the largest |S| * |O_S| below 300000 (TR12J: feature 9, 80 x 3440).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "gvm/mesh.h"
#include "gvm/part.h"
#include "visibility/direction_window.h"
#include "visibility/effective_minkowski_envelope.h"
#include "visibility/surface_visibility.h"

namespace gvm {
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

double coordinate_bound(const SolidMesh& mesh, const std::vector<uint32_t>& a,
                        const std::vector<uint32_t>& b) {
  double bound = 0;
  for (const auto* triangles : {&a, &b}) {
    for (uint32_t t : *triangles) {
      for (uint32_t v : mesh.triangles[t]) {
        const Point3& p = mesh.points[v];
        bound = std::max({bound, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
      }
    }
  }
  return bound;
}

// The feature of the part with the largest |S| * |O_S| below kMaxWork, its potential
// occluders, its LVM and the window built from it. Loaded once, on first use.
struct RealFeature {
  std::string error;  // set when there is no feature to benchmark
  std::optional<Part> part;
  uint32_t feature = 0;
  std::vector<uint32_t> s, o;
  sphere::SphericalImage lvm;
  std::unique_ptr<DirectionWindow> window;
};

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
    if (sv.kind != GvmKind::kGlobalOcclusionNotComputed) continue;  // no occlusion to compute
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

const RealFeature& real_feature() {
  static const RealFeature r = load_real_feature();
  return r;
}

// Args: {window, keep_faces}. The envelope runs in parallel (TBB): timed in real time.
void BM_EnvelopeRealFeature(benchmark::State& state) {
  const RealFeature& f = real_feature();
  if (!f.error.empty()) {
    state.SkipWithError(f.error.c_str());
    return;
  }
  const DirectionWindow* window = state.range(0) ? f.window.get() : nullptr;
  const bool keep_faces = state.range(1) != 0;
  EnvelopeStatistics stats;
  size_t border = 0;
  for (auto _ : state) {
    EffectiveMinkowskiEnvelope eme =
        compute_effective_minkowski_envelope(f.part->mesh(), f.s, f.o, keep_faces, window);
    benchmark::DoNotOptimize(eme);
    stats = eme.statistics;
    border = eme.border.size();
  }
  state.counters["feature"] = f.feature;
  state.counters["S"] = double(f.s.size());
  state.counters["O_S"] = double(f.o.size());
  state.counters["window_halfspaces"] = window ? double(window->size()) : 0.0;
  state.counters["tentative"] = double(stats.tentative_faces);
  state.counters["outside_window"] = double(stats.outside_window);
  state.counters["kept"] = double(stats.kept_faces);
  state.counters["envelope_faces"] = double(stats.envelope_faces);
  state.counters["border_arcs"] = double(border);
  state.counters["tentative_per_s"] =
      benchmark::Counter(double(stats.tentative_faces), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_EnvelopeRealFeature)
    ->ArgNames({"window", "keep_faces"})
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({1, 1})  // as in global_visibility_map
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The window itself: building it from the LVM (its half-spaces per LVM cell).
void BM_DirectionWindowBuild(benchmark::State& state) {
  const RealFeature& f = real_feature();
  if (!f.error.empty()) {
    state.SkipWithError(f.error.c_str());
    return;
  }
  const double bound = coordinate_bound(f.part->mesh(), f.s, f.o);
  for (auto _ : state) {
    DirectionWindow w(f.lvm, bound);
    benchmark::DoNotOptimize(w.size());
  }
  state.counters["window_halfspaces"] = double(f.window->size());
}
BENCHMARK(BM_DirectionWindowBuild);

}  // namespace
}  // namespace gvm
