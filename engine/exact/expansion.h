// Exact sums and products of doubles as floating-point expansions (Shewchuk, "Adaptive
// precision floating-point arithmetic and fast robust geometric predicates", 1997): a
// value is held as doubles of increasing magnitude that do not overlap, built by
// error-free transformations, so its sign is the sign of its largest component. This is
// the exact stage of the determinants of input differences: CAD input makes many of them
// exactly zero, and GMP's allocations made each such sign cost about 15,000 instructions.
//
// Exact as long as nothing overflows and no product underflows; predicates.cpp keeps its
// input in a range where neither can happen and leaves the rest to GMP.
#pragma once

#include <array>
#include <cstddef>

#include "gvm/geometry.h"

namespace gvm::exact {

// a + b = hi + lo exactly, hi the rounded sum (Knuth's two-sum, any order of magnitudes).
struct TwoDoubles {
  double hi, lo;
};

inline TwoDoubles two_sum(double a, double b) {
  const double s = a + b;
  const double b_virtual = s - a;
  const double a_virtual = s - b_virtual;
  return {s, (a - a_virtual) + (b - b_virtual)};
}

// a = hi + lo with both halves of at most 26 significant bits (Dekker), so that products
// of halves are exact.
inline TwoDoubles split(double a) {
  constexpr double kSplitter = 134217729.0;  // 2^27 + 1
  const double c = kSplitter * a;
  const double hi = c - (c - a);
  return {hi, a - hi};
}

// a * b = hi + lo exactly (Dekker's product: no fused multiply-add needed, and the build's
// -ffp-contract=off keeps the compiler from fusing these roundings).
inline TwoDoubles two_product(double a, double b) {
  const double p = a * b;
  const auto [ah, al] = split(a);
  const auto [bh, bl] = split(b);
  const double err = ((p - ah * bh) - al * bh) - ah * bl;
  return {p, al * bl - err};
}

// At most N components; every operation below adds at most one component per double it
// takes in, which the capacities of the results account for.
template <size_t N>
class Expansion {
 public:
  Expansion() = default;
  explicit Expansion(double a) { add(a); }

  // Shewchuk's Grow-Expansion with zero elimination, in place: component i is read before
  // slot k <= i is written.
  void add(double b) {
    double q = b;
    size_t k = 0;
    for (size_t i = 0; i < n_; ++i) {
      const auto [s, lo] = two_sum(q, c_[i]);
      q = s;
      if (lo != 0) c_[k++] = lo;
    }
    if (q != 0 || k == 0) c_[k++] = q;
    n_ = k;
  }
  template <size_t M>
  void add(const Expansion<M>& f, double sign = 1) {
    for (size_t i = 0; i < f.size(); ++i) add(sign * f[i]);
  }

  size_t size() const { return n_; }
  double operator[](size_t i) const { return c_[i]; }
  Sign sign() const {
    const double top = n_ == 0 ? 0 : c_[n_ - 1];
    return top > 0 ? Sign::kPositive : top < 0 ? Sign::kNegative : Sign::kZero;
  }

 private:
  std::array<double, N> c_{};
  size_t n_ = 0;
};

template <size_t N, size_t M>
Expansion<2 * N * M> operator*(const Expansion<N>& e, const Expansion<M>& f) {
  Expansion<2 * N * M> out;
  for (size_t j = 0; j < f.size(); ++j) {
    for (size_t i = 0; i < e.size(); ++i) {
      const auto [p, lo] = two_product(e[i], f[j]);
      out.add(lo);
      out.add(p);
    }
  }
  return out;
}

// a - b exactly, as an expansion of at most two components.
inline Expansion<2> difference(double a, double b) {
  const auto [hi, lo] = two_sum(a, -b);
  Expansion<2> out(lo);
  out.add(hi);
  return out;
}

}  // namespace gvm::exact
