// Images as PNG files, for pictures inlined into reports.
#pragma once

#include <string>
#include <string_view>

#include "snapshot.h"

namespace gvm::report {

// The bytes of an 8-bit RGBA, non-interlaced PNG of `image` (zlib-compressed, 'up' filter on
// every row). A PNG cannot be empty, so an image with no pixels, or whose rgba does not hold
// width x height x 4 bytes, is written as one transparent pixel.
std::string encode_png(const Image& image);

// A zlib stream of `bytes` (RFC 1950), as PNG's IDAT holds and as the browser's
// DecompressionStream("deflate") reads.
std::string zlib_deflate(std::string_view bytes);

}  // namespace gvm::report
