// gvm_plan_variants: what the planning tolerance and the automatic split change, part by
// part: one analysis, then four plans (exact with features whole, within the default
// tolerance, split, both), their setups, bounds and unreachable features.
//
//   gvm_plan_variants OUT.json [PART ...]      (default: every shared mesh and STEP part)
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "gvm/analysis.h"
#include "gvm/planner/plan.h"
#include "gvm/v1/benchmark.pb.h"
#include "support/shared_parts.h"

namespace {

using Clock = std::chrono::steady_clock;

gvm::v1::PlanVariant run(const gvm::Analysis& a, std::optional<double> tolerance, bool no_split,
                         gvm::v1::PlanVariants& row) {
  gvm::v1::PlanOptions o;
  if (tolerance) o.set_tolerance_radians(*tolerance);
  if (no_split) o.set_no_split(true);
  o.set_threads(2);
  const auto t0 = Clock::now();
  auto p = gvm::planner::plan(a, o);
  gvm::v1::PlanVariant out;
  out.set_plan_seconds(std::chrono::duration<double>(Clock::now() - t0).count());
  if (!p.ok()) {
    std::fprintf(stderr, "%s: %s\n", row.model().c_str(), p.status().message().c_str());
    return out;
  }
  const gvm::v1::Plan& m = p->message;
  out.set_setups(static_cast<uint32_t>(m.setups_size()));
  out.set_lower_bound(m.lower_bound());
  out.set_optimal(m.optimal());
  out.set_unreachable(m.unreachable_count());
  out.set_reached_within(m.tolerance().reached_within());
  for (const auto& s : m.surfaces()) out.set_split(out.split() + s.has_pieces());
  if (tolerance || no_split) return out;
  for (int k = 0; k < m.setups_size(); ++k) {
    for (const auto& r : m.setups(k).reach()) {
      if (!r.within_tolerance()) continue;
      std::string name;
      for (const auto& s : m.surfaces()) {
        if (s.id() == r.feature()) name = s.name();
      }
      char at[96];
      std::snprintf(at, sizeof at, " at %.2g rad (setup %d)", r.distance_radians(), k + 1);
      row.add_within_surfaces(name + at);
    }
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: gvm_plan_variants OUT.json [PART ...]\n");
    return 2;
  }
  std::vector<std::string> parts(argv + 2, argv + argc);
  if (parts.empty()) parts = gvm::bench::shared_parts();
  gvm::v1::PlanVariantsBenchmark out;
  out.set_machine("2-core Debian 12 VM");
  out.set_threads(2);
  out.set_tolerance_radians(gvm::planner::with_defaults({}).tolerance_radians());
  for (const std::string& path : parts) {
    gvm::AnalyzeRequest request;
    request.part_path = path;
    request.options.set_threads(2);
    const auto t0 = Clock::now();
    auto a = gvm::analyze(request);
    if (!a.ok()) {
      std::fprintf(stderr, "%s: %s\n", path.c_str(), a.status().message().c_str());
      continue;
    }
    gvm::v1::PlanVariants& row = *out.add_parts();
    row.set_model(std::filesystem::path(path).filename().string());
    row.set_features(static_cast<uint32_t>(a->features().size()));
    row.set_analysis_seconds(std::chrono::duration<double>(Clock::now() - t0).count());
    *row.mutable_exact_whole() = run(*a, 0.0, true, row);
    *row.mutable_within() = run(*a, std::nullopt, true, row);
    *row.mutable_split() = run(*a, 0.0, false, row);
    *row.mutable_both() = run(*a, std::nullopt, false, row);
    std::fprintf(stderr, "%s: %u/%u/%u/%u setups, unreachable %u -> %u\n", row.model().c_str(), row.exact_whole().setups(),
                 row.within().setups(), row.split().setups(), row.both().setups(), row.exact_whole().unreachable(),
                 row.both().unreachable());
    if (!gvm::bench::write_json(out, argv[1])) return 1;
  }
  return 0;
}
