// gvm_method_equality: the effective Minkowski envelope and the convex-decomposition
// baseline must give the same GVM, cell for cell (exact set equality), for every feature
// and concave region of the given parts.
//
//   gvm_method_equality PART... [--max-surfaces K]
//
// Prints one line per part (surfaces compared, time of each method) and every
// difference; exit status 0 when all agree, 1 on a difference, 2 on usage or load errors.
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "gvm/mesh.h"
#include "gvm/part.h"
#include "visibility/surface_visibility.h"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> parts;
  long max_surfaces = -1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--max-surfaces" && i + 1 < argc) {
      max_surfaces = std::stol(argv[++i]);
    } else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "usage: gvm_method_equality PART... [--max-surfaces K]\n");
      return 2;
    } else {
      parts.push_back(a);
    }
  }
  if (parts.empty()) {
    std::fprintf(stderr, "usage: gvm_method_equality PART... [--max-surfaces K]\n");
    return 2;
  }
  long differences = 0;
  bool load_failed = false;
  for (const std::string& path : parts) {
    auto solid = gvm::load_solid(path);
    if (!solid.ok()) {
      std::printf("%s: %s\n", path.c_str(), solid.status().message().c_str());
      load_failed = true;
      continue;
    }
    auto part = gvm::Part::analyze(std::move(*solid), gvm::PartOptions{});
    if (!part.ok()) {
      std::printf("%s: %s\n", path.c_str(), part.status().message().c_str());
      load_failed = true;
      continue;
    }
    std::vector<std::pair<std::string, std::vector<uint32_t>>> surfaces;
    for (const gvm::Feature& f : part->features()) surfaces.push_back({"feature " + f.name, f.triangles});
    for (const gvm::ConcaveRegion& r : part->regions()) {
      surfaces.push_back({"region " + std::to_string(r.id), r.triangles});
    }
    if (max_surfaces >= 0 && surfaces.size() > size_t(max_surfaces)) surfaces.resize(max_surfaces);
    double eme_seconds = 0, convex_seconds = 0;
    long part_differences = 0;
    for (const auto& [name, s] : surfaces) {
      auto t = Clock::now();
      const gvm::SurfaceVisibility eme = gvm::compute_surface_visibility(*part, s, true);
      eme_seconds += seconds_since(t);
      t = Clock::now();
      const gvm::SurfaceVisibility convex = gvm::compute_surface_visibility(
          *part, s, true, gvm::OcclusionMethod::kConvexDecomposition);
      convex_seconds += seconds_since(t);
      const bool same = eme.gvm.has_value() == convex.gvm.has_value() &&
                        (!eme.gvm || *eme.gvm == *convex.gvm);
      if (!same) {
        ++part_differences;
        std::printf("  DIFFERENT %s %s |S|=%zu\n    envelope: %s\n    convex:   %s\n", path.c_str(),
                    name.c_str(), s.size(), eme.gvm ? eme.gvm->description().c_str() : "none",
                    convex.gvm ? convex.gvm->description().c_str() : "none");
      }
    }
    std::printf("%s: %zu surfaces, %ld differences; envelope %.2f s, convex decomposition %.2f s\n",
                path.c_str(), surfaces.size(), part_differences, eme_seconds, convex_seconds);
    std::fflush(stdout);
    differences += part_differences;
  }
  if (differences > 0) return 1;
  return load_failed ? 2 : 0;
}
