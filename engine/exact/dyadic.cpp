#include "exact/dyadic.h"

#include <cmath>

#include "exact/block_cache.h"

namespace gvm::exact {
namespace {

// Before any exact evaluation: every GMP number of the engine is made and freed by Dyadic.
const bool kGmpUsesBlockCache = (use_block_cache_for_gmp(), true);

}  // namespace

Dyadic::Dyadic(double d) {
  if (d == 0) return;
  int exp = 0;
  double frac = std::frexp(d, &exp);  // d = frac * 2^exp, 0.5 <= |frac| < 1
  // 53 bits of mantissa become an exact integer.
  auto mant = static_cast<int64_t>(std::ldexp(frac, 53));
  m_ = mpz_class(static_cast<long>(mant));
  k_ = static_cast<int64_t>(exp) - 53;
}

// The sum or difference written straight into out_m: the operand with the larger exponent
// shifted left there, then the other added in place (one allocation, not three).
static void align_add(const mpz_class& am, int64_t ak, const mpz_class& bm, int64_t bk,
                      bool subtract, mpz_class& out_m, int64_t& out_k) {
  mpz_ptr out = out_m.get_mpz_t();
  if (ak <= bk) {
    mpz_mul_2exp(out, bm.get_mpz_t(), static_cast<mp_bitcnt_t>(bk - ak));
    if (subtract) {
      mpz_sub(out, am.get_mpz_t(), out);
    } else {
      mpz_add(out, am.get_mpz_t(), out);
    }
    out_k = ak;
  } else {
    mpz_mul_2exp(out, am.get_mpz_t(), static_cast<mp_bitcnt_t>(ak - bk));
    if (subtract) {
      mpz_sub(out, out, bm.get_mpz_t());
    } else {
      mpz_add(out, out, bm.get_mpz_t());
    }
    out_k = bk;
  }
}

Dyadic operator+(const Dyadic& a, const Dyadic& b) {
  if (a.is_zero()) return b;
  if (b.is_zero()) return a;
  Dyadic r;
  align_add(a.m_, a.k_, b.m_, b.k_, false, r.m_, r.k_);
  return r;
}

Dyadic operator-(const Dyadic& a, const Dyadic& b) {
  if (b.is_zero()) return a;
  if (a.is_zero()) return -b;
  Dyadic r;
  align_add(a.m_, a.k_, b.m_, b.k_, true, r.m_, r.k_);
  return r;
}

Dyadic operator*(const Dyadic& a, const Dyadic& b) {
  if (a.is_zero() || b.is_zero()) return {};
  return {a.m_ * b.m_, a.k_ + b.k_};
}

Dyadic operator-(const Dyadic& a) { return {-a.m_, a.k_}; }

double Dyadic::to_double() const {
  if (is_zero()) return 0;
  long exp = 0;
  double d = mpz_get_d_2exp(&exp, m_.get_mpz_t());
  return std::ldexp(d, static_cast<int>(exp + k_));
}

double Dyadic::frexp(int64_t& e) const {
  e = 0;
  if (is_zero()) return 0;
  long exp = 0;
  const double f = mpz_get_d_2exp(&exp, m_.get_mpz_t());
  e = static_cast<int64_t>(exp) + k_;
  return f;
}

}  // namespace gvm::exact
