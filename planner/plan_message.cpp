// The plan message: the one place where the planner's exact results become doubles.
#include <algorithm>

#include "gvm/analysis_proto.h"
#include "plan_state.h"

namespace gvm::planner {
namespace {

void fill_surfaces(const PlanState& s, const std::vector<int32_t>& setup_of, v1::Plan& out) {
  for (uint32_t i = 0; i < s.surfaces.size(); ++i) {
    const Surface& surface = *s.surfaces[i];
    v1::PlannedSurface* p = out.add_surfaces();
    p->set_id(surface.id);
    if (surface.kind == Surface::Kind::kRegion) {
      std::string name = "R";  // appended: GCC 12 warns falsely on "R" + std::string
      p->set_name(name += std::to_string(surface.id));
    } else {
      p->set_name(surface.name);
    }
    p->set_face_count(static_cast<uint32_t>(surface.faces.size()));
    p->set_on_hull(surface.on_hull);
    p->set_planar(surface.planar_normal.has_value());
    p->set_gvm_dimension(surface.maps.gvm ? surface.maps.gvm->dimension() : -1);
    p->set_gvm_description(surface.maps.gvm ? surface.maps.gvm->description() : "not computed");
    p->set_setup(setup_of[i]);
  }
}

void fill_setup(const PlanState& s, const PlacedSetup& placed, v1::Setup* out) {
  to_proto(placed.direction, out->mutable_direction());
  double clearance = 180;
  for (const TargetReach& r : placed.reach) {
    const Target& t = s.targets[r.target];
    const uint32_t id = s.surfaces[t.surface]->id;
    if (t.faces.empty()) out->add_features(id);
    v1::SetupFeature* f = out->add_reach();
    f->set_feature(id);
    for (uint32_t face : t.faces) f->add_faces(face);
    f->set_clearance_degrees(r.clearance_degrees);
    f->set_exact_alignment(r.exact_alignment);
    for (const auto& [from, to] : r.rotary_angles) {
      v1::AngleRange* a = f->add_rotary_angles();
      a->set_from_degrees(from);
      a->set_to_degrees(to);
    }
    f->set_rotary_angle_degrees(r.rotary_angle_degrees);
    if (r.within_tolerance) {
      f->set_within_tolerance(true);
      f->set_distance_radians(r.distance_radians);
    }
    if (t.piece > 0) f->set_piece(t.piece);
    clearance = std::min(clearance, r.clearance_degrees);
    if (r.exact_alignment) out->set_exact_alignment(true);
  }
  std::sort(out->mutable_features()->begin(), out->mutable_features()->end());
  out->set_clearance_degrees(clearance);
  out->set_head_a_degrees(placed.head_a_degrees);
  out->set_head_b_degrees(placed.head_b_degrees);
  if (placed.rotary_zero) to_proto(*placed.rotary_zero, out->mutable_rotary_zero());
}

// Surfaces planned piece by piece: how many pieces, and the setups that reach them.
void fill_pieces(const PlanState& s, v1::Plan& out) {
  for (const SplitSurface& split : s.split) {
    out.mutable_surfaces(static_cast<int>(split.surface))->mutable_pieces()->set_count(split.pieces);
  }
  for (const UnreachableSurface& u : s.unreachable) {
    if (u.pieces > 0) out.mutable_surfaces(static_cast<int>(u.surface))->mutable_pieces()->set_count(u.pieces);
  }
  for (size_t k = 0; k < s.setups.size(); ++k) {
    for (const TargetReach& r : s.setups[k].reach) {
      const Target& t = s.targets[r.target];
      if (t.faces.empty()) continue;
      auto* setups = out.mutable_surfaces(static_cast<int>(t.surface))->mutable_pieces()->mutable_setups();
      if (setups->empty() || setups->at(setups->size() - 1) != static_cast<int32_t>(k)) setups->Add(static_cast<int32_t>(k));
    }
  }
}

void fill_tolerance(const PlanState& s, v1::Plan& out) {
  if (!s.tolerance.active()) {
    out.mutable_options()->clear_tolerance_radians();  // an exact plan reads as before
    return;
  }
  v1::PlanTolerance* t = out.mutable_tolerance();
  t->set_radians(s.tolerance.radians);
  t->set_exact_setups(s.exact ? s.exact->setups : 0);
  t->set_exact_lower_bound(s.exact ? s.exact->lower_bound : 0);
  uint32_t within = 0;
  for (const PlacedSetup& p : s.setups) {
    for (const TargetReach& r : p.reach) within += r.within_tolerance;
  }
  t->set_reached_within(within);
}

void fill_unreachable(const PlanState& s, const UnreachableSurface& u, v1::Unreachable* out) {
  out->set_feature(s.surfaces[u.surface]->id);
  out->set_reason(u.reason);
  out->set_detail(u.detail);
  for (uint32_t f : u.blocking_features) out->add_blocking_features(f);
  if (u.probed_direction) to_proto(*u.probed_direction, out->mutable_probed_direction());
  out->set_nearest_head_a_degrees(u.nearest.nearest_head_a_degrees);
  out->set_nearest_head_b_degrees(u.nearest.nearest_head_b_degrees);
  out->set_nearest_clearance_degrees(u.nearest.nearest_clearance_degrees);
  out->set_pieces_reached(u.pieces_reached);
  for (const auto& [faces, reason] : u.pieces_unreachable) {
    v1::UnreachablePiece* p = out->add_pieces_unreachable();
    for (uint32_t f : faces) p->add_faces(f);
    p->set_reason(reason);
  }
}

std::string solver_text(const PlanState& s) {
  const CoverSolution& c = s.cover;
  const std::string solver = c.solver_ran ? "COIN-OR Cbc 2.10 (greedy warm start)" : "greedy";
  if (!s.candidate_lower_bound) return c.solver_ran ? solver : solver + ", proven by the packing bound";
  const std::string bound = s.bound_by_covers
                                ? "the exact optimum over certified covers of the sets' tolerance neighbourhoods"
                                : "the packing bound";
  if (s.setups.size() == c.lower_bound) return solver + ", proven by " + bound;
  return solver + "; bound " + std::to_string(*s.candidate_lower_bound) + " over the candidates, " +
         std::to_string(c.lower_bound) + " over every direction by " + bound;
}

void fill_solver(const PlanState& s, v1::SolverStatistics* out) {
  const CoverSolution& c = s.cover;
  out->set_solver(solver_text(s));
  out->set_candidate_set(s.candidates.description);
  out->set_candidates(s.candidates.evaluated);
  out->set_maximal_candidates(static_cast<uint32_t>(s.candidates.candidates.size()));
  out->set_overlay_vertices(s.candidates.overlay_vertices);
  out->set_greedy_setups(c.greedy);
  out->set_packing_bound(static_cast<uint32_t>(c.packing.size()));
  out->set_lp_bound(c.lp_bound);
  out->set_nodes(c.nodes);
  out->set_solver_ran(c.solver_ran);
  out->set_time_limit_reached(c.time_limit_reached);
  if (s.continuous_lower_bound) out->set_continuous_lower_bound(*s.continuous_lower_bound);
}

void fill_timing(const PlanState& s, v1::PlanTiming* out) {
  out->set_analysis_seconds(s.analysis->timing().total);
  out->set_candidates_seconds(s.times.candidates);
  out->set_cover_seconds(s.times.cover);
  out->set_placement_seconds(s.times.placement);
  out->set_unreachable_seconds(s.times.unreachable);
  out->set_total_seconds(s.times.total);
  out->set_threads(s.times.threads);
}

}  // namespace

v1::Plan plan_message(const PlanState& s) {
  v1::Plan out;
  out.set_mode(s.options.mode());
  *out.mutable_options() = s.options;
  to_proto(s.analysis->part(), out.mutable_part());
  out.set_surfaces_kind(s.options.surfaces());
  std::vector<int32_t> setup_of(s.surfaces.size(), -1);
  for (size_t k = 0; k < s.setups.size(); ++k) {
    fill_setup(s, s.setups[k], out.add_setups());
    for (const TargetReach& r : s.setups[k].reach) {
      const Target& t = s.targets[r.target];
      if (t.faces.empty()) setup_of[t.surface] = static_cast<int32_t>(k);
    }
  }
  fill_surfaces(s, setup_of, out);
  fill_pieces(s, out);
  for (const UnreachableSurface& u : s.unreachable) fill_unreachable(s, u, out.add_unreachable());
  // Setups that served nothing were dropped, which can only meet the bound sooner.
  out.set_lower_bound(s.cover.lower_bound);
  out.set_optimal(s.cover.lower_bound == s.setups.size());
  for (uint32_t t : s.cover.packing) out.add_lower_bound_witness(s.surfaces[s.targets[t].surface]->id);
  out.set_reached(static_cast<uint32_t>(std::count_if(setup_of.begin(), setup_of.end(), [](int32_t k) { return k >= 0; }) +
                                        s.split.size()));
  out.set_unreachable_count(static_cast<uint32_t>(s.unreachable.size()));
  fill_solver(s, out.mutable_solver());
  fill_tolerance(s, out);
  fill_timing(s, out.mutable_timing());
  out.set_engine_version(GVM_VERSION);
  return out;
}

}  // namespace gvm::planner
