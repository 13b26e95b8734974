#include <google/protobuf/util/json_util.h>
#include <spdlog/spdlog.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <optional>

#include "gvm/analysis.h"
#include "gvm/mesh.h"
#include "gvm/part.h"
#include "visibility/surface_visibility.h"

namespace gvm {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Input faces (ascending, unique) of a set of triangles.
std::vector<uint32_t> input_faces(const SolidMesh& mesh, std::span<const uint32_t> triangles) {
  std::vector<uint32_t> faces;
  faces.reserve(triangles.size());
  for (uint32_t t : triangles) faces.push_back(mesh.triangle_face[t]);
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  return faces;
}

v1::GvmStatus to_proto(GvmKind kind) {
  switch (kind) {
    case GvmKind::kExactNoPotentialOccluders:
      return v1::GVM_STATUS_EXACT_NO_POTENTIAL_OCCLUDERS;
    case GvmKind::kGlobalOcclusionNotComputed:
      return v1::GVM_STATUS_GLOBAL_OCCLUSION_NOT_COMPUTED;
    case GvmKind::kEmptyVoid:
      return v1::GVM_STATUS_EMPTY_VOID;
    case GvmKind::kGlobalOcclusionComputed:
      return v1::GVM_STATUS_GLOBAL_OCCLUSION_COMPUTED;
  }
  return v1::GVM_STATUS_UNSPECIFIED;
}

// Writes the maps and facts of one surface into a Region or Feature message.
template <class Msg>
void fill_surface(const SolidMesh& mesh, std::span<const uint32_t> triangles,
                  const SurfaceVisibility& vis, double seconds, Msg* msg) {
  for (uint32_t f : input_faces(mesh, triangles)) msg->add_faces(f);
  vis.lvm.to_proto(msg->mutable_lvm());
  if (vis.gvm) vis.gvm->to_proto(msg->mutable_gvm());
  v1::SurfaceInfo* info = msg->mutable_info();
  info->set_gvm_status(to_proto(vis.kind));
  info->set_neighbor_occluders(
      static_cast<uint32_t>(input_faces(mesh, vis.occluders.neighbor).size()));
  info->set_potential_occluders(
      static_cast<uint32_t>(input_faces(mesh, vis.occluders.potential).size()));
  info->set_seconds(seconds);
  const GlobalOcclusionStatistics& stats = vis.statistics;
  if (stats.envelope.tentative_faces > 0) {
    info->set_envelope_border_arcs(stats.envelope.border_edges);
    info->set_envelope_faces(stats.envelope.envelope_faces);
    info->set_envelope_patches(stats.envelope.patches);
  }
  if (stats.convex.pairs > 0) {
    info->set_pairwise_maps(stats.convex.maps);
    info->set_pairwise_map_arcs(stats.convex.map_arcs);
  }
  if (stats.envelope.tentative_faces > 0 || stats.convex.pairs > 0) {
    info->set_arrangement_vertices(stats.arrangement_vertices);
    info->set_occluded_boundary_arcs(stats.occluded_boundary_arcs);
  }
}

void fill_part_summary(const RawMesh& raw, const Part& part, v1::PartSummary* out) {
  const SolidMesh& mesh = part.mesh();
  out->set_source(mesh.source);
  out->set_input_faces(mesh.input_face_count);
  out->set_input_vertices(static_cast<uint32_t>(raw.points.size()));
  out->set_triangles(static_cast<uint32_t>(mesh.triangles.size()));
  out->set_shells(static_cast<uint32_t>(mesh.shell_is_void.size()));
  out->set_void_shells(static_cast<uint32_t>(
      std::count(mesh.shell_is_void.begin(), mesh.shell_is_void.end(), true)));
  std::vector<uint32_t> hull;
  for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    if (part.is_hull(t)) hull.push_back(t);
  }
  out->set_hull_faces(static_cast<uint32_t>(input_faces(mesh, hull).size()));
  Point3 lo = mesh.points.front(), hi = lo;
  for (const Point3& p : mesh.points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  auto* box = out->mutable_bounding_box();
  box->mutable_min()->set_x(lo.x), box->mutable_min()->set_y(lo.y), box->mutable_min()->set_z(lo.z);
  box->mutable_max()->set_x(hi.x), box->mutable_max()->set_y(hi.y), box->mutable_max()->set_z(hi.z);
  out->set_validation("valid");
}

// Throttled progress: the callback sees every surface, the log one line per second.
class Progress {
 public:
  Progress(size_t total, const std::function<bool(size_t, size_t)>& callback)
      : total_(total), callback_(callback), start_(Clock::now()) {}

  // Returns false when the caller asked to stop.
  bool tick() {
    size_t done = ++done_;
    if (callback_ && !callback_(done, total_)) cancelled_ = true;
    auto now = Clock::now();
    auto last = last_log_.load();
    if (now - start_ > std::chrono::seconds(2) && now - last > std::chrono::seconds(1) &&
        last_log_.compare_exchange_strong(last, now)) {
      spdlog::info("visibility maps: {}/{} surfaces, {:.1f} s", done, total_,
                   seconds_since(start_));
    }
    return !cancelled_;
  }
  bool cancelled() const { return cancelled_; }

 private:
  size_t total_;
  const std::function<bool(size_t, size_t)>& callback_;
  Clock::time_point start_;
  std::atomic<size_t> done_{0};
  std::atomic<Clock::time_point> last_log_{};
  std::atomic<bool> cancelled_{false};
};

// The whole analysis, inside the caller's task arena (so --threads bounds every phase).
StatusOr<v1::Analysis> analyze_in_arena(const AnalyzeRequest& request, int threads) {
  const auto t_start = Clock::now();
  v1::Analysis result;
  result.set_engine_version(GVM_VERSION);
  v1::Timing* timing = result.mutable_timing();

  auto t0 = Clock::now();
  StatusOr<RawMesh> raw = read_raw_mesh(request.part_path);
  if (!raw.ok()) return raw.status();
  timing->set_read_seconds(seconds_since(t0));

  t0 = Clock::now();
  StatusOr<SolidMesh> solid = build_solid(*raw);
  if (!solid.ok()) return solid.status();
  timing->set_validate_seconds(seconds_since(t0));

  t0 = Clock::now();
  PartOptions part_options;
  if (request.options.feature_angle_degrees() > 0) {
    part_options.feature_angle_degrees = request.options.feature_angle_degrees();
  }
  if (!request.groups_path.empty()) {
    auto groups = read_face_groups(request.groups_path, solid->input_face_count);
    if (!groups.ok()) return groups.status();
    part_options.face_groups = std::move(*groups);
  } else {
    part_options.face_groups = solid->groups;
  }
  StatusOr<Part> part = Part::analyze(std::move(*solid), part_options);
  if (!part.ok()) return part.status();
  timing->set_part_seconds(seconds_since(t0));
  const SolidMesh& mesh = part->mesh();

  // Surfaces: every region, then every feature. Independent, so computed in parallel and
  // stored by index: the output order never depends on the thread count.
  std::vector<std::span<const uint32_t>> surfaces;
  for (const ConcaveRegion& r : part->regions()) surfaces.emplace_back(r.triangles);
  for (const Feature& f : part->features()) surfaces.emplace_back(f.triangles);
  std::vector<SurfaceVisibility> maps(surfaces.size());
  std::vector<double> surface_seconds(surfaces.size());

  t0 = Clock::now();
  timing->set_threads(static_cast<uint32_t>(threads));
  const OcclusionMethod method =
      request.options.occlusion_method() == v1::OCCLUSION_METHOD_CONVEX_DECOMPOSITION
          ? OcclusionMethod::kConvexDecomposition
          : OcclusionMethod::kEffectiveMinkowskiEnvelope;
  Progress progress(surfaces.size(), request.progress);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, surfaces.size(), 1),
                    [&](const tbb::blocked_range<size_t>& range) {
                      for (size_t i = range.begin(); i != range.end(); ++i) {
                        if (progress.cancelled()) return;
                        auto ts = Clock::now();
                        maps[i] = compute_surface_visibility(*part, surfaces[i],
                                                             !request.options.lvm_only(), method);
                        surface_seconds[i] = seconds_since(ts);
                        progress.tick();
                      }
                    });
  if (progress.cancelled()) return Status(StatusCode::kCancelled, "analysis cancelled");
  timing->set_visibility_seconds(seconds_since(t0));

  fill_part_summary(*raw, *part, result.mutable_part());
  const size_t region_count = part->regions().size();
  uint32_t with_occluders = 0;
  for (size_t i = 0; i < surfaces.size(); ++i) {
    if (!maps[i].occluders.potential.empty()) ++with_occluders;
  }
  for (size_t i = 0; i < region_count; ++i) {
    const ConcaveRegion& r = part->regions()[i];
    v1::Region* msg = result.add_regions();
    msg->set_id(r.id);
    msg->set_is_void(r.is_void);
    fill_surface(mesh, r.triangles, maps[i], surface_seconds[i], msg);
  }
  for (size_t i = 0; i < part->features().size(); ++i) {
    const Feature& f = part->features()[i];
    v1::Feature* msg = result.add_features();
    msg->set_id(f.id);
    msg->set_name(f.name);
    msg->set_on_hull(f.on_hull);
    msg->set_region(f.region);
    if (f.region >= 0) result.mutable_regions(f.region)->add_features(f.id);
    fill_surface(mesh, f.triangles, maps[region_count + i], surface_seconds[region_count + i],
                 msg);
  }
  v1::Statistics* stats = result.mutable_statistics();
  stats->set_regions(static_cast<uint32_t>(region_count));
  stats->set_features(static_cast<uint32_t>(part->features().size()));
  stats->set_surfaces_with_potential_occluders(with_occluders);
  timing->set_total_seconds(seconds_since(t_start));
  return result;
}

}  // namespace

StatusOr<v1::Analysis> analyze(const AnalyzeRequest& request) {
  const int threads = request.options.threads() > 0 ? static_cast<int>(request.options.threads())
                                                    : tbb::this_task_arena::max_concurrency();
  tbb::task_arena arena(threads);
  std::optional<StatusOr<v1::Analysis>> out;
  arena.execute([&] { out.emplace(analyze_in_arena(request, threads)); });
  return std::move(*out);
}

std::string to_json(const v1::Analysis& analysis) {
  google::protobuf::util::JsonPrintOptions options;
  options.add_whitespace = true;
  options.always_print_primitive_fields = true;
  std::string out;
  // Serializing a message we built ourselves cannot fail.
  (void)google::protobuf::util::MessageToJsonString(analysis, &out, options);
  return out;
}

}  // namespace gvm
