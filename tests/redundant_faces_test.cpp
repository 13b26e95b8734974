// Envelope faces left out as lying inside larger ones, against brute-force membership.
#include "visibility/redundant_faces.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "support/spherical_polygons.h"

namespace gvm {
namespace {

using namespace sphere::test_polygons;

bool inside_closed(const Polygon& p, const ExactVec& u) {
  for (size_t i = 0; i < p.size(); ++i) {
    if (exact::sign_det(p[i], p[(i + 1) % p.size()], u) == Sign::kNegative) return false;
  }
  return true;
}

TEST(RedundantFaces, EveryFaceLeftOutLiesInTheKeptOnes) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> centre(-6, 6);
  std::vector<Polygon> faces;
  for (int i = 0; i < 40; ++i) faces.push_back(triangle_around(rng, centre(rng), centre(rng), 9));
  for (int i = 0; i < 400; ++i) faces.push_back(triangle_around(rng, centre(rng), centre(rng), 0.3));
  const std::vector<uint8_t> left_out = redundant_faces(faces);
  ASSERT_EQ(left_out.size(), faces.size());
  int count = 0;
  std::uniform_real_distribution<double> weight(0, 1);
  for (size_t i = 0; i < faces.size(); ++i) {
    if (!left_out[i]) continue;
    ++count;
    // The vertices and points inside the face: each in some kept face.
    std::vector<ExactVec> probes(faces[i].begin(), faces[i].end());
    for (int k = 0; k < 20; ++k) {
      D3 sum = {0, 0, 0};
      for (const ExactVec& corner : faces[i]) sum = axpy(0.05 + weight(rng), corner.unit(), sum);
      probes.push_back(v(sum));
    }
    for (const ExactVec& p : probes) {
      bool covered = false;
      for (size_t j = 0; j < faces.size() && !covered; ++j) covered = !left_out[j] && inside_closed(faces[j], p);
      ASSERT_TRUE(covered) << "face " << i << " left out, yet not inside the kept faces";
    }
  }
  // Most small triangles lie well inside a large one.
  EXPECT_GT(count, 200);
}

TEST(RedundantFaces, FacesOfEqualSizeAreNotLeftOutForEachOther) {
  // Two identical faces: each lies inside the other, one must stay.
  const Polygon p = square(-1, -1, 1, 1);
  const std::vector<uint8_t> left_out = redundant_faces(std::vector<Polygon>{p, p});
  EXPECT_FALSE(left_out[0] && left_out[1]);
}

}  // namespace
}  // namespace gvm
