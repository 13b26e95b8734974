// Runs of arrangement edges along one circle (probed_runs.h): every selected edge in one
// run, each run a chain through vertices where exactly two selected edges meet, its arc
// from the first edge's start to the last one's end, shorter than 180 degrees.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <vector>

#include "sphere/arrangement.h"
#include "visibility/probed_runs.h"

namespace gvm {
namespace {

using exact::ExactVec;
using sphere::Arrangement;
using sphere::ArrangementArc;

ExactVec v(double x, double y, double z) { return ExactVec::from_point({x, y, z}); }
ExactVec at_longitude(double degrees, double z) {
  return v(std::cos(degrees * M_PI / 180), std::sin(degrees * M_PI / 180), z);
}

// The equator in four arcs of layer 0, cut by short meridian arcs of layer 1; with
// `branch`, one more arc of layer 0 leaves the equator northwards at (0, 1, 0).
Arrangement equator(bool branch) {
  std::vector<ArrangementArc> arcs;
  const ExactVec up = v(0, 0, 1);
  const ExactVec quarter[4] = {v(1, 0, 0), v(0, 1, 0), v(-1, 0, 0), v(0, -1, 0)};
  for (int i = 0; i < 4; ++i) arcs.push_back({quarter[i], quarter[(i + 1) % 4], up, 0, 1});
  for (double lon : {20.0, 50.0, 130.0, 160.0, 200.0, 250.0, 300.0, 340.0}) {
    const ExactVec a = at_longitude(lon, -0.2), b = at_longitude(lon, 0.2);
    arcs.push_back({a, b, exact::cross(a, b), 1, 1});
  }
  if (branch) arcs.push_back({v(0, 1, 0), v(0, 1, 1), exact::cross(v(0, 1, 0), v(0, 1, 1)), 0, 1});
  const int reference_coverage[] = {0, 0};
  return Arrangement(arcs, {}, 2, v(0.3, -0.2, 0.9), reference_coverage);
}

// The selected edges: those of layer 0 on the equator.
std::vector<uint8_t> on_equator(const Arrangement& arr) {
  std::vector<uint8_t> selected(arr.edges().size(), 0);
  for (uint32_t e = 0; e < arr.edges().size(); ++e) {
    const auto& edge = arr.edges()[e];
    selected[e] = arr.edge_on_layer(e, 0) && exact::parallel(edge.normal, v(0, 0, 1));
  }
  return selected;
}

// The checks common to both cases; returns the vertices inside runs.
std::set<uint32_t> check_runs(const Arrangement& arr, const std::vector<uint8_t>& selected,
                              const std::vector<ProbedRun>& runs) {
  std::multiset<uint32_t> seen;
  std::set<uint32_t> inner;
  for (const ProbedRun& run : runs) {
    EXPECT_FALSE(run.edges.empty());
    EXPECT_EQ(run.inner.size() + 1, run.edges.size());
    // Each edge walked along the run's circle: its ends in order, counter-clockwise.
    ExactVec at = run.arc.start;
    for (size_t k = 0; k < run.edges.size(); ++k) {
      const auto& edge = arr.edges()[run.edges[k]];
      const bool forward = exact::same_direction(arr.vertices()[edge.v0].p, at);
      const ExactVec from = arr.vertices()[forward ? edge.v0 : edge.v1].p;
      const ExactVec to = arr.vertices()[forward ? edge.v1 : edge.v0].p;
      EXPECT_TRUE(exact::same_direction(from, at)) << "run broken before edge " << k;
      EXPECT_EQ(exact::sign_det(from, to, run.arc.normal), Sign::kPositive);
      if (k + 1 < run.edges.size()) EXPECT_TRUE(exact::same_direction(arr.vertices()[run.inner[k]].p, to));
      at = to;
      seen.insert(run.edges[k]);
    }
    EXPECT_TRUE(exact::same_direction(at, run.arc.end));
    // Shorter than 180 degrees: the start and end strictly counter-clockwise.
    EXPECT_EQ(exact::sign_det(run.arc.start, run.arc.end, run.arc.normal), Sign::kPositive);
    inner.insert(run.inner.begin(), run.inner.end());
  }
  for (uint32_t e = 0; e < arr.edges().size(); ++e) {
    EXPECT_EQ(seen.count(e), selected[e] ? 1u : 0u) << "edge " << e;
  }
  return inner;
}

TEST(ProbedRuns, AClosedCircleInRunsShorterThanAHalfCircle) {
  const Arrangement arr = equator(false);
  const std::vector<uint8_t> selected = on_equator(arr);
  ASSERT_EQ(std::count(selected.begin(), selected.end(), 1), 12);  // 4 arcs cut 8 times
  const std::vector<ProbedRun> runs = probed_runs(arr, selected);
  check_runs(arr, selected, runs);
  // 360 degrees in runs below 180: at least three, and fewer than one per edge.
  EXPECT_GE(runs.size(), 3u);
  EXPECT_LT(runs.size(), 12u);
}

TEST(ProbedRuns, ARunStopsWhereAThirdSelectedEdgeMeets) {
  const Arrangement arr = equator(true);
  std::vector<uint8_t> selected = on_equator(arr);
  uint32_t branch_vertex = UINT32_MAX;
  for (uint32_t e = 0; e < arr.edges().size(); ++e) {
    const auto& edge = arr.edges()[e];
    if (!arr.edge_on_layer(e, 0) || selected[e]) continue;
    selected[e] = 1;  // the northward arc
    for (uint32_t w : {edge.v0, edge.v1}) {
      if (exact::same_direction(arr.vertices()[w].p, v(0, 1, 0))) branch_vertex = w;
    }
  }
  ASSERT_NE(branch_vertex, UINT32_MAX);
  const std::vector<ProbedRun> runs = probed_runs(arr, selected);
  const std::set<uint32_t> inner = check_runs(arr, selected, runs);
  EXPECT_EQ(inner.count(branch_vertex), 0u);
}

}  // namespace
}  // namespace gvm
