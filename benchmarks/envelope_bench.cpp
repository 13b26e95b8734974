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
#include "support/real_feature.h"
#include "visibility/direction_window.h"
#include "visibility/effective_minkowski_envelope.h"
#include "visibility/surface_visibility.h"

namespace gvm {
namespace {

using bench::RealFeature;
using bench::real_feature;

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
  state.counters["window_halfspaces"] = window ? double(window->half_spaces()) : 0.0;
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
    benchmark::DoNotOptimize(w.half_spaces());
  }
  state.counters["window_halfspaces"] = double(f.window->half_spaces());
}
BENCHMARK(BM_DirectionWindowBuild);

}  // namespace
}  // namespace gvm
