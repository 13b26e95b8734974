#include "gvm/direction_overlay.h"

#include "sphere/coverage_overlay.h"

namespace gvm {
namespace {

std::vector<sphere::SphericalImage> images_of(std::span<const DirectionSet> sets) {
  std::vector<sphere::SphericalImage> out;
  out.reserve(sets.size());
  for (const DirectionSet& s : sets) out.push_back(s.image());
  return out;
}

Direction wrap(const exact::ExactVec& v) {
  return Direction(std::make_shared<const exact::ExactVec>(v));
}

}  // namespace

struct DirectionOverlay::Impl {
  explicit Impl(std::span<const DirectionSet> sets) : images(images_of(sets)), overlay(images) {}
  std::vector<sphere::SphericalImage> images;  // kept alive for the overlay
  sphere::CoverageOverlay overlay;
};

DirectionOverlay::DirectionOverlay(std::span<const DirectionSet> sets)
    : impl_(std::make_unique<Impl>(sets)) {}

DirectionOverlay::DirectionOverlay(DirectionOverlay&&) noexcept = default;
DirectionOverlay& DirectionOverlay::operator=(DirectionOverlay&&) noexcept = default;
DirectionOverlay::~DirectionOverlay() = default;

size_t DirectionOverlay::vertex_count() const { return impl_->overlay.vertex_count(); }
size_t DirectionOverlay::edge_count() const { return impl_->overlay.edge_count(); }
size_t DirectionOverlay::face_count() const { return impl_->overlay.face_count(); }

void DirectionOverlay::for_each_cell(const std::function<void(const Cell&)>& visit) const {
  impl_->overlay.for_each_cell([&](const sphere::CoverageOverlay::Cell& c) {
    const CellKind kind = c.kind == sphere::CoverageOverlay::CellKind::kVertex ? CellKind::kVertex
                          : c.kind == sphere::CoverageOverlay::CellKind::kEdge ? CellKind::kEdge
                                                                               : CellKind::kFace;
    visit(Cell{kind, wrap(c.witness), c.coverage});
  });
}

std::vector<DirectionOverlay::Coverage> DirectionOverlay::maximal_coverage() const {
  std::vector<Coverage> out;
  for (auto& m : impl_->overlay.maximal_coverage()) out.push_back({wrap(m.witness), std::move(m.coverage)});
  return out;
}

}  // namespace gvm
