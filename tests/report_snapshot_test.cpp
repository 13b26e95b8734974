// The report's static pictures: what a snapshot shows (colour, depth, orientation on the
// screen, no gaps between triangles, feature lines), that degenerate input gives an empty
// picture instead of failing, and that the PNG and base64 encodings are exact.
#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "report/base64.h"
#include "report/png.h"
#include "report/snapshot.h"

namespace gvm::report {
namespace {

using P = std::array<double, 3>;
const Rgb kRed{200, 30, 30}, kGrey{128, 128, 128}, kGreen{20, 180, 20}, kBlue{20, 20, 180};

struct Mesh {
  std::vector<P> points;
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<Rgb> colors;

  // A planar quad a-b-c-d, counter-clockwise seen from outside.
  void quad(P a, P b, P c, P d, Rgb color) {
    const auto n = static_cast<uint32_t>(points.size());
    points.insert(points.end(), {a, b, c, d});
    triangles.push_back({n, n + 1, n + 2});
    triangles.push_back({n, n + 2, n + 3});
    colors.insert(colors.end(), 2, color);
  }
  Image render(P toward, int size = 480) const { return render_snapshot(points, triangles, colors, {toward, size}); }
};

// An axis-aligned box, outward-facing, its top face (z = hi) in its own colour.
Mesh box(P lo, P hi, Rgb top, Rgb rest) {
  auto v = [&](int i, int j, int k) { return P{i ? hi[0] : lo[0], j ? hi[1] : lo[1], k ? hi[2] : lo[2]}; };
  Mesh m;
  m.quad(v(0, 0, 0), v(0, 1, 0), v(1, 1, 0), v(1, 0, 0), rest);  // z = lo
  m.quad(v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1), top);   // z = hi
  m.quad(v(0, 0, 0), v(1, 0, 0), v(1, 0, 1), v(0, 0, 1), rest);  // y = lo
  m.quad(v(0, 1, 0), v(0, 1, 1), v(1, 1, 1), v(1, 1, 0), rest);  // y = hi
  m.quad(v(0, 0, 0), v(0, 0, 1), v(0, 1, 1), v(0, 1, 0), rest);  // x = lo
  m.quad(v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1), rest);  // x = hi
  return m;
}

std::array<int, 4> pixel(const Image& image, int x, int y) {
  const uint8_t* p = &image.rgba[4 * (static_cast<size_t>(y) * image.width + x)];
  return {p[0], p[1], p[2], p[3]};
}
bool reddish(std::array<int, 4> p) { return p[3] == 255 && p[0] > 2 * p[1] && p[0] > 2 * p[2]; }
bool greyish(std::array<int, 4> p) { return p[3] == 255 && p[0] > 60 && p[0] == p[1] && p[1] == p[2]; }

bool transparent(const Image& image, int size) {
  if (image.width != size || image.height != size || image.rgba.size() != size_t(4) * size * size) return false;
  for (size_t i = 3; i < image.rgba.size(); i += 4) if (image.rgba[i] != 0) return false;
  return true;
}

TEST(Snapshot, CubeSeenFromAboveShowsItsTopAndFromBelowItsBottom) {
  const Mesh cube = box({0, 0, 0}, {1, 1, 1}, kRed, kGrey);
  const Image top = cube.render({0, 0, 1});
  ASSERT_EQ(top.width, 480);
  ASSERT_EQ(top.height, 480);
  EXPECT_TRUE(reddish(pixel(top, 240, 240)));
  for (auto [x, y] : {std::pair{0, 0}, {479, 0}, {0, 479}, {479, 479}}) EXPECT_EQ(pixel(top, x, y)[3], 0);
  EXPECT_TRUE(greyish(pixel(cube.render({0, 0, -1}), 240, 240)));
  EXPECT_TRUE(greyish(pixel(cube.render({0, 0, -7.5}), 240, 240))) << "toward_viewer need not be unit";
}

TEST(Snapshot, FacesSeenObliquelyAreDarker) {
  const Image image = box({0, 0, 0}, {1, 1, 1}, kGrey, kGrey).render({1, 1, 1});
  const auto centre = pixel(image, 240, 240);  // the corner (1, 1, 1), three faces at 54.7 degrees
  EXPECT_TRUE(greyish(centre));
  EXPECT_NEAR(centre[0], 128 * (0.35 + 0.65 / std::sqrt(3.0)), 1.0);
}

TEST(Snapshot, NearerSquareWinsWhicheverIsDrawnFirst) {
  for (bool green_first : {false, true}) {
    Mesh both;
    const auto square = [&](double z, Rgb c) { both.quad({0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 1, z}, c); };
    if (green_first) square(1, kGreen);
    square(0, kBlue);
    if (!green_first) square(1, kGreen);
    const auto above = pixel(both.render({0, 0, 1}), 240, 240), below = pixel(both.render({0, 0, -1}), 240, 240);
    EXPECT_GT(above[1], 2 * above[2]) << "seen from +z the square at z = 1 is in front; green first " << green_first;
    EXPECT_GT(below[2], 2 * below[1]) << "seen from -z the square at z = 0 is in front; green first " << green_first;
  }
}

struct Extent {
  int rows = 0, columns = 0;
  double red_row = 0, red_column = 0, other_row = 0;  // mean positions
};

Extent extent(const Image& image) {
  std::vector<bool> row(image.height), column(image.width);
  double red[3] = {0, 0, 0}, other[2] = {0, 0};
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const auto p = pixel(image, x, y);
      if (p[3] == 0) continue;
      row[y] = column[x] = true;
      if (reddish(p)) red[0] += 1, red[1] += y, red[2] += x;
      else other[0] += 1, other[1] += y;
    }
  }
  return {int(std::count(row.begin(), row.end(), true)), int(std::count(column.begin(), column.end(), true)),
          red[1] / red[0], red[2] / red[0], other[1] / other[0]};
}

TEST(Snapshot, PlusZIsUpOnTheScreen) {
  const Mesh tower = box({0, 0, 0}, {1, 1, 4}, kRed, kGrey);
  const Extent side = extent(tower.render({1, 0, 0}));
  EXPECT_GT(side.rows, 3 * side.columns);
  const Extent tilted = extent(tower.render({1, 0, 0.3}));  // the top face shows, at the top
  EXPECT_LT(tilted.red_row, tilted.other_row);
}

TEST(Snapshot, SeenAlongZPlusYIsUpAndPlusXRight) {
  Mesh plate;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      const double x = i, y = j;
      plate.quad({x, y, 0}, {x + 1, y, 0}, {x + 1, y + 1, 0}, {x, y + 1, 0}, i == 1 && j == 1 ? kRed : kGrey);
    }
  }
  for (P toward : {P{0, 0, 1}, P{0.01, 0, 1}, P{0, -0.02, -1}}) {  // nearly along z: still +y up
    const Extent e = extent(plate.render(toward));
    EXPECT_LT(e.red_row, 240) << toward[0] << " " << toward[1] << " " << toward[2];
    EXPECT_EQ(e.red_column > 240, toward[2] > 0) << "seen from below, +x is on the left";
  }
  const Image image = plate.render({0, 0, 1});
  // The feature line: the red pixel next to the grey ones is darker than red pixels inside.
  int first_red = 0;
  while (first_red < 480 && !reddish(pixel(image, first_red, 120))) ++first_red;
  ASSERT_LT(first_red + 10, 480);
  EXPECT_GT(pixel(image, first_red - 1, 120)[3], 0) << "grey on the left of the line";
  EXPECT_LT(pixel(image, first_red, 120)[0], pixel(image, first_red + 10, 120)[0]);
  EXPECT_EQ(pixel(image, first_red + 1, 120), pixel(image, first_red + 10, 120)) << "the line is 1 px wide";
}

// A square split into many triangles, interior vertices jittered: every pixel inside is
// covered, even where pixel centres fall on (or rounding-close to) shared edges.
TEST(Snapshot, TrianglesSharingEdgesLeaveNoPinholes) {
  const unsigned seed = 20240611;
  std::mt19937 rng(seed);
  for (double jitter : {0.0, 0.3}) {
    const int n = 17;
    std::uniform_real_distribution<double> shift(-jitter / n, jitter / n);
    Mesh grid;
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        const bool inside = i > 0 && i < n && j > 0 && j < n;
        grid.points.push_back({double(i) / n + (inside ? shift(rng) : 0), double(j) / n + (inside ? shift(rng) : 0), 0});
      }
    }
    for (uint32_t j = 0; j < n; ++j) {
      for (uint32_t i = 0; i < n; ++i) {
        const uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
        grid.triangles.insert(grid.triangles.end(), {{a, b, c}, {a, c, d}});
      }
    }
    grid.colors.assign(grid.triangles.size(), kGrey);
    const Image image = grid.render({0, 0, 1});
    const Extent e = extent(image);
    int opaque = 0;
    for (size_t k = 3; k < image.rgba.size(); k += 4) opaque += image.rgba[k] == 255;
    EXPECT_EQ(opaque, e.rows * e.columns) << "seed " << seed << " jitter " << jitter;
    EXPECT_GT(e.rows, 400);
  }
}

// Two triangles sharing the edge a-b, which passes within rounding of the centre of pixel
// (154, 200): evaluated from a and from b, the edge function is negative both times, so
// the pixel is covered only if both triangles evaluate the edge the same way. The zero-area
// triangle fixes the fit to scale 1 (world x = screen x, world y = 480 - screen y).
TEST(Snapshot, PixelCentreRoundingCloseToASharedEdgeIsCovered) {
  Mesh m;
  m.points = {{124.41611434477515, 290.51838613208184, 0}, {258.45428769430634, 241.42617885108663, 0},
              {170, 210, 0}, {212, 322, 0}, {19, 19, 0}, {461, 461, 0}};
  m.triangles = {{0, 1, 2}, {1, 0, 3}, {4, 5, 4}};
  m.colors.assign(3, kGrey);
  EXPECT_TRUE(greyish(pixel(m.render({0, 0, 1}), 154, 200)));
}

TEST(Snapshot, DegenerateInputGivesTransparentImageOfTheRequestedSize) {
  const Mesh cube = box({0, 0, 0}, {1, 1, 1}, kRed, kGrey);
  EXPECT_TRUE(transparent(Mesh{}.render({0, 0, 1}), 480));
  EXPECT_TRUE(transparent(cube.render({0, 0, 0}, 64), 64));
  EXPECT_TRUE(transparent(cube.render({NAN, 0, 1}, 64), 64));
  Mesh sliver;  // zero area
  sliver.points = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  sliver.triangles = {{0, 1, 2}};
  sliver.colors = {kRed};
  EXPECT_TRUE(transparent(sliver.render({0, 0, 1}), 480));
  Mesh point = sliver;  // all points equal
  point.points.assign(3, {5, 5, 5});
  EXPECT_TRUE(transparent(point.render({1, 0, 0}, 100), 100));
  Mesh broken = sliver;  // an index out of range, a non-finite point
  broken.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {INFINITY, 0, 0}};
  broken.triangles = {{0, 1, 7}, {0, 1, 3}};
  EXPECT_TRUE(transparent(broken.render({0, 0, 1}), 480));
  const Image none = cube.render({0, 0, 1}, 0);
  EXPECT_EQ(none.width, 0);
  EXPECT_TRUE(none.rgba.empty());
  Mesh uncoloured = cube;
  uncoloured.colors.clear();
  EXPECT_TRUE(greyish(pixel(uncoloured.render({0, 0, 1}), 240, 240)));
}

// A minimal PNG reader: checks the signature, the header and every CRC, then inflates and
// unfilters the pixels (filters 0 and 2, the ones the encoder may use).
Image decode_png(const std::string& png) {
  Image image;
  const auto u32 = [&](size_t at) {
    return uint32_t(uint8_t(png[at])) << 24 | uint32_t(uint8_t(png[at + 1])) << 16 |
           uint32_t(uint8_t(png[at + 2])) << 8 | uint32_t(uint8_t(png[at + 3]));
  };
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n"));
  std::string idat, last;
  for (size_t at = 8; at + 12 <= png.size() && last != "IEND";) {
    const uint32_t length = u32(at);
    last = png.substr(at + 4, 4);
    const std::string data = png.substr(at + 8, length);
    const auto* typed = reinterpret_cast<const Bytef*>(png.data() + at + 4);
    EXPECT_EQ(u32(at + 8 + length), crc32(0L, typed, 4 + length)) << last;
    if (last == "IHDR") {
      image.width = int(u32(at + 8)), image.height = int(u32(at + 12));
      EXPECT_EQ(data.substr(8), std::string({8, 6, 0, 0, 0}));
    }
    if (last == "IDAT") idat += data;
    at += 12 + length;
  }
  EXPECT_EQ(last, "IEND");
  const size_t stride = size_t(image.width) * 4;
  std::vector<uint8_t> raw((stride + 1) * image.height + 1);  // one spare byte: catches excess data
  uLongf size = raw.size();
  EXPECT_EQ(uncompress(raw.data(), &size, reinterpret_cast<const Bytef*>(idat.data()), idat.size()), Z_OK);
  EXPECT_EQ(size, raw.size() - 1);
  for (int y = 0; y < image.height; ++y) {
    const uint8_t filter = raw[y * (stride + 1)];
    EXPECT_TRUE(filter == 0 || filter == 2) << "row " << y;
    for (size_t i = 0; i < stride; ++i) {
      const uint8_t above = filter == 2 && y > 0 ? image.rgba[(y - 1) * stride + i] : 0;
      image.rgba.push_back(uint8_t(raw[y * (stride + 1) + 1 + i] + above));
    }
  }
  return image;
}

TEST(Png, RoundTripIsExact) {
  const Image render = box({0, 0, 0}, {1, 2, 3}, kRed, kGrey).render({1, 0.5, 0.7}, 97);
  std::mt19937 rng(7);
  Image noise{5, 3, {}};  // not square, every byte value
  for (int i = 0; i < 5 * 3 * 4; ++i) noise.rgba.push_back(uint8_t(rng()));
  for (const Image& image : {render, noise}) {
    const Image decoded = decode_png(encode_png(image));
    EXPECT_EQ(decoded.width, image.width);
    EXPECT_EQ(decoded.height, image.height);
    EXPECT_EQ(decoded.rgba, image.rgba);
  }
  const Image empty = decode_png(encode_png(Image{}));
  EXPECT_EQ(empty.width, 1);
  EXPECT_EQ(empty.rgba, std::vector<uint8_t>(4, 0));
}

TEST(Base64, Rfc4648TestVectors) {
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foob"), "Zm9vYg==");
  EXPECT_EQ(base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64("\xff\xfe\xfd"), "//79");  // bytes above 127 are not sign-extended
}

}  // namespace
}  // namespace gvm::report
