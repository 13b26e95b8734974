// Cost of the convex-decomposition baseline (the paper's reference [18]): the occlusion
// map of one triangle pair from its nine differences q - p, for separated pairs (a pointed
// cone) and for pairs sharing a vertex (eight non-zero differences; the cone may be the
// whole space), and all maps of a real feature against its potential occluders.
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
#include <random>
#include <span>
#include <string>
#include <vector>

#include "exact/exact_vec.h"
#include "gvm/mesh.h"
#include "gvm/part.h"
#include "visibility/convex_decomposition.h"
#include "visibility/direction_window.h"
#include "visibility/surface_visibility.h"

namespace gvm {
namespace {

using exact::ExactVec;

constexpr size_t kCases = 256;

struct PairCase {
  std::vector<ExactVec> differences;
};

// The differences q - p of two triangles, each vertex a leaf shared by the differences
// that use it (as pairwise_occlusion_maps shares them), zero differences left out.
PairCase pair_case(const std::array<Point3, 3>& fs, const std::array<Point3, 3>& fo) {
  PairCase c;
  for (const Point3& q : fo) {
    for (const Point3& p : fs) {
      if (q == p) continue;
      c.differences.push_back(ExactVec::from_point(q) - ExactVec::from_point(p));
    }
  }
  return c;
}

// F_S near the origin, F_O near (0, 0, 10): every difference has z > 0, the cone they
// span is pointed and its map a convex polygon (up to 6 sides).
std::vector<PairCase> pointed_cases() {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> c(-1, 1);
  std::vector<PairCase> out;
  for (size_t i = 0; i < kCases; ++i) {
    std::array<Point3, 3> fs, fo;
    for (Point3& p : fs) p = {c(rng), c(rng), c(rng)};
    for (Point3& q : fo) q = {c(rng), c(rng), 10 + c(rng)};
    out.push_back(pair_case(fs, fo));
  }
  return out;
}

// F_S and F_O share the vertex v (as neighbouring faces of a mesh do): the zero
// difference drops out, the cone of the other eight is pointed or the whole space.
std::vector<PairCase> touching_cases() {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> c(-1, 1);
  std::vector<PairCase> out;
  for (size_t i = 0; i < kCases; ++i) {
    const Point3 v{c(rng), c(rng), c(rng)};
    auto near_v = [&] { return Point3{v.x + c(rng), v.y + c(rng), v.z + c(rng)}; };
    std::array<Point3, 3> fs{v, near_v(), near_v()}, fo{near_v(), v, near_v()};
    out.push_back(pair_case(fs, fo));
  }
  return out;
}

void run_pairwise(benchmark::State& state, const std::vector<PairCase>& cases) {
  size_t i = 0;
  for (auto _ : state) {
    sphere::SphericalImage map = gvm::pairwise_occlusion_map(cases[i % kCases].differences);
    benchmark::DoNotOptimize(map);
    ++i;
  }
  // The mix of outcomes over the cases (outside the timed loop).
  size_t polygons = 0, full = 0, arcs = 0;
  for (const PairCase& c : cases) {
    const sphere::SphericalImage map = gvm::pairwise_occlusion_map(c.differences);
    if (map.is_full_sphere()) ++full;
    if (map.dimension() == 2 && !map.is_full_sphere()) {
      ++polygons;
      arcs += map.faces()[0].loops[0].arcs.size();
    }
  }
  state.counters["polygon_frac"] = double(polygons) / kCases;
  state.counters["full_sphere_frac"] = double(full) / kCases;
  state.counters["arcs_per_polygon"] = polygons ? double(arcs) / polygons : 0.0;
}

void BM_PairwiseOcclusionMapPointed(benchmark::State& state) {
  static const std::vector<PairCase> cases = pointed_cases();
  run_pairwise(state, cases);
}
BENCHMARK(BM_PairwiseOcclusionMapPointed);

void BM_PairwiseOcclusionMapTouching(benchmark::State& state) {
  static const std::vector<PairCase> cases = touching_cases();
  run_pairwise(state, cases);
}
BENCHMARK(BM_PairwiseOcclusionMapTouching);

// ---- A real feature -------------------------------------------------------------------

// The first of these found is used, unless GVM_BENCH_PART names another part file.
constexpr const char* kDefaultParts[] = {"occt_TR12J_OCC.stl", "trimesh_featuretype_from_step.off"};
constexpr uint64_t kMaxWork = 300000;  // |S| * |O_S|: one run well under a second

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

// Same choice as envelope_bench.cpp: the largest |S| * |O_S| below kMaxWork.
struct RealFeature {
  std::string error;
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

// Arg: window (0/1). Without the window every pair is computed (tens of microseconds
// each), so only the first occluders of O_S are taken, about kMaxPairsWithoutWindow pairs
// (counter O_used); with the window, all of O_S. The maps are computed in parallel (TBB):
// timed in real time.
constexpr size_t kMaxPairsWithoutWindow = 20000;

void BM_PairwiseOcclusionMapsRealFeature(benchmark::State& state) {
  const RealFeature& f = real_feature();
  if (!f.error.empty()) {
    state.SkipWithError(f.error.c_str());
    return;
  }
  const DirectionWindow* window = state.range(0) ? f.window.get() : nullptr;
  std::span<const uint32_t> o = f.o;
  if (!window) o = o.first(std::min(o.size(), std::max<size_t>(1, kMaxPairsWithoutWindow / f.s.size())));
  ConvexDecompositionStatistics stats;
  for (auto _ : state) {
    stats = {};
    std::vector<sphere::SphericalImage> maps =
        gvm::pairwise_occlusion_maps(f.part->mesh(), f.s, o, window, &stats);
    benchmark::DoNotOptimize(maps);
  }
  state.counters["feature"] = f.feature;
  state.counters["S"] = double(f.s.size());
  state.counters["O_S"] = double(f.o.size());
  state.counters["O_used"] = double(o.size());
  state.counters["pairs"] = double(stats.pairs);
  state.counters["outside_window"] = double(stats.outside_window);
  state.counters["maps"] = double(stats.maps);
  state.counters["map_arcs"] = double(stats.map_arcs);
  state.counters["pairs_per_s"] =
      benchmark::Counter(double(stats.pairs), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_PairwiseOcclusionMapsRealFeature)
    ->ArgName("window")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace gvm
