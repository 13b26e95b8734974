#include "candidates.h"

#include <tbb/parallel_for.h>

#include <cmath>

#include "gvm/direction_overlay.h"

namespace gvm::planner {

CandidateSet exact_candidates(std::span<const Target> targets) {
  std::vector<DirectionSet> reach;
  reach.reserve(targets.size());
  for (const Target& t : targets) reach.push_back(t.reach);
  const DirectionOverlay overlay(reach);
  CandidateSet out;
  out.overlay_vertices = overlay.vertex_count();
  out.evaluated = static_cast<uint32_t>(overlay.vertex_count());
  for (DirectionOverlay::Coverage& c : overlay.maximal_coverage()) {
    out.candidates.push_back({std::move(c.witness), std::move(c.sets)});
  }
  out.description = "every direction (the exact arrangement of all reach-set boundaries, " +
                    std::to_string(out.overlay_vertices) + " vertices)";
  return out;
}

std::vector<Candidate> evaluate(std::span<const Direction> directions, size_t targets,
                                const std::function<bool(uint32_t, const Direction&)>& serves) {
  std::vector<std::vector<uint32_t>> served(directions.size());
  tbb::parallel_for(size_t{0}, directions.size(), [&](size_t i) {
    for (uint32_t t = 0; t < targets; ++t) {
      if (serves(t, directions[i])) served[i].push_back(t);
    }
  });
  std::vector<Candidate> out;
  for (size_t i = 0; i < directions.size(); ++i) {
    if (!served[i].empty()) out.push_back({directions[i], std::move(served[i]), uint32_t(i)});
  }
  return out;
}

std::vector<Direction> fibonacci_directions(size_t n) {
  std::vector<Direction> out;
  out.reserve(n);
  const double golden = M_PI * (3 - std::sqrt(5.0));
  for (size_t i = 0; i < n; ++i) {
    const double z = 1 - (2 * double(i) + 1) / double(n);
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    const double phi = golden * double(i);
    out.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
  }
  return out;
}

}  // namespace gvm::planner
