// Cost of the exact spherical arrangement and of the region unions built on it (paper
// Sec. 5.2), on n random small convex spherical polygons scattered over the sphere (at
// n = 1024 about one polygon covers a direction on average), and of the box tree that
// finds the candidate pairs.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "exact/exact_vec.h"
#include "sphere/arrangement.h"
#include "sphere/box_tree.h"
#include "sphere/region_union.h"

namespace gvm {
namespace {

using exact::ExactVec;
using sphere::ArrangementArc;
using D3 = std::array<double, 3>;

D3 cross(const D3& a, const D3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

D3 normalized(const D3& a) {
  const double n = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  return {a[0] / n, a[1] / n, a[2] / n};
}

// A polygon's boundary: arcs counter-clockwise seen from outside (the polygon on their
// left), normal = from x to, weight 1, layer 0; consecutive arcs share their vertex node.
using Polygon = std::vector<ArrangementArc>;

// n convex polygons of 3 to 6 vertices and angular radius 0.02 to 0.1 around random
// centers. The vertices lie on a plane tangent to the sphere at the center, so the
// polygon (a convex polygon of that plane, seen from the origin) is convex on the sphere.
std::vector<Polygon> random_polygons(size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> uni(0, 1);
  std::uniform_int_distribution<int> sides(3, 6);
  std::vector<Polygon> out;
  for (size_t i = 0; i < n; ++i) {
    const D3 c = normalized({gauss(rng), gauss(rng), gauss(rng)});
    const D3 helper = std::fabs(c[0]) < 0.6 ? D3{1, 0, 0} : D3{0, 1, 0};
    const D3 e1 = normalized(cross(c, helper)), e2 = cross(c, e1);  // e1 x e2 = c
    const int k = sides(rng);
    const double radius = std::tan(0.02 + 0.08 * uni(rng));
    const double phase = 2 * M_PI * uni(rng);
    std::vector<ExactVec> v;
    for (int j = 0; j < k; ++j) {
      // Angles increasing (counter-clockwise around c), jittered but in order.
      const double a = phase + 2 * M_PI * (j + 0.4 * (uni(rng) - 0.5)) / k;
      const double x = radius * std::cos(a), y = radius * std::sin(a);
      v.push_back(ExactVec::from_point(
          {c[0] + x * e1[0] + y * e2[0], c[1] + x * e1[1] + y * e2[1], c[2] + x * e1[2] + y * e2[2]}));
    }
    Polygon p;
    for (int j = 0; j < k; ++j) {
      const ExactVec &from = v[j], &to = v[(j + 1) % k];
      p.push_back({from, to, exact::cross(from, to), 0, 1});
    }
    out.push_back(std::move(p));
  }
  return out;
}

// A convex polygon smaller than a hemisphere is the intersection of its arcs' closed
// hemispheres; the reference lies on no circle, so "inside" is strict.
bool covers(const Polygon& p, const ExactVec& r) {
  for (const ArrangementArc& a : p) {
    if (exact::sign_dot(r, a.normal) != Sign::kPositive) return false;
  }
  return true;
}

// Small integer directions in turn until one lies on none of the circles.
ExactVec reference_direction(const std::vector<Polygon>& polygons) {
  for (int k = 1;; ++k) {
    const ExactVec r =
        ExactVec::from_point({double(2 * k + 1), double(-3 * k - 5), double(7 * k + 2)});
    bool ok = true;
    for (const Polygon& p : polygons) {
      for (const ArrangementArc& a : p) ok = ok && exact::sign_dot(r, a.normal) != Sign::kZero;
    }
    if (ok) return r;
  }
}

struct Input {
  std::vector<Polygon> polygons;
  std::vector<ArrangementArc> arcs;  // all polygons' arcs
  ExactVec reference;
  int coverage = 0;                  // polygons containing the reference
};

Input make_input(size_t n) {
  Input in;
  in.polygons = random_polygons(n, 1234);
  for (const Polygon& p : in.polygons) in.arcs.insert(in.arcs.end(), p.begin(), p.end());
  in.reference = reference_direction(in.polygons);
  for (const Polygon& p : in.polygons) in.coverage += covers(p, in.reference) ? 1 : 0;
  return in;
}

void BM_Arrangement(benchmark::State& state) {
  const Input in = make_input(size_t(state.range(0)));
  const int coverage[1] = {in.coverage};
  size_t vertices = 0, edges = 0, faces = 0;
  for (auto _ : state) {
    sphere::Arrangement arr(in.arcs, {}, 1, in.reference, coverage);
    benchmark::DoNotOptimize(arr);
    vertices = arr.vertices().size();
    edges = arr.edges().size();
    faces = arr.faces().size();
  }
  state.counters["arcs"] = double(in.arcs.size());
  state.counters["vertices"] = double(vertices);
  state.counters["edges"] = double(edges);
  state.counters["faces"] = double(faces);
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_Arrangement)->RangeMultiplier(4)->Range(16, 1024)->Unit(benchmark::kMillisecond)->Complexity();

// The closed region covered by some polygon, from one arrangement of all their arcs.
void BM_PositiveRegion(benchmark::State& state) {
  const Input in = make_input(size_t(state.range(0)));
  sphere::Region region;
  for (auto _ : state) {
    region = sphere::positive_region(in.arcs, in.reference, in.coverage);
    benchmark::DoNotOptimize(region);
  }
  state.counters["arcs"] = double(in.arcs.size());
  state.counters["vertices"] = double(region.arrangement_vertices);
  state.counters["boundary_arcs"] = double(region.boundary.size());
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_PositiveRegion)->RangeMultiplier(4)->Range(16, 1024)->Unit(benchmark::kMillisecond)->Complexity();

// The same region as the union, up a balanced tree, of the regions of groups of 8
// polygons (computed once, outside the timed loop; the copy of the parts is timed).
// The merges run in parallel (TBB): timed in real time.
void BM_RegionUnion(benchmark::State& state) {
  const Input in = make_input(size_t(state.range(0)));
  constexpr size_t kGroup = 8;
  std::vector<sphere::Region> parts;
  for (size_t g = 0; g < in.polygons.size(); g += kGroup) {
    std::vector<ArrangementArc> arcs;
    int coverage = 0;
    for (size_t i = g; i < std::min(g + kGroup, in.polygons.size()); ++i) {
      arcs.insert(arcs.end(), in.polygons[i].begin(), in.polygons[i].end());
      coverage += covers(in.polygons[i], in.reference) ? 1 : 0;
    }
    parts.push_back(sphere::positive_region(arcs, in.reference, coverage));
  }
  uint64_t group_vertices = 0;
  for (const sphere::Region& r : parts) group_vertices += r.arrangement_vertices;
  sphere::Region region;
  for (auto _ : state) {
    region = sphere::region_union(parts, in.reference);
    benchmark::DoNotOptimize(region);
  }
  state.counters["groups"] = double(parts.size());
  state.counters["vertices"] = double(region.arrangement_vertices - group_vertices);
  state.counters["boundary_arcs"] = double(region.boundary.size());
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_RegionUnion)
    ->RangeMultiplier(4)
    ->Range(16, 1024)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Complexity();

// n boxes around random points of the unit sphere (boxes around short arcs, as the
// arrangement builds them), their half-sizes shrinking like 1 / sqrt(n) so that a box
// overlaps about as many others whatever n (the pairs grow linearly).
std::vector<sphere::Box> random_boxes(size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss;
  const double scale = std::sqrt(4 * M_PI / double(n));
  std::uniform_real_distribution<double> half(0.25 * scale, scale);
  std::vector<sphere::Box> out(n);
  for (sphere::Box& b : out) {
    const D3 c = normalized({gauss(rng), gauss(rng), gauss(rng)});
    for (int i = 0; i < 3; ++i) {
      const double h = half(rng);
      b.lo[i] = c[i] - h;
      b.hi[i] = c[i] + h;
    }
  }
  return out;
}

void BM_BoxTreeOverlappingPairs(benchmark::State& state) {
  const std::vector<sphere::Box> boxes = random_boxes(size_t(state.range(0)), 99);
  const sphere::BoxTree tree(boxes);
  size_t pairs = 0;
  for (auto _ : state) {
    auto p = tree.overlapping_pairs();
    benchmark::DoNotOptimize(p);
    pairs = p.size();
  }
  state.counters["pairs"] = double(pairs);
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_BoxTreeOverlappingPairs)->RangeMultiplier(8)->Range(64, 1 << 15)->Complexity();

void BM_BoxTreeBuild(benchmark::State& state) {
  const std::vector<sphere::Box> boxes = random_boxes(size_t(state.range(0)), 99);
  for (auto _ : state) {
    sphere::BoxTree tree(boxes);
    benchmark::DoNotOptimize(tree);
  }
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_BoxTreeBuild)->RangeMultiplier(8)->Range(64, 1 << 15)->Complexity();

}  // namespace
}  // namespace gvm
