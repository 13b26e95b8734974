// gvm_sampler: the exact engine against the simplest ray-casting sampler, the alternative
// users have (issue 15): one Embree ray from the centroid of every front-facing triangle
// along each of N Fibonacci directions, on the same part, back to back, same threads.
//
//   gvm_sampler [PART...] [--directions N[,N...]] [--threads T] [--json FILE]
//
// Without parts: every part of $GVM_SHARED_DIR/data/parts (default ../shared). Per part:
// the exact analysis (every region and feature) and its seconds, then the sampler at each
// N (default 2000,10000,40000) and its seconds, and what the sampler gets wrong against
// the exact GVMs at its own directions (membership decided exactly): features it loses
// (a non-empty GVM, nothing seen), features with a point or an arc no lattice can hit,
// and the (feature, direction) verdicts that differ, more than 1 degree from the GVM's
// boundary (its errors) or less (the floats'). Prints a Markdown table with the totals;
// --json writes the rows (protobuf's mapping of gvm.v1.SamplerBenchmark); --from-json
// merges the rows of runs made in pieces instead of measuring.
#include <spdlog/spdlog.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "candidates.h"
#include "gvm/analysis.h"
#include "gvm/v1/benchmark.pb.h"
#include "support/ray_sampler.h"
#include "support/shared_parts.h"

namespace {

using Vec = std::array<double, 3>;

struct Options {
  std::vector<std::string> parts;
  std::vector<size_t> directions = {2000, 10000, 40000};
  unsigned threads = 1;
  std::string json;
  std::vector<std::string> from_json;  // earlier runs' rows, merged instead of computed
};

// A feature as both sides see it: its triangles, its exact LVM and GVM.
struct FeatureTruth {
  std::vector<uint32_t> triangles;
  const gvm::DirectionSet* lvm = nullptr;
  const gvm::DirectionSet* gvm = nullptr;
};

std::vector<FeatureTruth> feature_truths(const gvm::Analysis& analysis) {
  const gvm::SolidMesh& mesh = analysis.mesh();
  std::vector<std::vector<uint32_t>> of_face(mesh.input_face_count);
  for (uint32_t t = 0; t < mesh.triangles.size(); ++t) of_face[mesh.triangle_face[t]].push_back(t);
  std::vector<FeatureTruth> out;
  for (const gvm::Surface& f : analysis.features()) {
    FeatureTruth truth;
    truth.lvm = &f.maps.lvm;
    truth.gvm = f.maps.gvm ? &*f.maps.gvm : nullptr;
    for (uint32_t face : f.faces) truth.triangles.insert(truth.triangles.end(), of_face[face].begin(), of_face[face].end());
    out.push_back(std::move(truth));
  }
  return out;
}

bool has_point_or_arc(const gvm::DirectionSet& gvm) {
  for (const gvm::DirectionSet& cell : gvm.cells()) {
    if (cell.dimension() < 2) return true;
  }
  return false;
}

// Within this angle of a GVM's boundary a sampler's verdict is the floats' (its start
// offset, rays that graze the part): counted apart from its errors.
constexpr double kBoundaryRadians = M_PI / 180;

// The sampler's verdicts against exact membership, feature by feature.
void judge(const std::vector<FeatureTruth>& features, const std::vector<Vec>& units,
           const gvm::bench::SampledVisibility& sampled, gvm::v1::SamplerRun& run) {
  std::vector<std::vector<uint32_t>> seen(features.size());
  for (uint32_t d = 0; d < sampled.seen.size(); ++d) {
    for (uint32_t f : sampled.seen[d]) seen[f].push_back(d);
  }
  std::vector<gvm::Direction> exact;
  for (const Vec& u : units) exact.emplace_back(u[0], u[1], u[2]);
  std::atomic<uint64_t> seen_but_blocked = 0, missed_but_visible = 0, near_boundary = 0;
  std::atomic<uint32_t> lost = 0, wrong = 0;
  tbb::parallel_for(size_t(0), features.size(), [&](size_t f) {
    const FeatureTruth& truth = features[f];
    if (!truth.gvm) return;
    uint64_t false_seen = 0, false_missed = 0, near = 0;
    for (uint32_t d = 0; d < units.size(); ++d) {
      // The GVM lies in the LVM, a convex set whose test is cheap.
      const bool in_gvm = truth.lvm->contains(exact[d]) && truth.gvm->contains(exact[d]);
      const bool was_seen = std::binary_search(seen[f].begin(), seen[f].end(), d);
      if (in_gvm == was_seen) continue;
      if (std::abs(truth.gvm->approx_signed_clearance(units[d])) <= kBoundaryRadians) {
        ++near;
      } else {
        false_seen += was_seen, false_missed += in_gvm;
      }
    }
    const bool is_lost = !truth.gvm->is_empty() && seen[f].empty();
    seen_but_blocked += false_seen, missed_but_visible += false_missed, near_boundary += near;
    lost += is_lost;
    wrong += is_lost || false_seen + false_missed > 0;
  });
  run.set_lost_features(lost), run.set_wrong_features(wrong);
  run.set_seen_but_blocked(seen_but_blocked), run.set_missed_but_visible(missed_but_visible);
  run.set_near_boundary(near_boundary);
}

std::vector<Vec> lattice(size_t n) {
  std::vector<Vec> out;
  for (const gvm::Direction& d : gvm::planner::fibonacci_directions(n)) out.push_back(d.unit());
  return out;
}

bool run_part(const std::string& path, const Options& opt, gvm::v1::SamplerComparison& row) {
  row.set_model(std::filesystem::path(path).filename().string());
  gvm::AnalyzeRequest request;
  request.part_path = path;
  request.options.set_threads(opt.threads);
  auto analysis = gvm::analyze(request);
  if (!analysis.ok()) {
    std::fprintf(stderr, "gvm_sampler: %s: %s\n", path.c_str(), std::string(analysis.status().message()).c_str());
    return false;
  }
  row.set_exact_seconds(analysis->timing().total);
  row.set_exact_visibility_seconds(analysis->timing().visibility);
  row.set_triangles(static_cast<uint32_t>(analysis->mesh().triangles.size()));
  const std::vector<FeatureTruth> features = feature_truths(*analysis);
  row.set_features(static_cast<uint32_t>(features.size()));
  for (const FeatureTruth& f : features) {
    if (!f.gvm || f.gvm->is_empty()) continue;
    row.set_reachable(row.reachable() + 1);
    row.set_with_points_or_arcs(row.with_points_or_arcs() + has_point_or_arc(*f.gvm));
  }
  std::vector<std::vector<uint32_t>> triangles;
  for (const FeatureTruth& f : features) triangles.push_back(f.triangles);
  for (size_t n : opt.directions) {
    const std::vector<Vec> units = lattice(n);
    const auto sampled = gvm::bench::sample_visibility(analysis->mesh(), triangles, units, opt.threads);
    gvm::v1::SamplerRun& run = *row.add_samplers();
    run.set_directions(static_cast<uint32_t>(n));
    run.set_rays(sampled.rays);
    run.set_seconds(sampled.seconds);
    tbb::task_arena(static_cast<int>(opt.threads)).execute([&] { judge(features, units, sampled, run); });
  }
  return true;
}

void print_table(const gvm::v1::SamplerBenchmark& bench) {
  if (bench.parts().empty()) return;
  const auto& runs = bench.parts(0).samplers();
  std::printf("| part | triangles | features (reachable, points/arcs) | exact s |");
  for (const auto& s : runs) std::printf(" sampler %u s | wrong (lost) |", s.directions());
  std::printf("\n|---|---:|---:|---:|");
  for (int i = 0; i < runs.size(); ++i) std::printf("---:|---:|");
  std::printf("\n");
  double exact = 0;
  std::vector<double> seconds(runs.size(), 0);
  std::vector<uint32_t> wrong(runs.size(), 0), lost(runs.size(), 0), faster(runs.size(), 0);
  for (const auto& r : bench.parts()) {
    std::printf("| %s | %u | %u (%u, %u) | %.2f |", r.model().c_str(), r.triangles(), r.features(), r.reachable(),
                r.with_points_or_arcs(), r.exact_seconds());
    exact += r.exact_seconds();
    for (int i = 0; i < r.samplers().size() && i < runs.size(); ++i) {
      const auto& s = r.samplers(i);
      std::printf(" %.2f | %u (%u) |", s.seconds(), s.wrong_features(), s.lost_features());
      seconds[i] += s.seconds(), wrong[i] += s.wrong_features(), lost[i] += s.lost_features();
      faster[i] += r.exact_seconds() < s.seconds();
    }
    std::printf("\n");
  }
  std::printf("| all %d parts | | | %.1f |", bench.parts().size(), exact);
  for (int i = 0; i < runs.size(); ++i) std::printf(" %.1f | %u (%u) |", seconds[i], wrong[i], lost[i]);
  std::printf("\n\nExact faster than the sampler on");
  for (int i = 0; i < runs.size(); ++i) {
    std::printf("%s %u of %d parts at %u directions", i ? "," : "", faster[i], bench.parts().size(),
                runs[i].directions());
  }
  std::printf(".\n");
}

// Every part, each row on stderr as it is done (the table comes at the end).
bool measure(const Options& opt, gvm::v1::SamplerBenchmark& bench) {
  bench.set_machine(std::to_string(std::thread::hardware_concurrency()) + " cores");
  bench.set_threads(opt.threads);
  bool ok = true;
  for (const std::string& part : opt.parts) {
    gvm::v1::SamplerComparison row;
    if (!run_part(part, opt, row)) {
      ok = false;
      continue;
    }
    std::fprintf(stderr, "%s: exact %.2f s\n", row.model().c_str(), row.exact_seconds());
    *bench.add_parts() = std::move(row);
  }
  return ok;
}

// Runs made in pieces (two single-thread processes on two cores, say), merged by part.
bool merge(const std::vector<std::string>& files, gvm::v1::SamplerBenchmark& bench) {
  for (const std::string& file : files) {
    gvm::v1::SamplerBenchmark piece;
    if (!gvm::bench::read_json(file, piece)) return false;
    bench.set_machine(piece.machine()), bench.set_threads(piece.threads());
    for (const auto& row : piece.parts()) *bench.add_parts() = row;
  }
  std::sort(bench.mutable_parts()->begin(), bench.mutable_parts()->end(),
            [](const auto& a, const auto& b) { return a.model() < b.model(); });
  return true;
}

std::vector<size_t> parse_counts(const std::string& text) {
  std::vector<size_t> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(std::stoul(item));
  return out;
}

constexpr const char* kUsage =
    "usage: gvm_sampler [PART...] [--directions N[,N...]] [--threads T] [--json FILE]\n"
    "       gvm_sampler --from-json FILE [--from-json FILE...] [--json FILE]\n";

}  // namespace

int main(int argc, char** argv) {
  spdlog::set_level(spdlog::level::warn);  // the analyses' progress lines are not the table
  Options opt;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      const bool has_value = i + 1 < argc;
      if (a == "--directions" && has_value) opt.directions = parse_counts(argv[++i]);
      else if (a == "--threads" && has_value) opt.threads = static_cast<unsigned>(std::stoul(argv[++i]));
      else if (a == "--json" && has_value) opt.json = argv[++i];
      else if (a == "--from-json" && has_value) opt.from_json.push_back(argv[++i]);
      else if (!a.empty() && a[0] == '-') throw std::invalid_argument(a);
      else opt.parts.push_back(a);
    }
  } catch (const std::exception&) {
    std::fprintf(stderr, "%s", kUsage);
    return 2;
  }
  if (opt.parts.empty()) opt.parts = gvm::bench::shared_parts();
  if (opt.directions.empty() || opt.threads == 0) {
    std::fprintf(stderr, "%s", kUsage);
    return 2;
  }
  gvm::v1::SamplerBenchmark bench;
  bool ok = opt.from_json.empty() ? measure(opt, bench) : merge(opt.from_json, bench);
  print_table(bench);
  if (!opt.json.empty()) ok = gvm::bench::write_json(bench, opt.json) && ok;
  return ok ? 0 : 1;
}
