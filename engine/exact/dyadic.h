// Exact dyadic rational m * 2^k with an arbitrary-precision integer mantissa (GMP).
// Every double is dyadic and the predicates only use +, - and *, so this ring is closed
// under everything the exact stage needs and never rounds, whatever the exponent range
// of the input (1e-300 and 1e300 in one mesh included).
#pragma once

#include <gmpxx.h>

#include <cstdint>
#include <utility>

#include "gvm/geometry.h"

namespace gvm::exact {

class Dyadic {
 public:
  Dyadic() = default;
  explicit Dyadic(double d);

  friend Dyadic operator+(const Dyadic& a, const Dyadic& b);
  friend Dyadic operator-(const Dyadic& a, const Dyadic& b);
  friend Dyadic operator*(const Dyadic& a, const Dyadic& b);
  friend Dyadic operator-(const Dyadic& a);

  Sign sign() const { return static_cast<Sign>(sgn(m_)); }
  bool is_zero() const { return sgn(m_) == 0; }
  double to_double() const;
  // The value as f * 2^e with 0.5 <= |f| < 1 (f truncated to a double; 0 and e = 0 for
  // zero): for magnitudes beyond the double range.
  double frexp(int64_t& e) const;

 private:
  Dyadic(mpz_class m, int64_t k) : m_(std::move(m)), k_(k) {}
  mpz_class m_;     // mantissa
  int64_t k_ = 0;   // binary exponent
};

}  // namespace gvm::exact
