// What an Analysis owns, shared by the driver that builds it and the queries on it.
#pragma once

#include <span>
#include <vector>

#include "gvm/analysis.h"
#include "exact/exact_vec.h"
#include "gvm/part.h"
#include "visibility/surface_visibility.h"

namespace gvm {

struct Analysis::Impl {
  explicit Impl(Part p) : part(std::move(p)) {}
  Part part;               // at its canonical scale (mesh/exact_scale.h)
  SolidMesh input_mesh;    // the same solid at the file's scale
  PartSummary summary;
  std::vector<Surface> regions, features;
  AnalysisTiming timing;
  v1::AnalyzeOptions options;
  uint32_t surfaces_with_potential_occluders = 0;
};

namespace analysis_internal {

OcclusionMethod method_of(const v1::AnalyzeOptions& options);

// The exact maps and sizes of one surface, its occluders counted in input faces.
SurfaceMaps surface_maps(const SolidMesh& mesh, SurfaceVisibility vis, double seconds);

// Input faces (ascending, unique) of a set of triangles.
std::vector<uint32_t> input_faces(const SolidMesh& mesh, std::span<const uint32_t> triangles);

// The outward normal shared by every triangle, when they all lie in one plane with one
// orientation.
std::optional<Direction> common_plane_normal(const SolidMesh& mesh,
                                             std::span<const uint32_t> triangles);

// The exact normal of triangle t; whether triangles a and b lie in one plane with one
// orientation.
exact::ExactVec normal_of(const SolidMesh& mesh, uint32_t t);
bool coplanar_alike(const SolidMesh& mesh, uint32_t a, uint32_t b);

// Triangles of the given input faces (ascending), or the first face not in the part.
StatusOr<std::vector<uint32_t>> triangles_of(const SolidMesh& mesh, std::span<const uint32_t> faces);

}  // namespace analysis_internal
}  // namespace gvm
