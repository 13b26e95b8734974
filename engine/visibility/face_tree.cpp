#include "visibility/face_tree.h"

namespace gvm {

FaceTree::FaceTree(std::span<const FaceEstimate> faces, std::span<const uint32_t> subset) : faces_(faces) {
  std::vector<sphere::Box> boxes;
  boxes.reserve(subset.size());
  index_.reserve(subset.size());
  sides_.reserve(subset.size());
  for (uint32_t i : subset) {
    const FaceEstimate& f = faces[i];
    if (!f.certain) continue;
    Sides s;
    s.area = f.area;
    if (f.inward.size() <= Sides::kMax) {
      s.count = static_cast<uint32_t>(f.inward.size());
      for (size_t j = 0; j < s.count; ++j) s.inward[j] = f.inward[j], s.limit[j] = kSlack + f.error[j];
    }
    index_.push_back(i);
    sides_.push_back(s);
    boxes.push_back(f.box);
  }
  tree_.emplace(boxes);
}

namespace {

sphere::Box point_box(const sphere::D3& x) {
  return {{x[0] - kSlack, x[1] - kSlack, x[2] - kSlack}, {x[0] + kSlack, x[1] + kSlack, x[2] + kSlack}};
}

}  // namespace

bool FaceTree::face_holds(uint32_t k, const sphere::D3& x) const {
  const Sides& s = sides_[k];
  if (s.count == 0) return strictly_inside(faces_[index_[k]], x);
  for (size_t j = 0; j < s.count; ++j) {
    if (!(sphere::dot(s.inward[j], x) > s.limit[j])) return false;
  }
  return true;
}

bool FaceTree::holds(const sphere::D3& x) const {
  return tree_->visit_overlapping(point_box(x), [&](uint32_t k) { return face_holds(k, x); });
}

int64_t FaceTree::largest_holding(const sphere::D3& x, size_t& tested) const {
  int64_t best = -1;
  double area = -1;
  tree_->visit_overlapping(point_box(x), [&](uint32_t k) {
    ++tested;
    if (sides_[k].area > area && face_holds(k, x)) best = index_[k], area = sides_[k].area;
    return false;
  });
  return best;
}

}  // namespace gvm
