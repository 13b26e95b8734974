// Plan options: checked field by field, and completed with the defaults of each mode.
#include <cmath>
#include <cstdio>
#include <string>

#include "gvm/planner/plan.h"

namespace gvm::planner {
namespace {

constexpr double kDefaultCone = 5;  // the usual conical tolerance of CMM probing
// Above the tilt that single-precision STL coordinates give a facet (~1e-7 rad), well below
// any machine's indexing resolution (~1e-5 rad).
constexpr double kDefaultTolerance = 1e-6;
constexpr double kMaxTolerance = 0.017453292519943295;  // one degree: rounding, not a clearance

bool finite_at_least(double x, double lo) { return std::isfinite(x) && x >= lo; }

std::string num(double x) {
  std::string s = std::to_string(x);
  while (s.size() > 1 && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

Status check_head(const v1::ProbeHead& h) {
  if (!finite_at_least(h.a_min_degrees(), 0) || !finite_at_least(h.a_max_degrees(), h.a_min_degrees()) ||
      h.a_max_degrees() > 180) {
    return InvalidArgument("head: A range " + num(h.a_min_degrees()) + ".." + num(h.a_max_degrees()) +
                           " must satisfy 0 <= A_MIN <= A_MAX <= 180 degrees");
  }
  if (!std::isfinite(h.b_min_degrees()) || !finite_at_least(h.b_max_degrees(), h.b_min_degrees()) ||
      h.b_min_degrees() < -360 || h.b_max_degrees() > 360 || h.b_max_degrees() - h.b_min_degrees() > 360) {
    return InvalidArgument("head: B range " + num(h.b_min_degrees()) + ".." + num(h.b_max_degrees()) +
                           " must satisfy B_MIN <= B_MAX, within -360..360 and at most 360 degrees wide");
  }
  if (!(std::isfinite(h.step_degrees()) && h.step_degrees() > 0)) {
    return InvalidArgument("head: step " + num(h.step_degrees()) + " must be a positive number of degrees");
  }
  const double a_steps = (h.a_max_degrees() - h.a_min_degrees()) / h.step_degrees();
  const double b_steps = (h.b_max_degrees() - h.b_min_degrees()) / h.step_degrees();
  if ((a_steps + 1) * (b_steps + 1) > 1e6) {
    return InvalidArgument("head: a step of " + num(h.step_degrees()) +
                           " degrees gives more than a million orientations");
  }
  return Status::Ok();
}

Status check_probe_fields(const v1::PlanOptions& o) {
  if (o.has_head()) {
    if (Status s = check_head(o.head()); !s.ok()) return s;
  }
  if (o.has_part_up()) {
    const auto& u = o.part_up();
    if (!std::isfinite(u.x()) || !std::isfinite(u.y()) || !std::isfinite(u.z()) ||
        (u.x() == 0 && u.y() == 0 && u.z() == 0)) {
      return InvalidArgument("part_up: (" + num(u.x()) + ", " + num(u.y()) + ", " + num(u.z()) +
                             ") must be a non-zero finite vector");
    }
  }
  if (o.has_cone_degrees() && !(finite_at_least(o.cone_degrees(), 0) && o.cone_degrees() < 90)) {
    return InvalidArgument("cone_degrees: " + num(o.cone_degrees()) +
                           " must be at least 0 and less than 90 degrees");
  }
  return Status::Ok();
}

}  // namespace

Status validate(const v1::PlanOptions& o) {
  if (!v1::PlanMode_IsValid(o.mode())) {
    return InvalidArgument("mode: unknown value " + std::to_string(o.mode()));
  }
  if (!v1::PlanSurfaces_IsValid(o.surfaces())) {
    return InvalidArgument("surfaces: unknown value " + std::to_string(o.surfaces()));
  }
  if (!finite_at_least(o.time_limit_seconds(), 0)) {
    return InvalidArgument("time_limit_seconds: " + num(o.time_limit_seconds()) +
                           " must be a non-negative number of seconds");
  }
  if (o.threads() > 1024) {
    return InvalidArgument("threads: " + std::to_string(o.threads()) + " is more than 1024");
  }
  if (o.has_tolerance_radians() &&
      !(finite_at_least(o.tolerance_radians(), 0) && o.tolerance_radians() <= kMaxTolerance)) {
    char value[32];
    std::snprintf(value, sizeof value, "%.6g", o.tolerance_radians());
    return InvalidArgument(std::string("tolerance_radians: ") + value +
                           " must be at least 0 and at most 0.0174533 (one degree)");
  }
  const bool probe = o.mode() == v1::PLAN_MODE_PROBE;
  const bool setup = o.mode() == v1::PLAN_MODE_SETUP || o.mode() == v1::PLAN_MODE_UNSPECIFIED;
  if (o.min_clearance_degrees() != 0) {
    if (!setup) {
      return InvalidArgument("min_clearance_degrees applies to the setup mode only (probe mode: cone_degrees)");
    }
    if (!(finite_at_least(o.min_clearance_degrees(), 0) && o.min_clearance_degrees() < 90)) {
      return InvalidArgument("min_clearance_degrees: " + num(o.min_clearance_degrees()) +
                             " must be at least 0 and less than 90 degrees");
    }
  }
  if (!probe && (o.has_head() || o.has_part_up() || o.has_cone_degrees())) {
    return InvalidArgument(std::string(o.has_head() ? "head" : o.has_part_up() ? "part_up" : "cone_degrees") +
                           " applies to the probe mode only");
  }
  return probe ? check_probe_fields(o) : Status::Ok();
}

v1::PlanOptions with_defaults(const v1::PlanOptions& options) {
  v1::PlanOptions o = options;
  if (o.mode() == v1::PLAN_MODE_UNSPECIFIED) o.set_mode(v1::PLAN_MODE_SETUP);
  if (o.surfaces() == v1::PLAN_SURFACES_UNSPECIFIED) o.set_surfaces(v1::PLAN_SURFACES_FEATURES);
  if (!o.has_tolerance_radians()) o.set_tolerance_radians(kDefaultTolerance);
  if (o.mode() != v1::PLAN_MODE_PROBE) return o;
  if (!o.has_head()) {
    v1::ProbeHead* h = o.mutable_head();
    h->set_a_min_degrees(0);
    h->set_a_max_degrees(105);
    h->set_b_min_degrees(-180);
    h->set_b_max_degrees(180);
    h->set_step_degrees(7.5);
  }
  if (!o.has_part_up()) o.mutable_part_up()->set_z(1);
  if (!o.has_cone_degrees()) o.set_cone_degrees(kDefaultCone);
  return o;
}

}  // namespace gvm::planner
