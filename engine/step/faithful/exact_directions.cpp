// Direction classes, their integer vectors and frames (exact_directions.h). The doubles
// here only choose vectors; every relation the vectors promise (orthogonality, a frame)
// is checked in integers.
#include "step/faithful/exact_directions.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>
#include <utility>

namespace gvm::faithful {
namespace {

using LD = long double;

constexpr double kMaxAngle = 1e-7;     // a class's vector is never farther from it
constexpr double kExactEnough = 1e-13; // a rational direction found: stop looking
constexpr int64_t kFreeBound = int64_t(1) << 16, kFreeLimit = int64_t(1) << 20;
constexpr double kFreeTarget = 9e-8;  // rad: a free direction searched beyond 2^16 only if not this close
constexpr LD kPlaneBound = LD(int64_t(1) << 20);

LD norm(const IVec& v) { return std::sqrt(LD(v.x) * v.x + LD(v.y) * v.y + LD(v.z) * v.z); }

// Extended Euclid: s a + t b = gcd(a, b) >= 0.
int64_t ext_gcd(int64_t a, int64_t b, int64_t& s, int64_t& t) {
  int64_t s0 = 1, s1 = 0, t0 = 0, t1 = 1;
  while (b != 0) {
    const int64_t q = a / b;
    std::tie(a, b) = std::pair{b, a - q * b};
    std::tie(s0, s1) = std::pair{s1, s0 - q * s1};
    std::tie(t0, t1) = std::pair{t1, t0 - q * t1};
  }
  if (a < 0) a = -a, s0 = -s0, t0 = -t0;
  s = s0, t = t0;
  return a;
}

// Lagrange-Gauss reduction of a basis of a two-dimensional lattice.
std::array<IVec, 2> reduce(IVec b1, IVec b2) {
  for (int guard = 0; guard < 200; ++guard) {
    if (dot(b2, b2) < dot(b1, b1)) std::swap(b1, b2);
    const i128 mu = round_div(dot(b1, b2), dot(b1, b1));
    if (mu == 0) break;
    b2 = b2 - int64_t(mu) * b1;
  }
  if (dot(b2, b2) < dot(b1, b1)) std::swap(b1, b2);
  return {b1, b2};
}

struct PoolEntry {
  IVec v;
  double angle;  // how far it may be from the B-rep direction it stands for
};

double abs_cos(const IVec& v, const Dir3& d) {
  const LD n = norm(v);
  return double(std::fabs((LD(v.x) * d[0] + LD(v.y) * d[1] + LD(v.z) * d[2]) / n));
}

IVec snap_class(const Dir3& d, const std::vector<PoolEntry>& pool) {
  std::vector<const PoolEntry*> orthogonal;
  for (const PoolEntry& p : pool)
    if (abs_cos(p.v, d) <= kOrthogonal + p.angle) orthogonal.push_back(&p);
  for (size_t i = 0; i < orthogonal.size(); ++i)
    for (size_t j = i + 1; j < orthogonal.size(); ++j) {
      if (dot(orthogonal[i]->v, orthogonal[j]->v) != 0) continue;
      const IVec v = canonical(cross(orthogonal[i]->v, orthogonal[j]->v));
      if (line_angle(v, d) <= kMaxAngle) return v;
    }
  for (const PoolEntry* p : orthogonal) {
    const IVec v = snap_orthogonal(d, p->v);
    if (line_angle(v, d) <= kMaxAngle) return v;
  }
  return snap_free(d);
}

bool has_axis(const Frame& f, const IVec& v) { return std::find(f.axis.begin(), f.axis.end(), v) != f.axis.end(); }

// The frame of class vector v: with two classes orthogonal to it and to each other, or one,
// or completed by the shortest integer vector orthogonal to it.
Frame frame_of(const IVec& v, const std::vector<IVec>& known) {
  std::vector<IVec> orthogonal;
  for (const IVec& a : known)
    if (dot(a, v) == 0) orthogonal.push_back(a);
  for (size_t i = 0; i < orthogonal.size(); ++i)
    for (size_t j = i + 1; j < orthogonal.size(); ++j)
      if (dot(orthogonal[i], orthogonal[j]) == 0) return {{v, orthogonal[i], orthogonal[j]}, {}};
  const IVec a = !orthogonal.empty() ? orthogonal.front() : canonical(orthogonal_lattice(v)[0]);
  return {{v, a, canonical(cross(v, a))}, {}};
}

}  // namespace

double line_angle(const IVec& v, const Dir3& d) {
  const LD x = LD(v.y) * d[2] - LD(v.z) * d[1], y = LD(v.z) * d[0] - LD(v.x) * d[2],
           z = LD(v.x) * d[1] - LD(v.y) * d[0];
  const LD along = std::fabs(LD(v.x) * d[0] + LD(v.y) * d[1] + LD(v.z) * d[2]);
  return double(std::atan2(std::sqrt(x * x + y * y + z * z), along));
}

std::array<IVec, 2> orthogonal_lattice(const IVec& a) {
  if (a.x == 0 && a.y == 0) return {IVec{1, 0, 0}, IVec{0, 1, 0}};
  int64_t s, t;
  const int64_t g12 = ext_gcd(a.x, a.y, s, t);
  // a . k1 = 0 and a . k2 = a.z (s a.x + t a.y - g12) = 0; with gcd(g12, a.z) = 1 they
  // span every integer vector orthogonal to a.
  const IVec k1{a.y / g12, -a.x / g12, 0};
  const IVec k2{s * a.z, t * a.z, -g12};
  return reduce(k1, k2);
}

IVec snap_free(const Dir3& d) {
  int dom = 0;
  for (int k = 1; k < 3; ++k)
    if (std::fabs(d[k]) > std::fabs(d[dom])) dom = k;
  const int a = (dom + 1) % 3, b = (dom + 2) % 3;
  const LD ra = LD(d[a]) / std::fabs(LD(d[dom])), rb = LD(d[b]) / std::fabs(LD(d[dom]));
  // The angle's square is about the components' squared misses over D^2: cheap to compare.
  int64_t best_d = 1;
  LD best_miss = 10;
  for (int64_t D = 1; D <= kFreeLimit; ++D) {
    const LD ma = LD(D) * ra - std::llround(LD(D) * ra), mb = LD(D) * rb - std::llround(LD(D) * rb);
    const LD miss = (ma * ma + mb * mb) / (LD(D) * LD(D));
    if (miss < best_miss) best_miss = miss, best_d = D;
    if (best_miss <= kExactEnough * kExactEnough) break;
    // Beyond 2^16 only while the best is not yet well within the bound.
    if (D >= kFreeBound && best_miss <= kFreeTarget * kFreeTarget) break;
  }
  int64_t c[3];
  c[dom] = d[dom] < 0 ? -best_d : best_d;
  c[a] = std::llround(LD(best_d) * LD(d[a]) / std::fabs(LD(d[dom])));
  c[b] = std::llround(LD(best_d) * LD(d[b]) / std::fabs(LD(d[dom])));
  return canonical({c[0], c[1], c[2]});
}

IVec snap_orthogonal(const Dir3& d, const IVec& a) {
  const auto [b1, b2] = orthogonal_lattice(a);
  // d ~ alpha b1 + beta b2, least squares in the plane of the lattice.
  const LD g11 = LD(dot(b1, b1)), g12 = LD(dot(b1, b2)), g22 = LD(dot(b2, b2));
  const LD r1 = b1.x * d[0] + b1.y * d[1] + LD(b1.z) * d[2], r2 = b2.x * d[0] + b2.y * d[1] + LD(b2.z) * d[2];
  const LD det = g11 * g22 - g12 * g12;
  const LD alpha = (r1 * g22 - r2 * g12) / det, beta = (r2 * g11 - r1 * g12) / det;
  // Continued fraction of the larger over the smaller coefficient: convergents p/q give
  // the integer pairs (q, p) that approximate the direction best for their size.
  const bool swap = std::fabs(beta) > std::fabs(alpha);
  const LD big = swap ? beta : alpha, small = swap ? alpha : beta;
  LD x = std::fabs(small / big);
  int64_t p0 = 0, q0 = 1, p1 = 1, q1 = 0;
  IVec best = big > 0 ? b1 : (-1) * b1;
  if (swap) best = big > 0 ? b2 : (-1) * b2;
  double best_angle = line_angle(best, d);
  for (int step = 0; step < 64 && best_angle > kExactEnough * 1e-2; ++step) {
    const LD whole = std::floor(x);
    if (whole > LD(int64_t(1) << 40)) break;
    const int64_t an = int64_t(whole);
    const int64_t p2 = an * p1 + p0, q2 = an * q1 + q0;
    p0 = p1, q0 = q1, p1 = p2, q1 = q2;
    // (q1, p1) scaled by the signs of (big, small), in the basis (b1, b2) as swapped.
    const int64_t cb = (big < 0 ? -q1 : q1), cs = (small < 0 ? -p1 : p1);
    const IVec v = swap ? cs * b1 + cb * b2 : cb * b1 + cs * b2;
    if (norm(v) > kPlaneBound) break;
    const double angle = line_angle(v, d);
    if (angle < best_angle) best = v, best_angle = angle;
    const LD frac = x - whole;
    if (frac <= 0) break;
    x = 1 / frac;
  }
  return canonical(best);
}

ExactDirections exact_directions(const std::vector<Dir3>& directions, const std::vector<uint32_t>& weights) {
  ExactDirections out;
  std::vector<std::vector<uint32_t>> members;
  for (uint32_t i = 0; i < directions.size(); ++i) {
    const Dir3& d = directions[i];
    uint32_t c = 0;
    for (; c < out.classes.size(); ++c) {
      const Dir3& b = out.classes[c].brep;
      const double x = b[1] * d[2] - b[2] * d[1], y = b[2] * d[0] - b[0] * d[2], z = b[0] * d[1] - b[1] * d[0];
      if (std::sqrt(x * x + y * y + z * z) <= kParallel) break;
    }
    if (c == out.classes.size()) {
      out.classes.push_back({d, {}, 0, 0});
      members.emplace_back();
    }
    out.classes[c].weight += weights[i];
    members[c].push_back(i);
    out.class_of.push_back(c);
  }
  std::vector<uint32_t> order(out.classes.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return out.classes[a].weight > out.classes[b].weight; });

  std::vector<PoolEntry> pool = {{{1, 0, 0}, 0}, {{0, 1, 0}, 0}, {{0, 0, 1}, 0}};
  for (uint32_t c : order) {
    DirectionClass& cls = out.classes[c];
    cls.exact = snap_class(cls.brep, pool);
    for (uint32_t m : members[c]) cls.angle = std::max(cls.angle, line_angle(cls.exact, directions[m]));
    pool.push_back({cls.exact, cls.angle});
  }

  std::vector<IVec> known = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (uint32_t c : order) known.push_back(out.classes[c].exact);
  out.frames.push_back({{IVec{1, 0, 0}, IVec{0, 1, 0}, IVec{0, 0, 1}}, {}});
  for (uint32_t c : order) {
    const IVec& v = out.classes[c].exact;
    if (std::any_of(out.frames.begin(), out.frames.end(), [&](const Frame& f) { return has_axis(f, v); })) continue;
    out.frames.push_back(frame_of(v, known));
  }
  for (Frame& f : out.frames)
    for (int k = 0; k < 3; ++k)
      f.real[k] = std::any_of(out.classes.begin(), out.classes.end(),
                              [&](const DirectionClass& c) { return c.exact == f.axis[k]; });
  return out;
}

}  // namespace gvm::faithful
