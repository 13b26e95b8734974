// An exact direction on the unit sphere: the direction of a non-zero vector whose
// coordinates are exact (the doubles given, or exact constructions from them). Never
// normalized, so nothing is rounded until a caller asks for a unit vector in doubles.
#pragma once

#include <array>
#include <memory>

#include "gvm/geometry.h"

namespace gvm {

namespace exact {
class ExactVec;
}

class Direction {
 public:
  Direction() = default;  // no direction: only to be assigned to
  // The direction of the vector (x, y, z), the doubles taken exactly; not all zero.
  Direction(double x, double y, double z);

  bool valid() const { return v_ != nullptr; }
  // The unit vector, rounded to doubles (output and searches, never decisions).
  std::array<double, 3> unit() const;
  Direction operator-() const;

  // The same direction, exactly (positive multiples are equal).
  friend bool operator==(const Direction& a, const Direction& b);
  // Sign of a . b, exactly.
  friend Sign sign_dot(const Direction& a, const Direction& b);
  // The direction of a x b, exactly; a and b must not be parallel.
  friend Direction cross(const Direction& a, const Direction& b);
  // a and b are parallel or antiparallel, exactly.
  friend bool parallel(const Direction& a, const Direction& b);

  // The engine's exact vector (engine internals only).
  const exact::ExactVec& exact() const { return *v_; }
  explicit Direction(std::shared_ptr<const exact::ExactVec> v) : v_(std::move(v)) {}

 private:
  std::shared_ptr<const exact::ExactVec> v_;
};

}  // namespace gvm
