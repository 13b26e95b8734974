// How the fuzz targets turn their bytes into requests, shared with the regression test
// (tests/fuzz_regression_test.cpp) so that a checked-in input replays exactly as found.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace gvm::fuzz {

// fuzz_analysis_*: parts of at most this many faces.
constexpr uint32_t kAnalysisMaxFaces = 48;

// fuzz_analysis_stl: the bytes are facets of 3 vertices of 3 little-endian float32 each
// (36 bytes); they become a well-formed binary STL (zero normals and attributes) of at
// most kAnalysisMaxFaces facets, so that mutations reach the geometry.
constexpr size_t kFacetBytes = 36;

inline std::string binary_stl_of_facets(std::string_view facets) {
  const uint32_t n = static_cast<uint32_t>(std::min<size_t>(facets.size() / kFacetBytes, kAnalysisMaxFaces));
  std::string out(80, '\0');
  out.append(reinterpret_cast<const char*>(&n), 4);  // little-endian host, as the format
  for (uint32_t i = 0; i < n; ++i) {
    out.append(12, '\0');
    out.append(facets.substr(size_t(i) * kFacetBytes, kFacetBytes));
    out.append(2, '\0');
  }
  return out;
}

// fuzz_groups: the part the groups are for, a unit cube of 6 quads.
constexpr uint32_t kCubeFaces = 6;
constexpr std::string_view kCube =
    "OFF\n8 6 0\n"
    "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"
    "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n";

}  // namespace gvm::fuzz
