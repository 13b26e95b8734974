// Floating-point value with a certified absolute error bound: the filter stage of every
// predicate. Each operation adds the rounding error it may commit (half an ulp of the
// result, plus the smallest normal to cover underflow), so |exact - v| <= e holds for any
// expression evaluated from exact inputs. The sign is certain when |v| > e (with a small
// safety factor for the rounding of e itself); otherwise the caller evaluates exactly.
#pragma once

#include <cfloat>
#include <cmath>
#include <optional>

#include "gvm/geometry.h"

namespace gvm::exact {

class Approx {
 public:
  constexpr Approx() = default;
  constexpr Approx(double v) : v_(v), e_(0) {}  // NOLINT: exact input
  constexpr Approx(double v, double e) : v_(v), e_(e) {}

  double value() const { return v_; }
  double error() const { return e_; }

  friend Approx operator+(const Approx& a, const Approx& b) {
    double v = a.v_ + b.v_;
    return {v, a.e_ + b.e_ + std::fabs(v) * kU + kEta};
  }
  friend Approx operator-(const Approx& a, const Approx& b) {
    double v = a.v_ - b.v_;
    return {v, a.e_ + b.e_ + std::fabs(v) * kU + kEta};
  }
  friend Approx operator-(const Approx& a) { return {-a.v_, a.e_}; }
  friend Approx operator*(const Approx& a, const Approx& b) {
    double v = a.v_ * b.v_;
    double e = std::fabs(a.v_) * b.e_ + std::fabs(b.v_) * a.e_ + a.e_ * b.e_;
    return {v, e + std::fabs(v) * kU + kEta};
  }

  // The certified sign, or nothing when the filter cannot decide.
  std::optional<Sign> sign() const {
    // 2^-40 covers the rounding committed while accumulating e itself (a few ulps per
    // operation for expressions of a few hundred operations).
    double bound = e_ * (1.0 + 0x1p-40) + kEta;
    if (!(std::isfinite(v_) && std::isfinite(bound))) return std::nullopt;
    if (v_ > bound) return Sign::kPositive;
    if (v_ < -bound) return Sign::kNegative;
    return std::nullopt;
  }

 private:
  static constexpr double kU = 0x1p-53;       // unit roundoff
  static constexpr double kEta = DBL_MIN;     // absolute error of an underflowed result
  double v_ = 0;
  double e_ = 0;
};

}  // namespace gvm::exact
