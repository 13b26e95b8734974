// One planning run: the targets and the surfaces that cannot be reached, the candidates
// of the mode, the exact set cover, the assignment of every target to one chosen setup,
// the placement of each setup, and the reasons; then the message.
#include "gvm/planner/plan.h"

#include <spdlog/spdlog.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <chrono>
#include <numeric>
#include <optional>
#include <stop_token>
#include <tuple>

#include "exact_cover.h"
#include "gvm/cancellable_run.h"
#include "plan_state.h"

namespace gvm::planner {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::unique_ptr<Mode> make_mode(const v1::PlanOptions& o) {
  switch (o.mode()) {
    case v1::PLAN_MODE_ROTARY:
      return make_rotary_mode(o);
    case v1::PLAN_MODE_PROBE:
      return make_probe_mode(o);
    default:
      return make_setup_mode(o);
  }
}

// Automatic features up to this many faces are split by default (PlanOptions.split_max_faces).
constexpr uint32_t kDefaultSplitMaxFaces = 20000;

uint32_t split_max_faces(const v1::PlanOptions& o) {
  return o.has_split_max_faces() ? o.split_max_faces() : kDefaultSplitMaxFaces;
}

class Planner {
 public:
  // Runs in a task of `ctx`, which a stop request cancels: its parallel loops then stop
  // early (each is followed by a check), and the engine's calls inside it give up
  // (Analysis::surface_of answers kCancelled, others may throw; plan() maps both).
  Planner(const Analysis& analysis, const v1::PlanOptions& options, const PlanControl& control,
          int threads, tbb::task_group_context& ctx)
      : mode_(make_mode(options)), control_(control), ctx_(ctx) {
    state_.times.threads = static_cast<uint32_t>(threads);
    state_.analysis = &analysis;
    state_.options = options;
    state_.surfaces = planned_surfaces(analysis, options);
    state_.tolerance = Tolerance::of(options.tolerance_radians());
  }

  StatusOr<SetupPlan> run() {
    const auto t0 = Clock::now();
    collect_targets();
    if (!split_unreachable()) return cancelled();
    if (!keep_going("candidates", 0, 1)) return cancelled();
    Status covered = cover();
    if (!covered.ok()) return covered;
    if (!keep_going("placement", 0, 1)) return cancelled();
    place_setups();
    if (!keep_going("reasons", 0, 1)) return cancelled();
    if (!explain_unreachable()) return cancelled();
    state_.times.total = seconds_since(t0);
    SetupPlan out;
    out.message = plan_message(state_);
    for (const PlacedSetup& s : state_.setups) out.directions.push_back(s.direction);
    return out;
  }

 private:
  static Status cancelled() { return Status(StatusCode::kCancelled, "planning cancelled"); }

  // False once stopped (a stop request, or progress saying so: then the task group is
  // cancelled too, so that parallel work in flight winds down).
  bool keep_going(std::string_view phase, size_t done, size_t total) {
    if (stopped_ || ctx_.is_group_execution_cancelled()) {
      stopped_ = true;
      return false;
    }
    if (!control_.progress || control_.progress(phase, done, total)) return true;
    stopped_ = true;
    ctx_.cancel_group_execution();
    return false;
  }

  // A target for every planned surface that some setup can reach; the others are
  // unreachable from their own maps.
  void collect_targets() {
    const bool normal_only = state_.options.planar_normal();
    for (uint32_t i = 0; i < state_.surfaces.size(); ++i) {
      const Surface& s = *state_.surfaces[i];
      const DirectionSet directions =
          s.maps.gvm ? tool_directions(*s.maps.gvm, s.planar_normal, normal_only) : DirectionSet();
      if (directions.is_empty()) {
        state_.unreachable.emplace_back(i, reason_of_empty_reach(s, normal_only));
        continue;
      }
      state_.targets.push_back({i, {}, 0, *s.maps.gvm, directions, mode_->reach_of(directions)});
    }
  }

  // Pieces of unreachable surfaces become targets of their own (their maps computed in
  // parallel, kept in piece order). A piece of an automatic feature that the rest of the
  // part occludes whole is cut again, along its seeds' normals.
  bool split_unreachable() {
    const auto t0 = Clock::now();
    const bool normal_only = state_.options.planar_normal();
    for (size_t k = 0; k < state_.unreachable.size(); ++k) {
      UnreachableSurface& u = state_.unreachable[k];
      if (!keep_going("split", k, state_.unreachable.size())) return false;
      std::vector<std::vector<uint32_t>> pieces = pieces_of(u);
      if (pieces.size() < 2) {
        u.split_by_direction = false;
        continue;
      }
      std::vector<std::optional<Surface>> maps = maps_of(pieces);
      if (u.split_by_direction) recut_occluded(pieces, maps);
      if (!keep_going("split", k, state_.unreachable.size())) return false;  // pieces left undone
      u.pieces = static_cast<uint32_t>(pieces.size());
      for (size_t i = 0; i < pieces.size(); ++i) {
        if (!maps[i]) continue;
        const Surface& piece = *maps[i];
        const DirectionSet directions =
            piece.maps.gvm ? tool_directions(*piece.maps.gvm, piece.planar_normal, normal_only) : DirectionSet();
        if (directions.is_empty()) {
          u.pieces_unreachable.push_back({pieces[i], piece_reason(piece, normal_only)});
          continue;
        }
        state_.targets.push_back({u.surface, pieces[i], static_cast<uint32_t>(i + 1), *piece.maps.gvm, directions,
                                  mode_->reach_of(directions)});
      }
    }
    state_.times.unreachable += seconds_since(t0);
    return true;
  }

  std::vector<std::optional<Surface>> maps_of(const std::vector<std::vector<uint32_t>>& pieces) const {
    std::vector<std::optional<Surface>> maps(pieces.size());
    tbb::parallel_for(size_t{0}, pieces.size(), [&](size_t i) {
      StatusOr<Surface> piece = state_.analysis->surface_of(pieces[i]);
      if (piece.ok()) maps[i] = std::move(*piece);  // the faces come from the part: only a cancel fails
    });
    return maps;
  }

  // Pieces with a direction of their own (LVM(S + N_S)) that the rest of the part takes
  // away (an empty GVM) replaced by their pieces along their seeds' normals, when that
  // cuts them.
  void recut_occluded(std::vector<std::vector<uint32_t>>& pieces, std::vector<std::optional<Surface>>& maps) const {
    std::vector<std::vector<uint32_t>> out_pieces;
    std::vector<std::optional<Surface>> out_maps;
    for (size_t i = 0; i < pieces.size(); ++i) {
      const bool occluded = maps[i] && maps[i]->maps.gvm && maps[i]->maps.gvm->is_empty() && !maps[i]->maps.lvm.is_empty();
      std::vector<std::vector<uint32_t>> cut;
      if (occluded && pieces[i].size() > 1) cut = state_.analysis->visible_pieces(pieces[i], Analysis::Growth::kAlongSeedNormal);
      if (cut.size() < 2) {
        out_pieces.push_back(std::move(pieces[i]));
        out_maps.push_back(std::move(maps[i]));
        continue;
      }
      std::vector<std::optional<Surface>> cut_maps = maps_of(cut);
      for (size_t j = 0; j < cut.size(); ++j) {
        out_pieces.push_back(std::move(cut[j]));
        out_maps.push_back(std::move(cut_maps[j]));
      }
    }
    pieces = std::move(out_pieces);
    maps = std::move(out_maps);
  }

  // An automatic feature whose own faces have no common direction: in pieces that have one
  // (unless --no-split). With --split, any other unreachable surface: in its planar pieces.
  std::vector<std::vector<uint32_t>> pieces_of(UnreachableSurface& u) const {
    if (u.reason == v1::UNREACHABLE_REASON_VOID || u.reason == v1::UNREACHABLE_REASON_GVM_NOT_COMPUTED) return {};
    const Surface& s = *state_.surfaces[u.surface];
    if (!state_.options.no_split() && s.automatic && u.reason == v1::UNREACHABLE_REASON_SELF_OCCLUDED) {
      if (const uint32_t limit = split_max_faces(state_.options); limit > 0 && s.faces.size() > limit) {
        u.split_limit = limit;
        return {};
      }
      const StatusOr<DirectionSet> own = state_.analysis->own_lvm(s.faces);
      if (own.ok() && own->is_empty()) {
        u.split_by_direction = true;
        return state_.analysis->visible_pieces(s.faces);
      }
    }
    if (!state_.options.split()) return {};
    return state_.analysis->planar_pieces(s.faces);
  }

  // A piece's own faces may have a direction that its neighbours take away.
  v1::UnreachableReason piece_reason(const Surface& piece, bool normal_only) const {
    const v1::UnreachableReason r = reason_of_empty_reach(piece, normal_only);
    if (r != v1::UNREACHABLE_REASON_SELF_OCCLUDED) return r;
    const StatusOr<DirectionSet> own = state_.analysis->own_lvm(piece.faces);
    return own.ok() && !own->is_empty() ? v1::UNREACHABLE_REASON_NEIGHBOR_OCCLUDED : r;
  }

  CoverOptions cover_options() {
    CoverOptions options;
    options.time_limit_seconds = state_.options.time_limit_seconds();
    options.cancelled = [this] { return !keep_going("set cover", 0, 1); };
    return options;
  }

  Status cover() {
    if (Status s = cover_exactly(); !s.ok() || !state_.tolerance.active()) return s;
    return cover_within();
  }

  Status cover_exactly() {
    const auto t0 = Clock::now();
    const CoverOptions options = cover_options();
    if (mode_->exact()) {
      auto serves = [this](uint32_t t, const Direction& d) { return mode_->serves(state_.targets[t], d); };
      StatusOr<ExactCover> exact = exact_cover(state_.targets, serves, options);
      if (!exact.ok()) return exact.status();
      if (exact->solution.cancelled || stopped_) return cancelled();
      state_.candidates = std::move(exact->candidates);
      state_.cover = std::move(exact->solution);
      const size_t n = state_.targets.size(), k = exact->overlay_targets;
      state_.candidates.description =
          k == n ? "every direction (the exact arrangement of all " + std::to_string(n) + " reach sets' boundaries)"
                 : "every direction (the exact arrangement of " + std::to_string(k) + " of the " + std::to_string(n) +
                       " reach sets' boundaries proves the bound; the others are tested at its witnesses)";
      state_.times.candidates = seconds_since(t0);
      return Status::Ok();
    }
    state_.candidates = mode_->candidates(state_.targets);
    state_.times.candidates = seconds_since(t0);
    const auto t1 = Clock::now();
    StatusOr<CoverSolution> solution = solve_set_cover(problem(state_.candidates.candidates), options);
    if (!solution.ok()) return solution.status();
    if (solution->cancelled || stopped_) return cancelled();
    state_.cover = std::move(*solution);
    if (!state_.candidates.relaxed.empty()) {
      // Without the clearance requirement every direction is a candidate: its optimum is
      // a lower bound over the continuum, not only over the stated candidates.
      StatusOr<CoverSolution> relaxed = solve_set_cover(problem(state_.candidates.relaxed), options);
      if (relaxed.ok() && !relaxed->cancelled) state_.continuous_lower_bound = relaxed->lower_bound;
    }
    state_.times.cover = seconds_since(t1);
    spdlog::debug("plan: {} targets, {} candidates, cover of {} (bound {})", state_.targets.size(),
                  state_.candidates.candidates.size(), state_.cover.chosen.size(), state_.cover.lower_bound);
    return Status::Ok();
  }

  // Again within the tolerance, from the exact plan's candidates: the exact count is kept
  // for the message.
  Status cover_within() {
    const auto t0 = Clock::now();
    state_.exact = ExactCount{static_cast<uint32_t>(state_.cover.chosen.size()), state_.cover.lower_bound};
    state_.continuous_lower_bound.reset();  // the optimum without a clearance requirement, but exactly
    const CoverOptions options = cover_options();
    auto within = [this](uint32_t t, const Direction& d) {
      return mode_->serves_within(state_.targets[t], d, state_.tolerance);
    };
    if (std::optional<CandidateSet> all = mode_->candidates_within(state_.targets, state_.tolerance)) {
      StatusOr<CoverSolution> solution = solve_set_cover(problem(all->candidates), options);
      if (!solution.ok()) return solution.status();
      if (solution->cancelled || stopped_) return cancelled();
      state_.candidates = std::move(*all);
      state_.cover = std::move(*solution);
    } else {
      StatusOr<ToleranceCover> c = tolerance_cover(state_.targets, state_.candidates, within, state_.tolerance, options);
      if (!c.ok()) return c.status();
      if (c->solution.cancelled || stopped_) return cancelled();
      c->candidates.description = "every direction within the tolerance (candidates: " +
                                  std::to_string(state_.candidates.candidates.size()) + " exact witnesses, " +
                                  std::to_string(c->corners) + " corners of the reach sets and " +
                                  std::to_string(c->midpoints) +
                                  " midpoints, each tested within it)";
      state_.candidates = std::move(c->candidates);
      state_.cover = std::move(c->solution);
      state_.candidate_lower_bound = c->candidate_lower_bound;
      state_.bound_by_covers = c->bound_by_covers;
    }
    state_.times.cover += seconds_since(t0);
    return Status::Ok();
  }

  // Whether a setup at d serves the target as this plan decides it.
  bool serves(const Target& t, const Direction& d) const {
    return state_.tolerance.active() ? mode_->serves_within(t, d, state_.tolerance) : mode_->serves(t, d);
  }

  CoverProblem problem(const std::vector<Candidate>& candidates) const {
    CoverProblem p;
    p.items = static_cast<uint32_t>(state_.targets.size());
    for (const Candidate& c : candidates) p.candidates.push_back(c.targets);
    return p;
  }

  // Every target to one chosen setup: the first, in order of decreasing coverage, that
  // serves it. Setups left with nothing (another setup serves all they would) are dropped.
  std::vector<std::pair<uint32_t, std::vector<uint32_t>>> assignment() const {
    const std::vector<Candidate>& all = state_.candidates.candidates;
    std::vector<uint32_t> order = state_.cover.chosen;
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
      return all[a].targets.size() > all[b].targets.size();
    });
    std::vector<std::vector<uint32_t>> assigned(order.size());
    std::vector<char> done(state_.targets.size(), 0);
    for (size_t k = 0; k < order.size(); ++k) {
      for (uint32_t t : all[order[k]].targets) {
        if (!done[t]) done[t] = 1, assigned[k].push_back(t);
      }
    }
    std::vector<std::pair<uint32_t, std::vector<uint32_t>>> out;
    for (size_t k = 0; k < order.size(); ++k) {
      if (!assigned[k].empty()) out.push_back({order[k], std::move(assigned[k])});
    }
    return out;
  }

  void place_setups() {
    const auto t0 = Clock::now();
    std::vector<std::pair<Candidate, std::vector<uint32_t>>> setups;
    for (auto& [candidate, assigned] : assignment()) {
      setups.push_back({state_.candidates.candidates[candidate], std::move(assigned)});
    }
    place(setups, std::vector<char>(setups.size(), 1));
    if (ctx_.is_group_execution_cancelled()) return;  // setups left unplaced: run() stops
    // Once the directions are known, a target served by several setups goes to the one
    // where it has the most room (a side face machined from the side rather than grazed
    // from the top); setups that changed are placed again from where they are.
    std::vector<char> changed(setups.size(), 0);
    for (auto& [moved, from, to] : moves(setups)) {
      auto& source = setups[from].second;
      source.erase(std::find(source.begin(), source.end(), moved));
      setups[to].second.insert(std::upper_bound(setups[to].second.begin(), setups[to].second.end(), moved), moved);
      changed[from] = changed[to] = 1;
    }
    for (size_t k = 0; k < setups.size(); ++k) {
      if (changed[k]) setups[k].first.direction = state_.setups[k].direction;
    }
    place(setups, changed);
    std::vector<PlacedSetup> kept;
    for (PlacedSetup& s : state_.setups) {
      if (!s.reach.empty()) kept.push_back(std::move(s));
    }
    state_.setups = std::move(kept);
    state_.times.placement = seconds_since(t0);
  }

  // Places the setups marked (in parallel; each one's result depends on it alone).
  void place(const std::vector<std::pair<Candidate, std::vector<uint32_t>>>& setups, const std::vector<char>& which) {
    state_.setups.resize(setups.size());
    tbb::parallel_for(size_t{0}, setups.size(), [&](size_t k) {
      if (!which[k]) return;
      if (setups[k].second.empty()) {
        state_.setups[k] = PlacedSetup{};
        return;
      }
      state_.setups[k] = place_one(setups[k].first, setups[k].second);
    });
  }

  // A setup whose direction some target is reached from only within the tolerance stays
  // where it is (a move could take it farther); the others are placed by the mode.
  PlacedSetup place_one(const Candidate& chosen, const std::vector<uint32_t>& assigned) const {
    std::vector<uint32_t> exact, loose;
    for (uint32_t t : assigned) (mode_->serves(state_.targets[t], chosen.direction) ? exact : loose).push_back(t);
    if (loose.empty()) return mode_->place(chosen, state_.targets, assigned);
    PlacedSetup p = mode_->place_fixed(chosen, state_.targets, exact, loose);
    for (TargetReach& r : p.reach) {
      if (std::find(loose.begin(), loose.end(), r.target) == loose.end()) continue;
      r.within_tolerance = true;
      r.exact_alignment = true;
      r.distance_radians = std::max(0.0, -state_.targets[r.target].reach.approx_signed_clearance(p.direction.unit()));
    }
    std::sort(p.reach.begin(), p.reach.end(), [](const TargetReach& a, const TargetReach& b) { return a.target < b.target; });
    return p;
  }

  // (target, from, to): targets with more clearance in another placed setup that serves
  // them (decided by doubles; whether it serves them, exactly).
  std::vector<std::tuple<uint32_t, size_t, size_t>> moves(
      const std::vector<std::pair<Candidate, std::vector<uint32_t>>>& setups) const {
    std::vector<std::tuple<uint32_t, size_t, size_t>> out;
    for (size_t from = 0; from < setups.size(); ++from) {
      for (uint32_t t : setups[from].second) {
        const Target& target = state_.targets[t];
        size_t best = from;
        double room = target.reach.approx_signed_clearance(state_.setups[from].direction.unit());
        for (size_t k = 0; k < setups.size(); ++k) {
          const double r = target.reach.approx_signed_clearance(state_.setups[k].direction.unit());
          if (k != from && r > room && serves(target, state_.setups[k].direction)) best = k, room = r;
        }
        if (best != from) out.emplace_back(t, from, best);
      }
    }
    return out;
  }

  // Reasons for the unreachable surfaces, and targets no candidate serves (cone,
  // clearance) become unreachable too.
  bool explain_unreachable() {
    const auto t0 = Clock::now();
    for (uint32_t t : state_.cover.uncoverable) {
      const Target& target = state_.targets[t];
      if (!target.faces.empty()) {
        unreachable_of(target.surface).pieces_unreachable.push_back({target.faces, mode_->unserved(target).reason});
        continue;
      }
      const Unserved why = mode_->unserved(target);
      state_.unreachable.emplace_back(target.surface, why.reason).nearest = why;
    }
    for (const PlacedSetup& s : state_.setups) {
      for (const TargetReach& r : s.reach) {
        if (!state_.targets[r.target].faces.empty()) ++unreachable_of(state_.targets[r.target].surface).pieces_reached;
      }
    }
    // Surfaces every piece of which is reached are reached, piece by piece.
    std::erase_if(state_.unreachable, [this](const UnreachableSurface& u) {
      const bool reached = u.pieces > 0 && u.pieces_unreachable.empty() && u.pieces_reached == u.pieces;
      if (reached) state_.split.push_back({u.surface, u.pieces});
      return reached;
    });
    std::sort(state_.split.begin(), state_.split.end(),
              [](const SplitSurface& a, const SplitSurface& b) { return a.surface < b.surface; });
    std::sort(state_.unreachable.begin(), state_.unreachable.end(),
              [](const UnreachableSurface& a, const UnreachableSurface& b) { return a.surface < b.surface; });
    if (!keep_going("reasons", 0, state_.unreachable.size())) return false;
    tbb::parallel_for(size_t{0}, state_.unreachable.size(), [&](size_t k) {
      UnreachableSurface& u = state_.unreachable[k];
      explain(*state_.analysis, *state_.surfaces[u.surface], u);
    });
    if (!keep_going("reasons", state_.unreachable.size(), state_.unreachable.size())) return false;
    state_.times.unreachable += seconds_since(t0);
    return true;
  }

  UnreachableSurface& unreachable_of(uint32_t surface) {
    for (UnreachableSurface& u : state_.unreachable) {
      if (u.surface == surface) return u;
    }
    // Never reached: pieces only come from surfaces already unreachable.
    return state_.unreachable.emplace_back(surface, v1::UNREACHABLE_REASON_UNSPECIFIED);
  }

  std::unique_ptr<Mode> mode_;
  const PlanControl& control_;
  tbb::task_group_context& ctx_;
  PlanState state_;
  bool stopped_ = false;
};

}  // namespace

StatusOr<SetupPlan> plan(const Analysis& analysis, const v1::PlanOptions& options,
                         const PlanControl& control) {
  if (Status s = validate(options); !s.ok()) return s;
  const v1::PlanOptions applied = with_defaults(options);
  const int threads = arena_threads(static_cast<int>(applied.threads()));
  return cancellable_run<SetupPlan>(threads, control.stop, "planning cancelled",
                                    [&](tbb::task_group_context& ctx) {
                                      return Planner(analysis, applied, control, threads, ctx).run();
                                    });
}

}  // namespace gvm::planner
