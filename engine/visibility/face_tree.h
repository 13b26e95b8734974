// Which of many projected faces certainly hold a direction: a box tree over their
// estimates (face_estimate.h), their sides side by side.
//
// The occlusion culling asks this of a few hundred faces per direction (on a pocket
// floor), and the estimates' own vectors, scattered over the heap, cost a cache miss each:
// the sides of faces with up to four (every envelope face) are copied into one block.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "sphere/box_tree.h"
#include "visibility/face_estimate.h"

namespace gvm {

class FaceTree {
 public:
  // Over the certain faces of faces[subset] (faces must outlive the tree).
  FaceTree(std::span<const FaceEstimate> faces, std::span<const uint32_t> subset);

  bool empty() const { return index_.empty(); }

  // Whether some face of the subset strictly holds x (strictly_inside).
  bool holds(const sphere::D3& x) const;
  // The largest face of the subset (by FaceEstimate::area; an index into `faces`) that
  // strictly holds x, or -1; adds the number of faces whose boxes it tested to `tested`.
  int64_t largest_holding(const sphere::D3& x, size_t& tested) const;

 private:
  struct Sides {
    static constexpr size_t kMax = 4;
    double area = 0;
    std::array<sphere::D3, kMax> inward;
    std::array<double, kMax> limit;  // kSlack + error
    uint32_t count = 0;              // 0: more than kMax sides (use the estimate)
  };

  bool face_holds(uint32_t k, const sphere::D3& x) const;

  std::span<const FaceEstimate> faces_;
  std::vector<uint32_t> index_;  // into faces_, of each box
  std::vector<Sides> sides_;     // of each box's face
  std::optional<sphere::BoxTree> tree_;
};

}  // namespace gvm
