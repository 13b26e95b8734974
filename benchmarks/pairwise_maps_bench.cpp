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
#include "support/real_feature.h"
#include "visibility/convex_decomposition.h"
#include "visibility/direction_window.h"
#include "visibility/surface_visibility.h"

namespace gvm {
namespace {

using bench::RealFeature;
using bench::real_feature;

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
