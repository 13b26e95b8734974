// The directions that matter for a GVM, as half-spaces for pruning the envelope.
//
// GVM(S) = L - Int(Phi(O + (-S))) with L = LVM(S + N_S). A face of the envelope whose
// projection lies at a positive distance from L changes the coverage nowhere near L, so
// leaving it out (and taking the border of the faces that remain) gives the same GVM.
// The window holds, for every cell of L, great-circle half-spaces {x : m . x >= 0} that
// contain the cell; a face whose vertex directions q - p all lie strictly outside one
// half-space of every cell is such a face. Decided in double precision with a certified
// slack, so that a face is left out only when that is certain. A face with one direction
// in a cell's inscribed cap meets the cell without a look at its sides.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <vector>

#include "gvm/geometry.h"
#include "gvm/mesh.h"
#include "sphere/spherical_image.h"

namespace gvm {

class DirectionWindow {
 public:
  // coordinate_bound: at least the largest absolute coordinate of any point used below.
  DirectionWindow(const sphere::SphericalImage& lvm, double coordinate_bound);
  // A window around a closed set whose 2-cells need not be convex (what is left of the
  // LVM outside some occluded directions): each 2-cell is covered by four half-spaces
  // around a cap that holds it, and by the half-spaces of `within` (a convex 2-cell that
  // holds the set, or empty). None when a 2-cell lies in no cap smaller than a
  // hemisphere, or is bounded by a full circle.
  static std::optional<DirectionWindow> covering(const sphere::SphericalImage& set, const sphere::Face& within,
                                                 double coordinate_bound);

  // Number of half-spaces (0: the window holds every direction).
  size_t half_spaces() const { return normals_.size(); }
  // Values per row (0 when the window holds every direction): m_k . x for every
  // half-space k, then the coordinates of one point x of the row's element, its anchor.
  size_t row_size() const { return normals_.empty() ? 0 : normals_.size() + 3; }
  // The row of the point x.
  void values(const Point3& x, double* out) const;
  // Folds the row of another point of the same element into `row`: the largest (or
  // smallest) m_k . x; the anchor stays.
  void fold(double* row, const double* values, bool largest) const;
  // False only if the directions q - p of a face certainly miss L: q_max[k] is the
  // largest m_k . q over the face's vertices q of O, p_min[k] the smallest m_k . p over
  // its vertices p of S (the face's vertices are all pairs (q, p)).
  bool may_meet(const double* q_max, const double* p_min) const;
  // The row of a triangle, edge or point of the mesh: the largest (or smallest) values
  // over its vertices, anchored at the first.
  void row(const SolidMesh& mesh, std::initializer_list<uint32_t> vertices, bool largest, double* out) const;
  // The rows of triangles, one after another: the q_max or p_min of may_meet for their
  // pairs.
  std::vector<double> extremes(const SolidMesh& mesh, std::span<const uint32_t> triangles,
                               bool largest) const;

 private:
  explicit DirectionWindow(double coordinate_bound);
  // The hemispheres of a convex 2-cell's arcs, whose intersection it is.
  void add_half_spaces(const sphere::Face& convex);
  // The cells of the set's arcs and points.
  void add_lower_dimensional(const sphere::SphericalImage& set);
  // A cell of four half-spaces holding the cap of directions within `radius` (< 90
  // degrees) of the unit vector `centre`.
  void add_cap(const std::array<double, 3>& centre, double radius, const sphere::Face& within);

  static double value(const std::array<double, 3>& m, const Point3& x);
  // Ends a cell: the half-spaces added since the last cell, and their inscribed cap.
  void end_cell();

  // A cap inside a cell: a pair whose anchors' difference lies in it certainly meets the
  // cell, which a pocket floor's 420-sided LVM otherwise shows only by reading every side.
  struct InnerCap {
    std::array<double, 3> centre{0, 0, 0};
    double cos2_radius = 4;  // 4: no cap ((c . x)^2 > 4 |x|^2 never holds)
    // x in the cap, with |x|^2 = norm2_x: no square root for the pairs that miss.
    bool holds(const std::array<double, 3>& x, double norm2_x) const;
  };
  static InnerCap inscribed_cap(std::span<const std::array<double, 3>> normals);

  std::vector<std::array<double, 3>> normals_;
  std::vector<size_t> cell_end_;  // half-spaces of cell c: [cell_end_[c - 1], cell_end_[c])
  std::vector<InnerCap> inner_;   // of each cell
  double slack_ = 0;
};

// The window's values for one side of may_meet, row after row (each row row_size()
// values: the largest over a triangle, edge or point of O, or the smallest over one of S),
// with the extremes over each run of kRun rows, anchored at the run's first anchor. A row
// of the other side that certainly misses a run's extremes misses every row of the run, so
// the run's pairs are left out by one test: the 103k-triangle pocket part spent a quarter
// of its time testing pairs one by one.
class WindowRows {
 public:
  enum class Side { occluder, surface };  // rows of q_max (of O) or of p_min (of S)
  static constexpr size_t kRun = 32;

  // count rows in `rows` (count * window->row_size() values). window may be null or hold
  // every direction: every pair then may meet.
  WindowRows(const DirectionWindow* window, size_t count, std::vector<double> rows, Side side);

  size_t size() const { return count_; }
  const double* row(size_t i) const { return &rows_[i * k_]; }
  // The runs' extremes, run after run (none when every pair may meet).
  size_t runs() const { return k_ == 0 ? 0 : runs_.size() / k_; }
  const double* run(size_t r) const { return &runs_[r * k_]; }

  // Calls visit(i), in increasing order, for each row i whose pair with `other` (a row of
  // the other side) may meet the window, until visit returns false. Returns false if
  // stopped.
  template <class Visit>
  bool for_each_meeting(const double* other, const Visit& visit) const {
    for (size_t r = 0, begin = 0; begin < count_; ++r, begin += kRun) {
      if (k_ > 0 && !meets(&runs_[r * k_], other)) continue;
      for (size_t i = begin; i < std::min(count_, begin + kRun); ++i) {
        if ((k_ == 0 || meets(row(i), other)) && !visit(i)) return false;
      }
    }
    return true;
  }

 private:
  bool meets(const double* mine, const double* other) const {
    return side_ == Side::occluder ? window_->may_meet(mine, other) : window_->may_meet(other, mine);
  }

  const DirectionWindow* window_;
  size_t k_, count_;
  Side side_;
  std::vector<double> rows_, runs_;
};

// The largest absolute coordinate of the vertices of two sets of triangles: the
// coordinate bound of a window used with their points.
double coordinate_bound(const SolidMesh& mesh, std::span<const uint32_t> a,
                        std::span<const uint32_t> b);

}  // namespace gvm
