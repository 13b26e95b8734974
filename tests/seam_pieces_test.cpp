// Where grazing arcs can hold a seam (visibility/seam_pieces.h): overlaps of arcs that
// occlude opposite sides of one circle, however their circle is written, and the points
// where arcs of three circles cross; nothing else.
#include <gtest/gtest.h>

#include "exact/exact_vec.h"
#include "sphere/spherical_image.h"
#include "visibility/seam_pieces.h"

namespace gvm {
namespace {

using exact::ExactVec;

ExactVec v(double x, double y, double z) { return ExactVec::from_point({x, y, z}); }

// The arc from a to b counter-clockwise around a x b.
GrazingArc grazing(const ExactVec& a, const ExactVec& b, int side) { return {{a, b, exact::cross(a, b), 0, 0}, side}; }

bool same_arc(const sphere::ArrangementArc& x, const ExactVec& from, const ExactVec& to) {
  return exact::same_direction(x.from, from) && exact::same_direction(x.to, to);
}

TEST(SeamPieces, OppositeSidesOverlapOnTheirCommonPart) {
  // Two arcs of the equator, (1, 0, 0) to (0, 1, 0) and (1, 1, 0) to (-1, 1, 0).
  const SeamPieces both = seam_pieces({grazing(v(1, 0, 0), v(0, 1, 0), 1), grazing(v(1, 1, 0), v(-1, 1, 0), -1)});
  ASSERT_EQ(both.arcs.size(), 1u);
  EXPECT_TRUE(same_arc(both.arcs[0], v(1, 1, 0), v(0, 1, 0)));
  EXPECT_TRUE(both.points.empty());
  // The same side on both: no seam can lie there.
  const SeamPieces one = seam_pieces({grazing(v(1, 0, 0), v(0, 1, 0), 1), grazing(v(1, 1, 0), v(-1, 1, 0), 1)});
  EXPECT_TRUE(one.arcs.empty());
  EXPECT_TRUE(one.points.empty());
  // An arc whose contacts may occlude either side overlaps itself.
  const SeamPieces either = seam_pieces({grazing(v(1, 0, 0), v(0, 1, 0), 0)});
  ASSERT_EQ(either.arcs.size(), 1u);
  EXPECT_TRUE(same_arc(either.arcs[0], v(1, 0, 0), v(0, 1, 0)));
}

TEST(SeamPieces, TheCircleIsFoundWhateverItsNormalsLength) {
  // The second arc is written backwards around a normal of another length: its side flips
  // with it, so the two still occlude opposite sides.
  GrazingArc a = grazing(v(1, 0, 0), v(0, 1, 0), 1);
  GrazingArc b{{v(-1, 3, 0), v(1, 1, 0), v(0, 0, -7), 0, 0}, 1};  // (1, 1, 0) -> (-1, 3, 0), side -1
  const SeamPieces p = seam_pieces({a, b});
  ASSERT_EQ(p.arcs.size(), 1u);
  EXPECT_TRUE(same_arc(p.arcs[0], v(1, 1, 0), v(0, 1, 0)));
}

TEST(SeamPieces, ArcsMeetingOnlyAtAPointGiveThePoint) {
  const SeamPieces p = seam_pieces({grazing(v(1, 0, 0), v(1, 1, 0), 1), grazing(v(1, 1, 0), v(0, 1, 0), -1)});
  EXPECT_TRUE(p.arcs.empty());
  ASSERT_EQ(p.points.size(), 1u);
  EXPECT_TRUE(exact::same_direction(p.points[0], v(1, 1, 0)));
}

TEST(SeamPieces, ThreeCirclesCrossingGiveTheirPointTwoDoNot) {
  // Arcs through +z on the circles of normals x, y and (1, -1, 0), each strictly inside.
  const GrazingArc ax = grazing(v(0, -1, 1), v(0, 1, 1), 1);
  const GrazingArc ay = grazing(v(1, 0, 1), v(-1, 0, 1), 1);
  const GrazingArc ad = grazing(v(-1, -1, 1), v(1, 1, 1), -1);
  const SeamPieces three = seam_pieces({ax, ay, ad});
  EXPECT_TRUE(three.arcs.empty());
  ASSERT_FALSE(three.points.empty());
  for (const ExactVec& p : three.points) EXPECT_TRUE(exact::same_direction(p, v(0, 0, 1)));
  const SeamPieces two = seam_pieces({ax, ay});
  EXPECT_TRUE(two.points.empty());
  EXPECT_TRUE(two.arcs.empty());
  // The third arc ending at +z does not pass through it.
  const SeamPieces ending = seam_pieces({ax, ay, grazing(v(-1, -1, 1), v(0, 0, 1), -1)});
  EXPECT_TRUE(ending.points.empty());
}

}  // namespace
}  // namespace gvm
