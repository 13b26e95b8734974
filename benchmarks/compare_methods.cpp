// gvm_compare: the effective Minkowski envelope against convex decomposition, the way the
// paper's Tables 1-2 compare them, on real parts.
//
//   gvm_compare [PART...] [--largest K | --all-features | --feature NAME...] [--no-convex]
//               [--convex-max-pairs N] [--threads T] [--csv FILE] [--json FILE] [--svg FILE]
//   gvm_compare --from-json FILE [--csv FILE] [--svg FILE]
//
// Without parts: every part of $GVM_SHARED_DIR/data/parts (default ../shared). For each
// part, the K (default 3) features with the largest |S| * |O_S| whose LVM has a 2-cell (or
// every feature, or the features named, e.g. F17, or given by id, e.g. '#17' for the
// JSON's feature 17; an LVM of arcs and points the envelope method leaves to the occlusion
// probe, with no envelope, so only the convex decomposition builds maps there), each
// computed by both methods: #S, #O_S, #GOM, #Arrng, #GVM, seconds and peak memory, and
// whether the two GVMs are equal. Convex decomposition is skipped on features with more
// than N pairs (default: no limit). Prints a table; --csv and --json write the same rows
// (JSON: protobuf's mapping of gvm.v1.Comparison); --svg plots seconds and #Arrng of both
// methods against |S| * |O_S|. --from-json reads the rows of an earlier run instead of
// computing them (to redraw the table, CSV or plot).
#include <spdlog/spdlog.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <malloc.h>
#include <ostream>
#include <string>
#include <thread>
#include <vector>

#include "gvm/analysis.h"
#include "gvm/mesh.h"
#include "gvm/part.h"
#include "gvm/v1/benchmark.pb.h"
#include "support/comparison_plot.h"
#include "support/shared_parts.h"
#include "visibility/surface_visibility.h"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct Options {
  std::vector<std::string> parts;
  std::vector<std::string> features;  // by name; empty: the largest
  size_t largest = 3;
  bool all_features = false, convex = true;
  uint64_t convex_max_pairs = UINT64_MAX;
  unsigned threads = 0;
  std::string csv, json, svg, from_json;
};

constexpr const char* kUsage =
    "usage: gvm_compare [PART...] [--largest K | --all-features | --feature NAME...] [--no-convex] "
    "[--convex-max-pairs N] [--threads T] [--csv FILE] [--json FILE] [--svg FILE] [-v]\n"
    "       gvm_compare --from-json FILE [--csv FILE] [--svg FILE]\n";

// The most resident memory a run adds to the process: VmHWM after it less VmRSS before
// it, so that a row does not count what earlier parts left behind (TR12J F234's convex
// decomposition left 2.6 GB resident for every row after it). glibc keeps the pages a
// run freed, so they are handed back first; writing 5 to clear_refs lowers the
// high-water mark to what is resident now.
double status_mb(const char* field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind(field, 0) == 0) return std::stod(line.substr(std::strlen(field))) / 1024;
  }
  return 0;
}

double reset_peak_memory() {
  malloc_trim(0);
  std::ofstream("/proc/self/clear_refs") << "5";
  return status_mb("VmRSS:");
}

uint64_t gvm_size(const gvm::sphere::SphericalImage& g) {
  uint64_t n = g.points().size() + g.curves().size();
  for (const auto& f : g.faces()) {
    for (const auto& loop : f.loops) n += loop.arcs.size();
  }
  return n;
}

gvm::v1::MethodRun run(const gvm::Part& part, const std::vector<uint32_t>& s,
                       gvm::OcclusionMethod method, gvm::sphere::SphericalImage* gvm_out) {
  const double resident_before = reset_peak_memory();
  const auto t = Clock::now();
  const gvm::SurfaceVisibility vis = gvm::compute_surface_visibility(part, s, true, method);
  gvm::v1::MethodRun r;
  r.set_seconds(std::chrono::duration<double>(Clock::now() - t).count());
  r.set_peak_mb(status_mb("VmHWM:") - resident_before);
  const bool envelope = method == gvm::OcclusionMethod::kEffectiveMinkowskiEnvelope;
  r.set_method(envelope ? gvm::v1::OCCLUSION_METHOD_EFFECTIVE_MINKOWSKI_ENVELOPE
                        : gvm::v1::OCCLUSION_METHOD_CONVEX_DECOMPOSITION);
  r.set_gom(envelope ? vis.statistics.envelope.border_edges : vis.statistics.convex.map_arcs);
  r.set_arrangement_vertices(vis.statistics.arrangement_vertices);
  if (vis.gvm) {
    r.set_gvm_size(gvm_size(*vis.gvm));
    *gvm_out = *vis.gvm;
  }
  return r;
}

void print_row(const gvm::v1::SurfaceComparison& c) {
  auto cells = [](const gvm::v1::MethodRun& r) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%9llu %10llu %6llu %9.3f %8.0f",
                  static_cast<unsigned long long>(r.gom()),
                  static_cast<unsigned long long>(r.arrangement_vertices()),
                  static_cast<unsigned long long>(r.gvm_size()), r.seconds(), r.peak_mb());
    return std::string(buf);
  };
  char ratio[32] = "-";
  if (c.has_convex()) std::snprintf(ratio, sizeof ratio, "%.1f", c.convex_over_envelope());
  std::printf("%-34s %-8s %5u %6u | %s | %s | %7s %s\n", c.model().c_str(), c.surface().c_str(),
              c.s(), c.o_s(), cells(c.envelope()).c_str(),
              c.has_convex() ? cells(c.convex()).c_str() : "   (skipped)                                 ",
              ratio, c.has_convex() ? (c.same_gvm() ? "same" : "DIFFERENT") : "");
  std::fflush(stdout);
}

void print_header() {
  std::printf("%-34s %-8s %5s %6s | %9s %10s %6s %9s %8s | %9s %10s %6s %9s %8s | %7s\n", "model",
              "feature", "#S", "#O_S", "#GOM", "#Arrng", "#GVM", "EME s", "peak MB", "#GOM",
              "#Arrng", "#GVM", "convex s", "peak MB", "ratio");
}

// Both methods on the chosen features of every part, each row printed as it is done.
// Returns false when a part cannot be read.
bool compare(const Options& opt, gvm::v1::Comparison& out) {
  for (const std::string& path : opt.parts) {
    // As `gvm analyze` reads it: STEP parts too, their B-rep faces (or OBJ groups) the features.
    gvm::AnalyzeRequest request;
    request.part_path = path;
    auto solid = gvm::load_part_solid(request);
    if (!solid.ok()) {
      std::fprintf(stderr, "%s: %s\n", path.c_str(), solid.status().message().c_str());
      return false;
    }
    gvm::PartOptions part_options;
    part_options.face_groups = solid->groups;
    auto part = gvm::Part::analyze(std::move(*solid), part_options);
    if (!part.ok()) {
      std::fprintf(stderr, "%s: %s\n", path.c_str(), part.status().message().c_str());
      return false;
    }
    struct Candidate {
      const gvm::Feature* feature;
      size_t o_s;
      bool has_2_cell;  // of its LVM: else the envelope builds nothing (the probe decides)
    };
    std::vector<Candidate> candidates;
    for (const gvm::Feature& f : part->features()) {
      const gvm::SurfaceVisibility occluders = gvm::compute_surface_visibility(*part, f.triangles, false);
      candidates.push_back({&f, occluders.occluders.potential.size(), occluders.lvm.dimension() == 2});
    }
    std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
      return a.feature->triangles.size() * a.o_s > b.feature->triangles.size() * b.o_s;
    });
    if (!opt.features.empty()) {
      std::erase_if(candidates, [&](const Candidate& c) {
        const std::string id = "#" + std::to_string(c.feature->id);
        return std::find_if(opt.features.begin(), opt.features.end(), [&](const std::string& f) {
                 return f == c.feature->name || f == id;
               }) == opt.features.end();
      });
    } else if (!opt.all_features) {
      // The largest whose LVM has a 2-cell: only there do the methods differ.
      std::erase_if(candidates, [](const Candidate& c) { return !c.has_2_cell; });
      if (candidates.size() > opt.largest) candidates.resize(opt.largest);
    }
    for (const Candidate& c : candidates) {
      gvm::v1::SurfaceComparison* row = out.add_surfaces();
      row->set_model(fs::path(path).filename().string());
      row->set_surface(c.feature->name);
      row->set_s(static_cast<uint32_t>(c.feature->triangles.size()));
      row->set_o_s(static_cast<uint32_t>(c.o_s));
      gvm::sphere::SphericalImage eme_gvm, convex_gvm;
      *row->mutable_envelope() = run(*part, c.feature->triangles,
                                     gvm::OcclusionMethod::kEffectiveMinkowskiEnvelope, &eme_gvm);
      if (opt.convex && uint64_t(row->s()) * row->o_s() <= opt.convex_max_pairs) {
        *row->mutable_convex() = run(*part, c.feature->triangles,
                                     gvm::OcclusionMethod::kConvexDecomposition, &convex_gvm);
        row->set_same_gvm(eme_gvm == convex_gvm);
        row->set_convex_over_envelope(row->convex().seconds() /
                                      std::max(row->envelope().seconds(), 1e-9));
      }
      print_row(*row);
    }
  }
  return true;
}

void write_csv(const gvm::v1::Comparison& out, std::ostream& csv) {
  csv << "model,feature,s,o_s,method,gom,arrangement_vertices,gvm_size,seconds,peak_mb,same_gvm\n";
  for (const auto& r : out.surfaces()) {
    for (const auto* m : {&r.envelope(), &r.convex()}) {
      if (m == &r.convex() && !r.has_convex()) continue;
      csv << r.model() << ',' << r.surface() << ',' << r.s() << ',' << r.o_s() << ','
          << (m == &r.envelope() ? "envelope" : "convex") << ',' << m->gom() << ','
          << m->arrangement_vertices() << ',' << m->gvm_size() << ',' << m->seconds() << ','
          << m->peak_mb() << ',' << (r.has_convex() ? (r.same_gvm() ? "1" : "0") : "") << '\n';
    }
  }
}

// Writes what was asked for; false when a file cannot be written.
bool write_outputs(const Options& opt, const gvm::v1::Comparison& out) {
  bool ok = true;
  auto write = [&](const std::string& path, auto&& body) {
    if (path.empty()) return;
    std::ofstream file(path);
    body(file);
    if (!file) {
      std::fprintf(stderr, "gvm_compare: cannot write %s\n", path.c_str());
      ok = false;
    }
  };
  write(opt.csv, [&](std::ostream& f) { write_csv(out, f); });
  write(opt.svg, [&](std::ostream& f) { f << gvm::bench::comparison_plot_svg(out); });
  if (!opt.json.empty()) ok = gvm::bench::write_json(out, opt.json) && ok;
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "gvm_compare: %s needs a value\n%s", a.c_str(), kUsage);
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--largest") opt.largest = std::stoul(next());
    else if (a == "--all-features") opt.all_features = true;
    else if (a == "--feature") opt.features.push_back(next());
    else if (a == "--no-convex") opt.convex = false;
    else if (a == "--convex-max-pairs") opt.convex_max_pairs = std::stoull(next());
    else if (a == "--threads") opt.threads = std::stoul(next());
    else if (a == "--csv") opt.csv = next();
    else if (a == "--json") opt.json = next();
    else if (a == "--svg") opt.svg = next();
    else if (a == "--from-json") opt.from_json = next();
    else if (a == "-v" || a == "--verbose") spdlog::set_level(spdlog::level::debug);
    else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "gvm_compare: unknown option %s\n%s", a.c_str(), kUsage);
      return 2;
    } else {
      opt.parts.push_back(a);
    }
  }
  gvm::v1::Comparison out;
  if (!opt.from_json.empty()) {
    if (!opt.parts.empty()) {
      std::fprintf(stderr, "gvm_compare: --from-json takes no parts\n%s", kUsage);
      return 2;
    }
    if (!gvm::bench::read_json(opt.from_json, out)) return 2;
    print_header();
    for (const auto& row : out.surfaces()) print_row(row);
  } else {
    if (opt.parts.empty()) opt.parts = gvm::bench::shared_parts();
    const unsigned threads = opt.threads ? opt.threads : std::thread::hardware_concurrency();
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    out.set_threads(threads);
    out.set_machine(std::to_string(std::thread::hardware_concurrency()) + " hardware threads");
    print_header();
    if (!compare(opt, out)) return 2;
  }
  if (!write_outputs(opt, out)) return 2;
  const bool all_same = std::all_of(out.surfaces().begin(), out.surfaces().end(),
                                    [](const auto& r) { return !r.has_convex() || r.same_gvm(); });
  return all_same ? 0 : 1;
}
