#include "targets.h"

namespace gvm::planner {

std::vector<const Surface*> planned_surfaces(const Analysis& analysis, const v1::PlanOptions& options) {
  std::vector<const Surface*> out;
  if (options.surfaces() == v1::PLAN_SURFACES_REGIONS) {
    for (const Surface& r : analysis.regions()) out.push_back(&r);
    return out;
  }
  for (const Surface& f : analysis.features()) {
    if (!options.concave_only() || !f.on_hull) out.push_back(&f);
  }
  return out;
}

DirectionSet tool_directions(const DirectionSet& gvm, const std::optional<Direction>& planar_normal,
                             bool planar_normal_only) {
  if (!planar_normal_only || !planar_normal) return gvm;
  return gvm.contains(*planar_normal) ? DirectionSet::point(*planar_normal) : DirectionSet();
}

DirectionSet rotary_axes(const DirectionSet& directions) {
  DirectionSet axes;
  for (const DirectionSet& cell : directions.cells()) {
    // A connected cell misses the circle of a only if it lies in one open hemisphere
    // around a or -a, i.e. a in +-Int(polar(cell)).
    const DirectionSet polar = cell.polar();
    axes = axes.union_with(DirectionSet::full_sphere().difference(polar).difference(polar.antipodal()));
    if (axes.is_full_sphere()) break;
  }
  return axes;
}

}  // namespace gvm::planner
