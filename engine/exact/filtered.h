// The one place where the filter/exact pattern lives: evaluate an expression with the
// certified floating-point filter, and only when its sign is uncertain, evaluate it again
// exactly. `expr` is a generic lambda taking a tag value of the number type to use.
#pragma once

#include "exact/approx.h"
#include "exact/dyadic.h"

namespace gvm::exact {

template <class Expr>
Sign filtered_sign(const Expr& expr) {
  if (auto s = expr(Approx{}).sign()) return *s;
  return expr(Dyadic{}).sign();
}

}  // namespace gvm::exact
