// gvm_plan_bench: the exact planner on real parts, against greedy and against a sampling
// planner (the usual alternative: a lattice of directions tested per feature, then the
// same set cover), and with --planar-normal.
//
//   gvm_plan_bench [PART...] [--threads T] [--directions N] [--json FILE]
//
// Without parts: every part of $GVM_SHARED_DIR/data/parts (default ../shared). Per part:
// features, reachable features, the exact plan's setups with its proven bound, greedy's
// count, the sampling planner's count and the reachable features it misses (GVM a point,
// an arc, or a 2-cell thinner than the lattice), the same with --planar-normal, and the
// planning time against the analysis time. Prints a Markdown table; --json writes the
// rows (protobuf's mapping of gvm.v1.PlannerBenchmark).
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "candidates.h"
#include "gvm/analysis.h"
#include "gvm/planner/plan.h"
#include "gvm/v1/benchmark.pb.h"
#include "set_cover.h"
#include "support/shared_parts.h"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

struct Options {
  std::vector<std::string> parts;
  unsigned threads = 0;
  size_t directions = 10000;
  std::string json;
};

// The sampling planner: features reached at lattice directions, the same exact cover.
void sample(const gvm::Analysis& analysis, size_t n, gvm::v1::PlannerRun& row) {
  const auto t0 = Clock::now();
  std::vector<gvm::planner::Target> reachable;
  for (const gvm::Surface& f : analysis.features()) {
    if (f.maps.gvm && !f.maps.gvm->is_empty()) {
      reachable.push_back({static_cast<uint32_t>(reachable.size()), {}, 0, *f.maps.gvm, *f.maps.gvm, *f.maps.gvm});
    }
  }
  const std::vector<gvm::Direction> lattice = gvm::planner::fibonacci_directions(n);
  const auto candidates = gvm::planner::evaluate(lattice, reachable.size(), [&](uint32_t t, const gvm::Direction& d) {
    return reachable[t].gvm.contains(d);
  });
  gvm::planner::CoverProblem problem{static_cast<uint32_t>(reachable.size()), {}};
  for (const auto& c : candidates) problem.candidates.push_back(c.targets);
  auto cover = gvm::planner::solve_set_cover(problem, {});
  row.set_sampled_directions(static_cast<uint32_t>(n));
  if (cover.ok()) {
    row.set_sampling_setups(static_cast<uint32_t>(cover->chosen.size()));
    for (uint32_t t : cover->uncoverable) {
      const int dim = reachable[t].gvm.dimension();
      if (dim == 0) row.set_sampling_missed_points(row.sampling_missed_points() + 1);
      if (dim == 1) row.set_sampling_missed_arcs(row.sampling_missed_arcs() + 1);
      if (dim == 2) row.set_sampling_missed_slivers(row.sampling_missed_slivers() + 1);
    }
  }
  row.set_sampling_seconds(seconds_since(t0));
}

gvm::v1::PlannerRun run_part(const std::string& path, const Options& opt) {
  gvm::v1::PlannerRun row;
  row.set_model(fs::path(path).filename().string());
  gvm::AnalyzeRequest request;
  request.part_path = path;
  request.options.set_threads(opt.threads);
  auto analysis = gvm::analyze(request);
  if (!analysis.ok()) {
    std::fprintf(stderr, "%s: %s\n", path.c_str(), analysis.status().message().c_str());
    return row;
  }
  row.set_analysis_seconds(analysis->timing().total);
  gvm::v1::PlanOptions options;
  options.set_threads(opt.threads);
  const auto t0 = Clock::now();
  auto plan = gvm::planner::plan(*analysis, options);
  row.set_plan_seconds(seconds_since(t0));
  if (!plan.ok()) {
    std::fprintf(stderr, "%s: %s\n", path.c_str(), plan.status().message().c_str());
    return row;
  }
  const gvm::v1::Plan& p = plan->message;
  row.set_features(static_cast<uint32_t>(p.surfaces_size()));
  row.set_reachable(p.reached());
  row.set_setups(static_cast<uint32_t>(p.setups_size()));
  row.set_lower_bound(p.lower_bound());
  row.set_optimal(p.optimal());
  row.set_greedy_setups(p.solver().greedy_setups());
  options.set_planar_normal(true);
  auto planar = gvm::planner::plan(*analysis, options);
  if (planar.ok()) {
    row.set_planar_normal_setups(static_cast<uint32_t>(planar->message.setups_size()));
    row.set_planar_normal_unreachable(planar->message.unreachable_count());
    row.set_planar_normal_optimal(planar->message.optimal());
  }
  sample(*analysis, opt.directions, row);
  return row;
}

void print_table(const gvm::v1::PlannerBenchmark& b) {
  std::printf("| part | features | reachable | exact setups (bound) | greedy | sampling setups | sampling misses "
              "(points/arcs/slivers) | planar-normal setups, unreachable | analysis s | plan s | plan / analysis |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& r : b.parts()) {
    std::printf("| %s | %u | %u | %u (%u%s) | %u | %u | %u/%u/%u | %u, %u | %.2f | %.3f | %.1f%% |\n", r.model().c_str(),
                r.features(), r.reachable(), r.setups(), r.lower_bound(), r.optimal() ? ", proven" : "",
                r.greedy_setups(), r.sampling_setups(), r.sampling_missed_points(), r.sampling_missed_arcs(),
                r.sampling_missed_slivers(), r.planar_normal_setups(), r.planar_normal_unreachable(),
                r.analysis_seconds(), r.plan_seconds(),
                r.analysis_seconds() > 0 ? 100 * r.plan_seconds() / r.analysis_seconds() : 0.0);
  }
}

}  // namespace

int main(int argc, char** argv) {
  spdlog::set_level(spdlog::level::warn);  // the analyses' progress lines are not the table
  Options opt;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--threads" && i + 1 < argc) {
      opt.threads = static_cast<unsigned>(std::stoul(argv[++i]));
    } else if (a == "--directions" && i + 1 < argc) {
      opt.directions = std::stoul(argv[++i]);
    } else if (a == "--json" && i + 1 < argc) {
      opt.json = argv[++i];
    } else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "usage: gvm_plan_bench [PART...] [--threads T] [--directions N] [--json FILE]\n");
      return 2;
    } else {
      opt.parts.push_back(a);
    }
  }
  if (opt.parts.empty()) opt.parts = gvm::bench::shared_parts();
  gvm::v1::PlannerBenchmark bench;
  bench.set_machine("2 cores, Debian 12");
  bench.set_threads(opt.threads);
  for (const std::string& part : opt.parts) {
    *bench.add_parts() = run_part(part, opt);
    std::fprintf(stderr, "%s done\n", part.c_str());
  }
  print_table(bench);
  if (!opt.json.empty() && !gvm::bench::write_json(bench, opt.json)) return 1;
  return 0;
}
