#include "tolerance.h"

#include "exact_cover.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace gvm::planner {
namespace {

constexpr int kMidpointRounds = 8;

using Vec = std::array<double, 3>;

// Each direction with the targets it serves within epsilon: `known` ones (served exactly)
// kept, every other target tested.
std::vector<Candidate> evaluate_within(std::span<const Target> targets, const std::vector<Direction>& directions,
                                       const std::vector<std::vector<uint32_t>>& known,
                                       const std::function<bool(uint32_t, const Direction&)>& serves) {
  std::vector<std::vector<uint32_t>> served(directions.size());
  tbb::parallel_for(size_t{0}, directions.size(), [&](size_t i) {
    std::vector<char> in(targets.size(), 0);
    for (uint32_t t : known[i]) in[t] = 1;
    for (uint32_t t = 0; t < targets.size(); ++t) {
      if (in[t] || serves(t, directions[i])) served[i].push_back(t);
    }
  });
  std::vector<Candidate> out;
  for (size_t i = 0; i < directions.size(); ++i) {
    if (!served[i].empty()) out.push_back({directions[i], std::move(served[i]), uint32_t(i)});
  }
  return out;
}

// The seeds' directions and, with `corners`, every target's corners, once each (by their
// rounded unit vectors: two exact directions that round alike are a rounding apart).
void gather(std::span<const Target> targets, const CandidateSet& seeds, bool with_corners,
            std::vector<Direction>& directions, std::vector<std::vector<uint32_t>>& known, uint32_t& corners) {
  std::map<Vec, size_t> seen;
  auto add = [&](const Direction& d, const std::vector<uint32_t>& exact) {
    if (!seen.emplace(d.unit(), directions.size()).second) return false;
    directions.push_back(d);
    known.push_back(exact);
    return true;
  };
  for (const Candidate& c : seeds.candidates) add(c.direction, c.targets);
  corners = 0;
  if (!with_corners) return;
  for (const Target& t : targets) {
    for (const Direction& v : t.reach.corners()) corners += add(v, {});
  }
}

double approx_distance(const DirectionSet& set, const Vec& u) { return std::max(0.0, -set.approx_signed_clearance(u)); }

// A direction halfway between where the reach sets of a and b are nearest: at a corner of
// one of them and the point of the other nearest it (searched in doubles; the candidate is
// then tested exactly like any other).
std::optional<Direction> midpoint(const Target& a, const Target& b) {
  double best = std::numeric_limits<double>::infinity();
  std::optional<std::pair<Direction, Direction>> pair;
  auto scan = [&](const DirectionSet& from, const DirectionSet& to) {
    for (const Direction& v : from.corners()) {
      const double d = approx_distance(to, v.unit());
      if (d < best) best = d, pair.emplace(v, to.snap(v.unit()));
    }
  };
  scan(a.reach, b.reach);
  scan(b.reach, a.reach);
  if (!pair) return std::nullopt;
  const Vec p = pair->first.unit(), q = pair->second.unit();
  const Vec m = {p[0] + q[0], p[1] + q[1], p[2] + q[2]};
  if (m[0] == 0 && m[1] == 0 && m[2] == 0) return std::nullopt;
  return Direction(m[0], m[1], m[2]);
}

// The exact optimum over certified supersets of the targets' epsilon-neighbourhoods: a
// lower bound for every direction. Nothing when some cover cannot be certified or the
// search was stopped.
std::optional<ExactCover> cover_of_dilations(std::span<const Target> targets, const Tolerance& tolerance,
                                             const CoverOptions& options) {
  std::vector<Target> covers;
  for (const Target& t : targets) {
    std::optional<DirectionSet> c = t.reach.dilation_cover(tolerance.radians, tolerance.cover_sin2);
    if (!c) return std::nullopt;
    covers.push_back({t.surface, {}, 0, *c, *c, *c});
  }
  auto contains = [&](uint32_t t, const Direction& d) { return covers[t].reach.contains(d); };
  StatusOr<ExactCover> exact = exact_cover(covers, contains, options);
  if (!exact.ok() || exact->solution.cancelled) return std::nullopt;
  return std::move(*exact);
}

CoverProblem problem(uint32_t items, const std::vector<Candidate>& candidates) {
  CoverProblem p{items, {}};
  for (const Candidate& c : candidates) p.candidates.push_back(c.targets);
  return p;
}

}  // namespace

Tolerance Tolerance::of(double radians) {
  Tolerance t;
  t.radians = radians;
  if (!(radians > 0)) return t;
  const double s = std::sin(radians), s2 = std::sin(2 * radians);
  t.near_sin2 = s * s * (1 - 0x1p-46);
  t.cover_sin2 = s * s * (1 + 0x1p-46);
  t.far_sin2 = std::min(1.0, s2 * s2 * (1 + 0x1p-46));
  return t;
}

VerifiedPacking verify_packing(std::span<const Target> targets, const std::vector<uint32_t>& packing,
                               const Tolerance& tolerance) {
  VerifiedPacking out;
  for (uint32_t i : packing) {
    bool apart = true;
    for (uint32_t k : out.items) {
      if (targets[i].reach.within(targets[k].reach, tolerance.far_sin2)) {
        out.near_pairs.emplace_back(k, i);
        apart = false;
        break;
      }
    }
    if (apart) out.items.push_back(i);
  }
  return out;
}

StatusOr<ToleranceCover> tolerance_cover(std::span<const Target> targets, const CandidateSet& seeds,
                                         const std::function<bool(uint32_t, const Direction&)>& serves,
                                         const Tolerance& tolerance, const CoverOptions& options) {
  ToleranceCover out;
  const uint32_t n = static_cast<uint32_t>(targets.size());
  // The exact witnesses alone first: where their cover meets a packing that holds within
  // the tolerance, the corners (thousands on curved parts) are not needed.
  for (const bool with_corners : {false, true}) {
    std::vector<Direction> directions;
    std::vector<std::vector<uint32_t>> known;
    gather(targets, seeds, with_corners, directions, known, out.corners);
    out.candidates.candidates = evaluate_within(targets, directions, known, serves);
    out.candidates.evaluated = static_cast<uint32_t>(directions.size());
    out.candidates.overlay_vertices = seeds.overlay_vertices;
    if (with_corners) break;
    StatusOr<CoverSolution> first = solve_set_cover(problem(n, out.candidates.candidates), options);
    if (!first.ok()) return first.status();
    if (first->cancelled) {
      out.solution = std::move(*first);
      return out;
    }
    const VerifiedPacking packing = verify_packing(targets, first->packing, tolerance);
    if (packing.items.size() == first->chosen.size()) {
      out.solution = std::move(*first);
      out.solution.packing = packing.items;
      out.solution.lower_bound = static_cast<uint32_t>(packing.items.size());
      out.solution.optimal = true;
      out.candidate_lower_bound = out.solution.lower_bound;
      return out;
    }
  }
  for (int round = 0;; ++round) {
    StatusOr<CoverSolution> solution = solve_set_cover(problem(n, out.candidates.candidates), options);
    if (!solution.ok()) return solution.status();
    out.solution = std::move(*solution);
    if (out.solution.cancelled) return out;
    const VerifiedPacking packing = verify_packing(targets, out.solution.packing, tolerance);
    out.candidate_lower_bound = out.solution.lower_bound;
    out.solution.packing = packing.items;
    out.solution.lower_bound = static_cast<uint32_t>(packing.items.size());
    out.solution.optimal = out.solution.chosen.size() == out.solution.lower_bound;
    if (out.solution.optimal) return out;
    if (packing.near_pairs.empty() || round == kMidpointRounds) break;
    // Pairs of the packing closer than 2 epsilon: the direction between them.
    std::vector<Direction> between;
    for (const auto& [a, b] : packing.near_pairs) {
      if (std::optional<Direction> m = midpoint(targets[a], targets[b])) between.push_back(*m);
    }
    std::vector<Candidate> added =
        evaluate_within(targets, between, std::vector<std::vector<uint32_t>>(between.size()), serves);
    const size_t before = out.candidates.candidates.size();
    for (Candidate& c : added) {
      c.source = out.candidates.evaluated++;
      out.candidates.candidates.push_back(std::move(c));
    }
    out.midpoints += static_cast<uint32_t>(added.size());
    if (out.candidates.candidates.size() == before) break;
  }
  // The packing falls short: the optimum over the dilations' covers, whose witnesses may
  // also serve more within the tolerance than the candidates so far.
  std::optional<ExactCover> covers = cover_of_dilations(targets, tolerance, options);
  if (!covers) return out;
  std::vector<Direction> witnesses;
  for (const Candidate& c : covers->candidates.candidates) witnesses.push_back(c.direction);
  for (Candidate& c : evaluate_within(targets, witnesses, std::vector<std::vector<uint32_t>>(witnesses.size()), serves)) {
    c.source = out.candidates.evaluated++;
    out.candidates.candidates.push_back(std::move(c));
  }
  StatusOr<CoverSolution> solution = solve_set_cover(problem(n, out.candidates.candidates), options);
  if (!solution.ok()) return solution.status();
  if (solution->chosen.size() <= out.solution.chosen.size()) {
    const std::vector<uint32_t> packing = out.solution.packing;
    const uint32_t bound = out.solution.lower_bound;
    out.candidate_lower_bound = solution->lower_bound;
    out.solution = std::move(*solution);
    out.solution.packing = packing;
    out.solution.lower_bound = bound;
  }
  if (covers->solution.lower_bound > out.solution.lower_bound) {
    out.solution.lower_bound = covers->solution.lower_bound;
    out.bound_by_covers = true;
  }
  out.solution.optimal = out.solution.chosen.size() == out.solution.lower_bound;
  return out;
}

}  // namespace gvm::planner
