// CMM with an indexing probe head: a setup is one orientation (A, B) of the head's grid;
// an orientation serves a feature when the cone of the conical tolerance around its
// direction lies in the feature's GVM. Features whose GVM is an arc or a point (through
// holes, slots) are served only by an orientation exactly on it, and flagged.
#include <cmath>
#include <cstdio>
#include <set>

#include "mode.h"
#include "placement.h"

namespace gvm::planner {
namespace {

using Vec = std::array<double, 3>;

// cos and sin of a whole number of quarter turns are exact; other angles are rounded.
std::array<double, 2> cos_sin_degrees(double degrees) {
  const double quarters = degrees / 90;
  if (quarters == std::floor(quarters)) {
    static constexpr double kCos[4] = {1, 0, -1, 0}, kSin[4] = {0, 1, 0, -1};
    const int q = static_cast<int>(((static_cast<long long>(quarters) % 4) + 4) % 4);
    return {kCos[q], kSin[q]};
  }
  const double r = degrees * (M_PI / 180);
  return {std::cos(r), std::sin(r)};
}

// The rotation taking the machine's +z to the part axis `up` (Rodrigues about z x up;
// a half turn about x when up is -z). Exact for the coordinate axes.
struct PartFrame {
  explicit PartFrame(const v1::Vec3& up_vector) {
    const double n = std::sqrt(up_vector.x() * up_vector.x() + up_vector.y() * up_vector.y() +
                               up_vector.z() * up_vector.z());
    up = {up_vector.x() / n, up_vector.y() / n, up_vector.z() / n};
  }
  Vec operator()(const Vec& v) const {
    const Vec k0 = {-up[1], up[0], 0};  // z x up
    const double s = std::sqrt(k0[0] * k0[0] + k0[1] * k0[1]), c = up[2];
    if (s == 0) return c > 0 ? v : Vec{v[0], -v[1], -v[2]};
    const Vec k = {k0[0] / s, k0[1] / s, 0};
    const Vec kxv = {k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0]};
    const double kv = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
    Vec out;
    for (int i = 0; i < 3; ++i) out[i] = v[i] * c + kxv[i] * s + k[i] * kv * (1 - c);
    return out;
  }
  Vec up;
};

struct Orientation {
  double a, b;
  Direction direction;
};

// Every orientation of the grid, one per distinct direction (A = 0 for every B is one;
// B = -180 and 180 are one), in grid order.
std::vector<Orientation> head_grid(const v1::ProbeHead& head, const PartFrame& frame) {
  std::vector<Orientation> out;
  std::set<Vec> seen;
  const double step = head.step_degrees();
  for (int i = 0;; ++i) {
    const double a = head.a_min_degrees() + i * step;
    if (a > head.a_max_degrees()) break;
    for (int j = 0;; ++j) {
      const double b = head.b_min_degrees() + j * step;
      if (b > head.b_max_degrees()) break;
      const auto [ca, sa] = cos_sin_degrees(a);
      const auto [cb, sb] = cos_sin_degrees(b);
      const Vec u = frame({sa * cb, sa * sb, ca});
      if (!seen.insert(u).second) continue;
      out.push_back({a, b, Direction(u[0], u[1], u[2])});
    }
  }
  return out;
}

std::string fixed(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", x);
  return buf;
}

class ProbeMode final : public Mode {
 public:
  explicit ProbeMode(const v1::PlanOptions& o)
      : grid_(head_grid(o.head(), PartFrame(o.part_up()))),
        cone_(o.cone_degrees()),
        sin2_(sin2_at_least(o.cone_degrees())) {}

  CandidateSet candidates(std::span<const Target> targets) const override {
    return on_grid(targets, [&](uint32_t t, const Direction& d) { return serves(targets[t], d); });
  }

  std::optional<CandidateSet> candidates_within(std::span<const Target> targets,
                                                const Tolerance& tolerance) const override {
    return on_grid(targets, [&](uint32_t t, const Direction& d) { return serves_within(targets[t], d, tolerance); });
  }

  PlacedSetup place(const Candidate& chosen, std::span<const Target> targets,
                    std::span<const uint32_t> assigned) const override {
    return place_fixed(chosen, targets, assigned, {});
  }

  PlacedSetup place_fixed(const Candidate& chosen, std::span<const Target> targets,
                          std::span<const uint32_t> assigned, std::span<const uint32_t> loose) const override {
    PlacedSetup p = Mode::place_fixed(chosen, targets, assigned, loose);
    p.head_a_degrees = grid_[chosen.source].a;
    p.head_b_degrees = grid_[chosen.source].b;
    return p;
  }

  Unserved unserved(const Target& target) const override {
    Unserved u;
    u.reason = v1::UNREACHABLE_REASON_NO_HEAD_ORIENTATION;
    double best = -1e300;
    for (const Orientation& o : grid_) {
      const double c = target.reach.approx_signed_clearance(o.direction.unit()) * (180 / M_PI);
      if (c > best) {
        best = c;
        u.nearest_head_a_degrees = o.a;
        u.nearest_head_b_degrees = o.b;
      }
    }
    u.nearest_clearance_degrees = best;
    u.detail = "no head orientation has its " + fixed(cone_) + " degree cone inside the GVM; the nearest, A " +
               fixed(u.nearest_head_a_degrees) + " B " + fixed(u.nearest_head_b_degrees) + ", " +
               (best >= 0 ? "has " + fixed(best) + " degrees of clearance"
                          : "is " + fixed(-best) + " degrees outside it");
    return u;
  }

  bool serves(const Target& t, const Direction& d) const override {
    return t.reach.dimension() == 2 ? t.reach.contains_cap(d, sin2_) : t.reach.contains(d);
  }

  // The tolerance comes off the cone: every direction of the cone is then within epsilon
  // of the GVM.
  bool serves_within(const Target& t, const Direction& d, const Tolerance& tolerance) const override {
    if (t.reach.dimension() < 2) return t.reach.within(d, tolerance.near_sin2);
    const double cone = cone_ - tolerance.radians * (180 / M_PI);
    return t.reach.contains_cap(d, cone > 0 ? sin2_at_least(cone) : 0);
  }

 private:
  CandidateSet on_grid(std::span<const Target> targets,
                       const std::function<bool(uint32_t, const Direction&)>& serves_target) const {
    std::vector<Direction> directions;
    for (const Orientation& o : grid_) directions.push_back(o.direction);
    CandidateSet out;
    out.candidates = evaluate(directions, targets.size(), serves_target);
    out.evaluated = static_cast<uint32_t>(directions.size());
    out.description = "the " + std::to_string(grid_.size()) + " distinct orientations of the head grid";
    return out;
  }

  std::vector<Orientation> grid_;
  double cone_, sin2_;
};

}  // namespace

std::unique_ptr<Mode> make_probe_mode(const v1::PlanOptions& options) {
  return std::make_unique<ProbeMode>(options);
}

}  // namespace gvm::planner
