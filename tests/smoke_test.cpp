#include <gtest/gtest.h>

#include "exact/predicates.h"

TEST(Smoke, Orient3dOfAxisTetrahedron) {
  using gvm::Point3;
  EXPECT_EQ(gvm::exact::orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}), gvm::Sign::kPositive);
}
