#include "visibility/global_visibility_map.h"

#include <spdlog/spdlog.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <optional>
#include <unordered_map>
#include <utility>

#include "parallel/interrupt.h"
#include "sphere/arrangement.h"
#include "sphere/d3.h"
#include "sphere/image_overlay.h"
#include "sphere/region_union.h"
#include "visibility/clip_window.h"
#include "visibility/convex_decomposition.h"
#include "visibility/direction_window.h"
#include "visibility/effective_minkowski_envelope.h"
#include "visibility/occluded_directions.h"
#include "visibility/occluder_beam.h"
#include "visibility/occlusion_culling.h"
#include "visibility/occlusion_probe.h"
#include "visibility/open_cells.h"
#include "visibility/probed_runs.h"
#include "visibility/redundant_faces.h"
#include "visibility/seam_candidates.h"

namespace gvm {
namespace {

using exact::ExactVec;
using sphere::Arrangement;
using sphere::ArrangementArc;
using sphere::ArrangementPoint;

constexpr int kLvm = 0;        // layer of LVM(S + N_S): coverage 1 inside its 2-cells
constexpr int kOcclusion = 1;  // layer of the closure of the occluded directions
constexpr int kSeam = 2;       // candidates for seams of the occlusion (seam_candidates.h)

// The vertices q - p of the sum, each built once: arcs that share an endpoint then share
// its node, which lets the exact predicates see zeros by construction.
class SumVertices {
 public:
  explicit SumVertices(const SolidMesh& mesh) : mesh_(mesh) {}
  const ExactVec& at(uint32_t q, uint32_t p) {
    auto [it, inserted] = cache_.try_emplace(uint64_t(q) << 32 | p);
    if (inserted) it->second = exact::point_difference(mesh_.points[q], mesh_.points[p]);
    return it->second;
  }
  const ExactVec& at(uint32_t q, uint32_t p) const { return cache_.at(uint64_t(q) << 32 | p); }

 private:
  const SolidMesh& mesh_;
  std::unordered_map<uint64_t, ExactVec> cache_;
};

// Whether u lies inside, outside or (none) on the boundary of a back-facing face: it
// projects to the convex polygon to the left of its edges (its vertices run
// counter-clockwise around the outward normal, seen from outside).
std::optional<bool> face_contains(const std::vector<ExactVec>& v, const ExactVec& u) {
  bool on_boundary = false;
  for (size_t i = 0; i < v.size(); ++i) {
    const Sign s = exact::sign_det(v[i], v[(i + 1) % v.size()], u);
    if (s == Sign::kNegative) return false;
    on_boundary = on_boundary || s == Sign::kZero;
  }
  if (on_boundary) return std::nullopt;
  return true;
}

// The envelope faces that can change the union inside the windows, with the windows each
// meets (bit k: window k): faces inside larger ones (redundant_faces.h), and faces that
// meet every window in zero area, change it nowhere.
struct FacesThatMatter {
  std::vector<uint32_t> kept;
  std::vector<uint64_t> windows_met;  // of each face
  std::vector<uint8_t> redundant;     // of each face
};

FacesThatMatter faces_that_matter(const std::vector<std::vector<ExactVec>>& faces,
                                  std::span<const ClipWindow> windows) {
  std::vector<uint8_t> redundant = redundant_faces(faces);
  std::vector<uint64_t> met(faces.size(), 0);
  tbb::parallel_for(size_t{0}, faces.size(), [&](size_t i) {
    for (size_t k = 0; k < windows.size() && !redundant[i]; ++k) met[i] |= uint64_t{!windows[k].misses(faces[i])} << k;
  });
  FacesThatMatter out;
  for (uint32_t i = 0; i < faces.size(); ++i) {
    if (!redundant[i] && (windows.empty() || met[i] != 0)) out.kept.push_back(i);
  }
  out.windows_met = std::move(met);
  out.redundant = std::move(redundant);
  return out;
}

// The closed occluded region, the reference direction it was labelled from, and the cells
// whose open insides are occluded outright.
struct Occlusion {
  sphere::Region region;
  ExactVec reference;
  OpenCells cells;
};

// The closure of the occluded directions by the effective Minkowski envelope (paper
// Sec. 4): the envelope's faces are the cells, a group's arcs its border chain. It is
// right near `needed` (within the LVM), which the window holds. With a reference
// given, none when that lies on one of the cells' circles.
std::optional<Occlusion> envelope_occlusion(const SolidMesh& mesh, std::span<const uint32_t> s,
                                            std::span<const uint32_t> o, const sphere::SphericalImage& needed,
                                            const DirectionWindow& window, std::span<const ClipWindow> clip,
                                            std::vector<ExactVec>& circles, const std::vector<ExactVec>& points,
                                            GlobalOcclusionStatistics* stats, const ExactVec* reference = nullptr) {
  const EffectiveMinkowskiEnvelope eme =
      compute_effective_minkowski_envelope(mesh, s, o, /*keep_faces=*/true, &window);
  spdlog::debug("global occlusion: |S| {} |O| {}: {} tentative faces ({} outside the LVM), {} kept, "
                "{} envelope faces, {} patches, {} border arcs",
                s.size(), o.size(), eme.statistics.tentative_faces, eme.statistics.outside_window,
                eme.statistics.kept_faces, eme.statistics.envelope_faces, eme.statistics.patches,
                eme.statistics.border_edges);
  if (stats) stats->envelope = eme.statistics;
  SumVertices sum(mesh);
  std::vector<std::vector<ExactVec>> faces;
  Interruptions interruptions;
  for (const EnvelopeFace& f : eme.faces) {
    interruptions.tick();
    std::vector<ExactVec> v;
    for (auto [q, p] : f.vertices) v.push_back(sum.at(q, p));
    faces.push_back(std::move(v));
  }
  // Named, not a structured binding: clang 14 (the fuzz preset) cannot capture those.
  const FacesThatMatter matter = faces_that_matter(faces, clip);
  const std::vector<uint32_t>& kept = matter.kept;
  const std::vector<uint64_t>& windows_met = matter.windows_met;
  const std::vector<uint8_t>& redundant = matter.redundant;
  spdlog::debug("global occlusion: {} of {} envelope faces lie inside larger ones or miss the {} windows "
                "around the LVM", faces.size() - kept.size(), faces.size(), clip.size());
  // The open cells are the faces that are not redundant: a redundant face's open inside
  // lies in the union of larger ones, and what OpenCells leaves undecided the probe
  // decides. Their sides are the circles the reference must avoid, with the windows'
  // (the unions hold no other faces).
  std::vector<OpenCells::Cell> open;
  const size_t circles_before = circles.size();
  for (size_t i = 0; i < faces.size(); ++i) {
    interruptions.tick();
    if (redundant[i]) continue;
    std::vector<ExactVec> n;
    for (size_t k = 0; k < faces[i].size(); ++k) n.push_back(exact::cross(faces[i][k], faces[i][(k + 1) % faces[i].size()]));
    circles.insert(circles.end(), n.begin(), n.end());
    open.push_back({faces[i], std::move(n)});
  }
  for (const ClipWindow& w : clip) circles.insert(circles.end(), w.normals().begin(), w.normals().end());
  if (reference && std::any_of(circles.begin() + circles_before, circles.end(),
                               [&](const ExactVec& n) { return exact::sign_dot(n, *reference) == Sign::kZero; })) {
    return std::nullopt;
  }
  const ExactVec r = reference ? *reference : sphere::generic_direction(circles, points);
  auto union_of = [&](std::span<const uint32_t> subset) {
    OccludingCells cells;
    cells.count = subset.size();
    cells.direction = [&](uint32_t i) { return exact::unit_estimate(faces[subset[i]][0]).unit; };
    cells.boundary = [&](std::span<const uint32_t> members) {
      std::vector<EnvelopeFace> group;
      for (uint32_t i : members) group.push_back(eme.faces[subset[i]]);
      std::vector<ArrangementArc> arcs;
      for (const EnvelopeBorderEdge& e : border_chain(group)) {
        const ExactVec &a = std::as_const(sum).at(e.q0, e.p0), &b = std::as_const(sum).at(e.q1, e.p1);
        arcs.push_back({a, b, exact::cross(a, b), 0, e.multiplicity});
      }
      return arcs;
    };
    cells.covers_reference = [&](uint32_t i) { return face_contains(faces[subset[i]], r) == true; };
    cells.windows = clip;
    cells.meets_window = [&](uint32_t i, size_t k) { return (windows_met[subset[i]] >> k & 1) != 0; };
    cells.coverage_at = [&](std::span<const uint32_t> members, const ExactVec& u) -> std::optional<int> {
      int coverage = 0;
      for (uint32_t i : members) {
        const std::optional<bool> inside = face_contains(faces[subset[i]], u);
        if (!inside) return std::nullopt;
        coverage += *inside;
      }
      return coverage;
    };
    return occluded_directions(cells, r);
  };
  TieredUnionStatistics tiers;
  sphere::Region region = union_by_tiers(faces, kept, clip, union_of, r, &tiers, {}, &needed);
  spdlog::debug("global occlusion: {} faces in {} tiers, {} inside the union of the tiers before theirs or "
                "missing what it leaves of the LVM",
                tiers.faces, tiers.tiers, tiers.left_out);
  return Occlusion{std::move(region), r, OpenCells(std::move(open))};
}

// The occluders seen under the largest solid angles from S's centre (twice the area over
// the squared distance of the centroid), ascending.
std::vector<uint32_t> nearest_occluders(const SolidMesh& mesh, std::span<const uint32_t> s,
                                        std::span<const uint32_t> o, size_t count) {
  using sphere::D3;
  auto point = [&](uint32_t v) { return D3{mesh.points[v].x, mesh.points[v].y, mesh.points[v].z}; };
  D3 centre{0, 0, 0};
  for (uint32_t t : s) {
    for (uint32_t v : mesh.triangles[t]) centre = sphere::add(centre, point(v), 1.0 / (3 * s.size()));
  }
  std::vector<std::pair<double, uint32_t>> scored;
  for (uint32_t t : o) {
    const Triangle& tri = mesh.triangles[t];
    const D3 a = point(tri[0]), b = point(tri[1]), c = point(tri[2]);
    const double area = sphere::norm(sphere::cross(sphere::add(b, a, -1), sphere::add(c, a, -1)));
    const D3 away = sphere::add(sphere::add(sphere::add(a, b), c), centre, -3);
    scored.emplace_back(-area / (sphere::dot(away, away) / 9 + 1e-300), t);
  }
  count = std::min(count, scored.size());
  std::partial_sort(scored.begin(), scored.begin() + count, scored.end());
  std::vector<uint32_t> out;
  for (size_t i = 0; i < count; ++i) out.push_back(scored[i].second);
  std::sort(out.begin(), out.end());
  return out;
}

// The closure in two passes where O is large. A first pass over the nearest occluders
// gives Q' within the closure Q (fewer occluders block fewer directions) and leaves
// V' = LVM - Int(Q'), often a small part of the LVM (TR12J's thread flanks: a tenth of a
// quarter sphere); the second keeps only the envelope faces near V'. Merged, Q' and the
// second union are Q on the LVM: outside V' the interior of Q' covers it, and near V' the
// second union is Q (a face left out lies at a positive distance from V'). The seams, the
// open cells and the probe still cover the whole LVM, so directions inside Int(Q') that
// grazing rays reach are found as before. One pass where the first leaves half of the
// LVM or more, or V' has no cover by caps.
Occlusion envelope_occlusion_in_passes(const SolidMesh& mesh, std::span<const uint32_t> s,
                                       std::span<const uint32_t> o, const sphere::SphericalImage& lvm,
                                       const DirectionWindow& window, std::span<const ClipWindow> clip,
                                       std::vector<ExactVec>& circles, const std::vector<ExactVec>& points,
                                       GlobalOcclusionStatistics* stats) {
  // Measured on the shared parts (docs/performance-history.md, "A window from a first
  // bound"): below 2,048 occluders the first pass costs more than the second saves.
  constexpr size_t kLargeO = 2048, kFirstPass = 64;
  constexpr double kLeftAtMost = 0.5;
  auto one_pass = [&] { return *envelope_occlusion(mesh, s, o, lvm, window, clip, circles, points, stats); };
  // An arc or a point of an LVM is a window as narrow as any.
  if (o.size() < kLargeO || lvm.dimension() < 2) return one_pass();
  std::optional<Occlusion> first = envelope_occlusion(mesh, s, nearest_occluders(mesh, s, o, kFirstPass), lvm,
                                                      window, clip, circles, points, stats);
  const sphere::SphericalImage left = sphere::outside_interior(lvm, first->region, first->reference);
  const double left_area = left.area(), lvm_area = lvm.area();
  spdlog::debug("global occlusion: the {} nearest occluders leave {:.4g} of the LVM's {:.4g} sr", kFirstPass,
                left_area, lvm_area);
  if (stats) stats->first_pass_occluders = kFirstPass;
  if (left.is_empty()) return std::move(*first);
  // The LVM is convex: one convex 2-cell.
  const sphere::Face within = lvm.faces().size() == 1 && lvm.faces()[0].convex ? lvm.faces()[0] : sphere::Face{};
  const std::optional<DirectionWindow> narrow =
      left_area < kLeftAtMost * lvm_area ? DirectionWindow::covering(left, within, coordinate_bound(mesh, s, o))
                                         : std::nullopt;
  std::optional<Occlusion> second =
      narrow ? envelope_occlusion(mesh, s, o, left, *narrow, clip, circles, points, stats, &first->reference)
             : std::nullopt;
  if (!second) {
    if (stats) stats->first_pass_occluders = 0;
    return one_pass();
  }
  const uint64_t work = first->region.arrangement_vertices + second->region.arrangement_vertices;
  second->region = sphere::region_union({std::move(second->region), std::move(first->region)}, first->reference);
  second->region.arrangement_vertices += work;
  second->cells.absorb(std::move(first->cells));
  return std::move(*second);
}

// The same closure by convex decomposition: the pairwise occlusion maps are the cells.
Occlusion convex_decomposition_occlusion(const SolidMesh& mesh, std::span<const uint32_t> s,
                                         std::span<const uint32_t> o, const DirectionWindow& window,
                                         std::vector<ExactVec>& circles,
                                         const std::vector<ExactVec>& points,
                                         GlobalOcclusionStatistics* stats) {
  ConvexDecompositionStatistics convex;
  const std::vector<sphere::SphericalImage> maps = pairwise_occlusion_maps(mesh, s, o, &window, &convex);
  spdlog::debug("global occlusion: |S| {} |O| {}: {} pairs ({} outside the LVM), {} maps with {} arcs",
                s.size(), o.size(), convex.pairs, convex.outside_window, convex.maps, convex.map_arcs);
  if (stats) stats->convex = convex;
  for (const sphere::SphericalImage& m : maps) {
    for (const sphere::Face& f : m.faces()) {
      for (const sphere::Arc& a : f.loops[0].arcs) circles.push_back(a.normal);
    }
  }
  const ExactVec r = sphere::generic_direction(circles, points);
  OccludingCells cells;
  cells.count = maps.size();
  cells.direction = [&](uint32_t i) {
    const auto& faces = maps[i].faces();
    return exact::unit_estimate(faces.empty() ? r : faces[0].loops[0].arcs[0].end).unit;
  };
  cells.boundary = [&](std::span<const uint32_t> members) {
    std::vector<ArrangementArc> arcs;
    for (uint32_t i : members) {
      for (const sphere::Face& f : maps[i].faces()) {
        for (const sphere::Arc& arc : f.loops[0].arcs) {
          std::vector<ExactVec> v = sphere::split_arc(arc);
          for (size_t k = 0; k + 1 < v.size(); ++k) arcs.push_back({v[k], v[k + 1], arc.normal, 0, 1});
        }
      }
    }
    return arcs;
  };
  cells.covers_reference = [&](uint32_t i) { return maps[i].contains(r); };
  std::vector<OpenCells::Cell> open;
  for (const sphere::SphericalImage& m : maps) {
    for (const sphere::Face& f : m.faces()) {
      if (!f.convex) continue;
      OpenCells::Cell cell;
      for (const sphere::Arc& arc : f.loops[0].arcs) {
        cell.vertices.push_back(arc.start);
        cell.normals.push_back(arc.normal);
        cell.minor_sides = cell.minor_sides && !arc.full &&
                           exact::sign_det(arc.normal, arc.start, arc.end) == Sign::kPositive;
      }
      open.push_back(std::move(cell));
    }
  }
  return {occluded_directions(cells, r), r, OpenCells(std::move(open))};
}

// The GVM with the visible pieces of partly occluded arcs added (a piece whose ends
// coincide is a point): arcs that continue one another on one circle are merged, as the
// arrangement's extraction does, and points the arcs now hold are dropped.
sphere::SphericalImage with_pieces(const sphere::SphericalImage& gvm,
                                   const std::vector<sphere::Arc>& pieces) {
  std::vector<sphere::Arc> arcs = gvm.curves();
  std::vector<ExactVec> points = gvm.points();
  for (const sphere::Arc& piece : pieces) {
    if (exact::same_direction(piece.start, piece.end)) {
      points.push_back(piece.start);
    } else {
      arcs.push_back(piece);
    }
  }
  for (bool merged = true; merged;) {
    merged = false;
    for (size_t i = 0; i < arcs.size() && !merged; ++i) {
      for (size_t j = 0; j < arcs.size() && !merged; ++j) {
        sphere::Arc& a = arcs[i];
        sphere::Arc b = arcs[j];
        if (i == j || a.full || b.full || !exact::parallel(a.normal, b.normal)) continue;
        if (exact::sign_dot(a.normal, b.normal) == Sign::kNegative) b = {b.end, b.start, a.normal};
        if (exact::same_direction(a.end, b.start)) {
          a.end = b.end;
        } else if (exact::same_direction(b.end, a.start)) {
          a.start = b.start;
        } else {
          continue;
        }
        a.full = exact::same_direction(a.start, a.end);
        arcs.erase(arcs.begin() + j);
        merged = true;
      }
    }
  }
  sphere::SphericalImage out;
  for (const sphere::Face& f : gvm.faces()) out.add_face(f);
  for (const sphere::Arc& a : arcs) out.add_curve(a);
  for (const ExactVec& p : points) {
    bool held = false;
    for (const sphere::Arc& a : arcs) held = held || sphere::arc_contains(a, p);
    for (const ExactVec& q : out.points()) held = held || exact::same_direction(p, q);
    if (!held) out.add_point(p);
  }
  return out;
}

// The visible parts of an open edge of a seam candidate inside Int(GOM) and a 2-cell of the
// LVM: the closed pieces that no open cell holds, decided by the probe, their ends (on the
// sides of cells) as well.
std::vector<sphere::Arc> visible_on_seam(const sphere::Arc& open_edge, OpenCells& open,
                                         const OcclusionProbe& probe) {
  std::vector<sphere::Arc> visible;
  auto add_point = [&](const ExactVec& x) {
    if (exact::same_direction(x, open_edge.start) || exact::same_direction(x, open_edge.end)) return;
    for (const sphere::Arc& v : visible) {
      if (sphere::arc_contains(v, x)) return;
    }
    if (!probe.occluded(x)) visible.push_back({x, x, open_edge.normal});
  };
  for (const sphere::Arc& piece : open.uncovered(open_edge)) {
    if (!exact::same_direction(piece.start, piece.end)) {
      for (sphere::Arc& v : probe.unoccluded(piece)) visible.push_back(std::move(v));
    }
    add_point(piece.start);
    add_point(piece.end);
  }
  return visible;
}

// The GVM of an LVM without 2-cells, from the rays alone: the probe decides Def. 2 for
// every direction of the LVM, and its arcs and points need no closure of the occluded
// directions (that is for the 2-cells, whose seams and grazing directions the probe then
// decides). The visible set is closed (blocking is an open condition), so each piece's
// visible sub-arcs hold their ends; the vertices between pieces are decided on their own.
sphere::SphericalImage probed_visibility(const sphere::SphericalImage& lvm, const OcclusionProbe& probe) {
  std::vector<sphere::Arc> visible;
  auto add_point = [&](const ExactVec& x) {
    for (const sphere::Arc& v : visible) {
      if (sphere::arc_contains(v, x)) return;
    }
    if (!probe.occluded(x)) visible.push_back({x, x, x});  // a point: equal ends
  };
  for (const sphere::Arc& arc : lvm.curves()) {
    const std::vector<ExactVec> v = sphere::split_arc(arc);
    for (size_t k = 0; k + 1 < v.size(); ++k) {
      for (sphere::Arc& piece : probe.unoccluded({v[k], v[k + 1], arc.normal})) visible.push_back(std::move(piece));
    }
    for (const ExactVec& x : v) add_point(x);
  }
  for (const ExactVec& p : lvm.points()) add_point(p);
  return with_pieces(sphere::SphericalImage{}, visible);
}

}  // namespace

sphere::SphericalImage global_visibility_map(const SolidMesh& mesh, std::span<const uint32_t> s,
                                             std::span<const uint32_t> o,
                                             const sphere::SphericalImage& lvm,
                                             OcclusionMethod method,
                                             GlobalOcclusionStatistics* stats) {
  if (lvm.is_empty() || o.empty()) return lvm;
  const std::vector<uint32_t> beam = occluders_in_beam(mesh, s, o, lvm);
  if (stats) stats->occluders_in_beam = beam.size();
  if (beam.empty()) return lvm;
  // The convex decomposition still builds the closure there: the baseline, which the
  // probe's answer is compared with (MethodEquality).
  if (lvm.dimension() < 2 && method == OcclusionMethod::kEffectiveMinkowskiEnvelope) {
    return probed_visibility(lvm, OcclusionProbe(mesh, s, beam));
  }
  const DirectionWindow window(lvm, coordinate_bound(mesh, s, beam));
  // One window around a small LVM only: the fan windows of ClipWindow::covering made the
  // unions of piattello.stp grow past 24 GB (regions clipped to neighbouring windows).
  std::vector<ClipWindow> clip;
  if (std::optional<ClipWindow> w = ClipWindow::around(lvm)) clip.push_back(std::move(*w));
  std::vector<ArrangementArc> arcs;
  std::vector<ArrangementPoint> points;
  sphere::add_image(lvm, kLvm, arcs, points);
  const SeamCandidates seams = seam_candidates(mesh, s, beam, lvm, window);
  for (const ArrangementArc& a : seams.arcs) arcs.push_back({a.from, a.to, a.normal, kSeam, 0});

  // The reference direction lies on no circle of the LVM, of any cell or of any candidate
  // arc, and on no point.
  std::vector<ExactVec> circles, point_dirs;
  for (const ArrangementArc& a : arcs) circles.push_back(a.normal);
  for (const auto& p : points) point_dirs.push_back(p.p);
  const auto union_start = std::chrono::steady_clock::now();
  auto [occluded, r, open_cells] =
      method == OcclusionMethod::kEffectiveMinkowskiEnvelope
          ? envelope_occlusion_in_passes(mesh, s, beam, lvm, window, clip, circles, point_dirs, stats)
          : convex_decomposition_occlusion(mesh, s, beam, window, circles, point_dirs, stats);
  spdlog::debug("global occlusion: closure of the occluded directions: {} boundary arcs, {:.2f} s",
                occluded.boundary.size(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - union_start).count());
  for (const ArrangementArc& a : occluded.boundary) {
    arcs.push_back({a.from, a.to, a.normal, kOcclusion, 1});
  }
  int coverage[2] = {0, 0};
  coverage[kLvm] = !lvm.faces().empty() && lvm.contains(r) ? 1 : 0;
  coverage[kOcclusion] = occluded.contains_reference ? 1 : 0;

  const auto start = std::chrono::steady_clock::now();
  Arrangement arr(arcs, points, 2, r, coverage);
  spdlog::debug("global occlusion: arrangement of {} arcs: {} vertices, {} edges, {} pairs, {:.2f} s", arcs.size(),
                arr.vertices().size(), arr.edges().size(), arr.compared_pairs(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  const auto& half = arr.half_edges();
  auto in_lvm_face = [&](uint32_t f) { return arr.coverage(f, kLvm) > 0; };
  auto occluded_face = [&](uint32_t f) { return arr.coverage(f, kOcclusion) > 0; };
  auto face_in = [&](uint32_t f) { return in_lvm_face(f) && !occluded_face(f); };
  // A cell is in Int(GOM) iff every face around it is covered -- but the points and arcs
  // of the LVM in there may still be visible (rays along them that only graze O), and so
  // may the seam candidates inside its 2-cells: the probe decides them from the rays
  // (occlusion_probe.h).
  const OcclusionProbe probe(mesh, s, beam);
  std::vector<sphere::Arc> grazing;  // visible parts of arcs of the LVM and of seams in Int(GOM)
  std::vector<uint8_t> edge_visible(arr.edges().size(), 0);
  int probed_arcs = 0, probed_points = 0, visible_points = 0;
  // Whether the probe finds all of an arc visible; else its visible pieces are grazing.
  auto decide = [&](const sphere::Arc& arc, std::vector<sphere::Arc> pieces) {
    ++probed_arcs;
    if (pieces.size() == 1 && exact::same_direction(pieces[0].start, arc.start) &&
        exact::same_direction(pieces[0].end, arc.end)) {
      return true;
    }
    grazing.insert(grazing.end(), pieces.begin(), pieces.end());
    return false;
  };
  // Edges of the LVM inside Int(GOM), in runs along their circles (probed_runs.h); the
  // vertices inside a run are decided with it (kVisible, kHidden: its pieces hold them).
  enum RunVertex : uint8_t { kNotInRun, kVisible, kHidden };
  std::vector<uint8_t> lvm_inside(arr.edges().size(), 0), run_vertex(arr.vertices().size(), kNotInRun);
  for (uint32_t e = 0; e < arr.edges().size(); ++e) {
    lvm_inside[e] = arr.edge_on_layer(e, kLvm) && occluded_face(half[2 * e].face) && occluded_face(half[2 * e + 1].face);
  }
  Interruptions interruptions(64);
  for (const ProbedRun& run : probed_runs(arr, lvm_inside)) {
    interruptions.tick();
    const bool whole = decide(run.arc, probe.unoccluded(run.arc));
    for (uint32_t e : run.edges) edge_visible[e] = whole;
    for (uint32_t v : run.inner) run_vertex[v] = whole ? kVisible : kHidden;
  }
  for (uint32_t e = 0; e < arr.edges().size(); ++e) {
    interruptions.tick();
    const auto& edge = arr.edges()[e];
    const uint32_t left = half[2 * e].face, right = half[2 * e + 1].face;
    if (lvm_inside[e] || (!arr.edge_on_layer(e, kLvm) && !in_lvm_face(left) && !in_lvm_face(right))) continue;
    if (!occluded_face(left) || !occluded_face(right)) {
      edge_visible[e] = 1;
    } else if (arr.edge_on_layer(e, kSeam)) {
      const sphere::Arc arc{arr.vertices()[edge.v0].p, arr.vertices()[edge.v1].p, edge.normal};
      edge_visible[e] = decide(arc, visible_on_seam(arc, open_cells, probe));
    }
  }
  // open_cells named in the capture: clang 14 (the fuzz preset) cannot capture a structured
  // binding by [&].
  auto vertex_in = [&, &open_cells = open_cells](uint32_t v) {
    const auto& vert = arr.vertices()[v];
    bool on_lvm = arr.vertex_has_point(v, kLvm);  // a point or on an arc: not in a 2-cell
    bool in_lvm = on_lvm;
    bool all_occluded = true;
    for (uint32_t h : vert.out) {
      on_lvm |= arr.edge_on_layer(half[h].edge, kLvm);
      in_lvm |= on_lvm || in_lvm_face(half[h].face);
      all_occluded &= occluded_face(half[h].face);
    }
    if (vert.out.empty()) all_occluded = occluded_face(0);
    if (!in_lvm) return false;
    if (!all_occluded) return true;
    if (!on_lvm && open_cells.hold(vert.p)) return false;
    if (run_vertex[v] != kNotInRun) return run_vertex[v] == kVisible;
    ++probed_points;
    const bool visible = !probe.occluded(vert.p);
    visible_points += visible;
    return visible;
  };
  sphere::SphericalImage gvm =
      arr.extract(face_in, [&](uint32_t e) { return edge_visible[e] != 0; }, vertex_in);
  // Seam candidate points are decided on their own (not in the arrangement: there are
  // many, nearly all deep inside the occluded directions).
  for (const ExactVec& p : seams.points) {
    if (open_cells.hold(p) || gvm.contains(p)) continue;
    ++probed_points;
    if (!probe.occluded(p)) {
      ++visible_points;
      grazing.push_back({p, p, p});  // a point: equal ends (the normal is not used)
    }
  }
  if (!grazing.empty()) gvm = with_pieces(gvm, grazing);
  if (probed_arcs + probed_points > 0) {
    spdlog::debug("occlusion probe: {} arcs of the LVM or seam candidates inside the occluded directions "
                  "({} visible pieces), {} points ({} visible)",
                  probed_arcs, grazing.size(), probed_points, visible_points);
  }
  if (stats) {
    stats->occluded_boundary_arcs = occluded.boundary.size();
    stats->arrangement_vertices = occluded.arrangement_vertices + arr.vertices().size();
  }
  return gvm;
}

}  // namespace gvm
