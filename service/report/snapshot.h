// A static picture of a triangle mesh: an orthographic software rendering along one
// direction, for reports that must print and must not depend on WebGL.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace gvm::report {

struct Rgb {
  uint8_t r = 0, g = 0, b = 0;
};

// Row-major, top row first, 4 bytes (r, g, b, a) per pixel.
struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;
};

struct SnapshotView {
  std::array<double, 3> toward_viewer;  // the viewer sits far away on this side (need not be unit)
  int size = 480;                       // the image is size x size pixels
};

// Orthographic, depth-buffered, flat-shaded. Each triangle is drawn in its colour scaled by
// a headlight term (0.35 + 0.65 |cos| of the angle between its normal and toward_viewer);
// back faces are drawn too (the depth buffer decides, which is safer for thin parts). The
// background is transparent (alpha 0). The projected bounding box of the part is fitted
// into the image with a small margin, keeping aspect. Screen "up" is the projection of +z,
// or of +y when toward_viewer is nearly parallel to z, so pictures are predictable. A 1 px
// darker line marks where adjacent visible pixels belong to triangles of different colour.
//
// Degenerate input never fails: an empty mesh, a mesh whose points all project to one point,
// a zero or non-finite toward_viewer give a fully transparent size x size image (a size
// below 1 gives an empty 0 x 0 image). Triangles with an out-of-range index or a non-finite
// point are skipped; triangles seen edge-on (zero projected area) cover no pixel; a triangle
// without a colour (triangle_colors too short) is drawn grey.
Image render_snapshot(std::span<const std::array<double, 3>> points,
                      std::span<const std::array<uint32_t, 3>> triangles, std::span<const Rgb> triangle_colors,
                      const SnapshotView& view);

}  // namespace gvm::report
