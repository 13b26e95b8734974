#include "gvm/direction.h"

#include "exact/exact_vec.h"

namespace gvm {
namespace {

Direction wrap(exact::ExactVec v) {
  return Direction(std::make_shared<const exact::ExactVec>(std::move(v)));
}

}  // namespace

Direction::Direction(double x, double y, double z)
    : v_(std::make_shared<const exact::ExactVec>(exact::ExactVec::from_point({x, y, z}))) {}

std::array<double, 3> Direction::unit() const { return v_->unit(); }

Direction Direction::operator-() const { return wrap(-*v_); }

bool operator==(const Direction& a, const Direction& b) {
  return exact::same_direction(*a.v_, *b.v_);
}

Sign sign_dot(const Direction& a, const Direction& b) { return exact::sign_dot(*a.v_, *b.v_); }

Direction cross(const Direction& a, const Direction& b) { return wrap(exact::cross(*a.v_, *b.v_)); }

bool parallel(const Direction& a, const Direction& b) { return exact::parallel(*a.v_, *b.v_); }

}  // namespace gvm
