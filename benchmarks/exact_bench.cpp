// Cost of the exact kernel: the filtered path (a certified sign from doubles) against the
// exact path (a zero or near-zero value, decided by GMP), and of the LVM of many normals.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "exact/exact_vec.h"
#include "exact/predicates.h"
#include "sphere/local_visibility_map.h"

namespace gvm {
namespace {

std::vector<Point3> random_points(size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> c(-100, 100);
  std::vector<Point3> p(n);
  for (auto& q : p) q = {c(rng), c(rng), c(rng)};
  return p;
}

// Generic positions: the filter decides.
void BM_Orient3dFiltered(benchmark::State& state) {
  auto p = random_points(1024, 1);
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(exact::orient3d(p[i & 1023], p[(i + 1) & 1023], p[(i + 2) & 1023],
                                             p[(i + 3) & 1023]));
    ++i;
  }
}
BENCHMARK(BM_Orient3dFiltered);

// Exactly coplanar points with non-representable differences: every call goes exact.
void BM_Orient3dExactZero(benchmark::State& state) {
  Point3 a{1e12, -1e12, 0}, b{1e-12, 0, -1e-12}, c{0, 0x1p-40, -0x1p-40},
      d{0x1p40, 1, -(0x1p40 + 1)};
  for (auto _ : state) benchmark::DoNotOptimize(exact::orient3d(a, b, c, d));
}
BENCHMARK(BM_Orient3dExactZero);

// The predicate of the Minkowski-sum faces on axis-aligned (CAD-like) input: zeros.
void BM_DetDiffAxisAlignedZero(benchmark::State& state) {
  Point3 a0{0, 0, 0}, a1{10, 0, 0}, b0{0, 0, 0}, b1{0, 7, 0}, c0{3, 4, 5}, c1{8, 1, 5};
  for (auto _ : state) benchmark::DoNotOptimize(exact::det_diff(a0, a1, b0, b1, c0, c1));
}
BENCHMARK(BM_DetDiffAxisAlignedZero);

// LVM of the normals of a tessellated cylindrical pocket wall and its floor: n facets.
void BM_LocalVisibilityMap(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  std::vector<exact::ExactVec> normals;
  for (int k = 0; k < n; ++k) {
    // Integer approximations of the facet normals keep the input exact and generic.
    double x = std::round(1000 * std::cos(2 * M_PI * k / n));
    double y = std::round(1000 * std::sin(2 * M_PI * k / n));
    normals.push_back(exact::ExactVec::from_point({-x, -y, 0}));
  }
  normals.push_back(exact::ExactVec::from_point({0, 0, 1}));
  for (auto _ : state) benchmark::DoNotOptimize(sphere::local_visibility_map(normals));
  state.SetComplexityN(n);
}
BENCHMARK(BM_LocalVisibilityMap)->RangeMultiplier(4)->Range(16, 4096)->Complexity();

}  // namespace
}  // namespace gvm
