// The parallel driver: read, validate, find regions and features, then the maps of every
// surface in parallel, stored by index so that nothing depends on the thread count.
#include <spdlog/spdlog.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <optional>
#include <stop_token>

#include "analysis/analysis_impl.h"
#include "gvm/cancellable_run.h"
#include "gvm/mesh.h"
#include "gvm/part.h"
#include "mesh/exact_scale.h"
#include "parallel/interrupt.h"

namespace gvm {
namespace {

using namespace analysis_internal;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string part_name(const AnalyzeRequest& request) {
  return request.part_name.empty() ? std::string("part") : request.part_name;
}

PartSummary summarize(const RawMesh& raw, const Part& part, const SolidMesh& mesh, const std::optional<StepPart>& step) {
  PartSummary out;
  out.source = mesh.source;
  out.input_faces = mesh.input_face_count;
  out.input_vertices = static_cast<uint32_t>(raw.points.size());
  out.triangles = static_cast<uint32_t>(mesh.triangles.size());
  out.shells = static_cast<uint32_t>(mesh.shell_is_void.size());
  out.void_shells = static_cast<uint32_t>(
      std::count(mesh.shell_is_void.begin(), mesh.shell_is_void.end(), true));
  std::vector<uint32_t> hull;
  for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    if (part.is_hull(t)) hull.push_back(t);
  }
  out.hull_faces = static_cast<uint32_t>(input_faces(mesh, hull).size());
  Point3 lo = mesh.points.front(), hi = lo;
  for (const Point3& p : mesh.points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  out.box_min = lo;
  out.box_max = hi;
  if (step) {
    out.file_unit = step->file_unit;
    out.cad_faces = static_cast<uint32_t>(step->cad_faces.size());
    out.linear_deflection = step->linear_deflection;
    out.angular_deflection_degrees = step->angular_deflection_degrees;
    out.tessellation = step->tessellation;
  }
  return out;
}

// The B-rep face a feature is, when all its faces come from one, or else the hole it is.
void describe_cad(Surface& feature, const StepPart& step) {
  const uint32_t first = step.face_cad[feature.faces.front()];
  for (uint32_t f : feature.faces) {
    if (step.face_cad[f] == first) continue;
    for (const CadHole& h : step.holes)
      if (std::binary_search(h.faces.begin(), h.faces.end(), first)) feature.cad_hole = h;
    return;
  }
  feature.cad_face = step.cad_faces[first];
}

// Throttled progress: the callback sees every surface, the log one line per second. A
// callback returning false cancels the analysis's task group (as a stop request does).
class Progress {
 public:
  Progress(size_t total, const std::function<bool(size_t, size_t)>& callback,
           tbb::task_group_context& ctx, spdlog::logger& log)
      : total_(total), callback_(callback), ctx_(ctx), log_(log), start_(Clock::now()) {}

  void tick() {
    size_t done = ++done_;
    if (callback_ && !callback_(done, total_)) ctx_.cancel_group_execution();
    auto now = Clock::now();
    auto last = last_log_.load();
    if (now - start_ > std::chrono::seconds(2) && now - last > std::chrono::seconds(1) &&
        last_log_.compare_exchange_strong(last, now)) {
      log_.info("visibility maps: {}/{} surfaces, {:.1f} s", done, total_, seconds_since(start_));
    }
  }

 private:
  size_t total_;
  const std::function<bool(size_t, size_t)>& callback_;
  tbb::task_group_context& ctx_;
  spdlog::logger& log_;
  Clock::time_point start_;
  std::atomic<size_t> done_{0};
  std::atomic<Clock::time_point> last_log_{};
};

bool is_step(const AnalyzeRequest& request) {
  if (request.part_bytes) return request.part_format == MeshFormat::kStep;
  const size_t dot = request.part_path.rfind('.');
  return dot != std::string::npos && parse_mesh_format(request.part_path.substr(dot)) == MeshFormat::kStep;
}

StepOptions step_options(const v1::StepOptions& o) {
  StepOptions out;
  out.linear_deflection = o.linear_deflection();
  if (o.angular_deflection_degrees() > 0) out.angular_deflection_degrees = o.angular_deflection_degrees();
  if (o.has_solid()) out.solid = static_cast<int>(o.solid());
  out.group_holes = o.group_holes();
  out.faithful = !o.brepmesh_only();
  out.max_memory_bytes = uint64_t(o.reader_memory_mb()) << 20;
  out.max_seconds = o.reader_seconds();
  return out;
}

// A STEP part: tessellated and welded by topology; its B-rep faces become the features
// unless the request asks for the mesh-based ones (or gives its own groups).
StatusOr<RawMesh> read_step_part(const AnalyzeRequest& request, std::optional<StepPart>& step) {
  StepOptions options = step_options(request.options.step());
  options.stop = request.stop;
  options.max_triangles = request.max_faces;  // checked before the mesh is built
  StatusOr<StepPart> read =
      request.part_bytes ? read_step(*request.part_bytes, options, part_name(request)) : read_step(request.part_path, options);
  if (!read.ok()) return read.status();
  step.emplace(std::move(*read));
  RawMesh raw = std::move(step->mesh);  // the rest of `step` names the B-rep faces
  if (request.options.step().features() != v1::STEP_FEATURES_AUTO) raw.groups = brep_face_groups(*step);
  return raw;
}

StatusOr<RawMesh> read_input(const AnalyzeRequest& request, std::optional<StepPart>& step) {
  if (is_step(request)) return read_step_part(request, step);
  return request.part_bytes ? read_raw_mesh(*request.part_bytes, request.part_format, part_name(request))
                            : read_raw_mesh(request.part_path);
}

// The part as the engine works on it: validated and analysed at its canonical scale (its
// largest coordinate in [1, 2), exactly: see mesh/exact_scale.h); `scale_exponent` says how
// far it was scaled.
StatusOr<Part> read_part(const AnalyzeRequest& request, RawMesh& raw, std::optional<StepPart>& step,
                         AnalysisTiming& timing, int& scale_exponent) {
  auto t0 = Clock::now();
  StatusOr<RawMesh> read = read_input(request, step);
  if (!read.ok()) return read.status();
  raw = std::move(*read);
  timing.read = seconds_since(t0);
  scale_exponent = mesh_internal::magnitude_exponent(raw.points);
  if (request.max_faces > 0 && raw.faces.size() > request.max_faces) {
    return ResourceExhausted(raw.source + ": " + std::to_string(raw.faces.size()) +
                             " faces, more than the limit of " + std::to_string(request.max_faces));
  }
  interruption_point();
  if (!mesh_internal::scale_exactly(raw.points, scale_exponent)) {
    return InvalidArgument(raw.source + ": the coordinates span more than the doubles can hold once the part is "
                           "scaled to its size (nonzero coordinates more than 2^1000 apart)");
  }

  t0 = Clock::now();
  StatusOr<SolidMesh> solid = build_solid(raw);
  interruption_point();  // a cancelled validation may have stopped short
  if (!solid.ok()) return solid.status();
  timing.validate = seconds_since(t0);

  t0 = Clock::now();
  PartOptions part_options;
  if (request.options.feature_angle_degrees() > 0) {
    part_options.feature_angle_degrees = request.options.feature_angle_degrees();
  }
  if (!request.groups_json.empty() || !request.groups_path.empty()) {
    auto groups = !request.groups_json.empty()
                      ? parse_face_groups(request.groups_json, solid->input_face_count, "face groups")
                      : read_face_groups(request.groups_path, solid->input_face_count);
    if (!groups.ok()) return groups.status();
    part_options.face_groups = std::move(*groups);
  } else {
    part_options.face_groups = solid->groups;
  }
  StatusOr<Part> part = Part::analyze(std::move(*solid), part_options);
  interruption_point();
  timing.part = seconds_since(t0);
  return part;
}

// The surfaces, every region then every feature, without their maps.
std::vector<Surface> surfaces_of(const Part& part, std::vector<std::span<const uint32_t>>& triangles) {
  const SolidMesh& mesh = part.mesh();
  std::vector<Surface> out;
  for (const ConcaveRegion& r : part.regions()) {
    Surface s;
    s.kind = Surface::Kind::kRegion;
    s.id = r.id;
    s.is_void = r.is_void;
    s.faces = input_faces(mesh, r.triangles);
    s.planar_normal = common_plane_normal(mesh, r.triangles);
    out.push_back(std::move(s));
    triangles.emplace_back(r.triangles);
  }
  for (const Feature& f : part.features()) {
    Surface s;
    s.id = f.id;
    s.name = f.name;
    s.on_hull = f.on_hull;
    s.automatic = f.automatic;
    s.region = f.region;
    s.faces = input_faces(mesh, f.triangles);
    s.planar_normal = common_plane_normal(mesh, f.triangles);
    if (f.region >= 0) out[f.region].features.push_back(f.id);
    out.push_back(std::move(s));
    triangles.emplace_back(f.triangles);
  }
  return out;
}

// The whole analysis, inside the caller's task arena (so --threads bounds every phase) and
// in a task of the cancellable group `ctx`; throws Interrupted once that is cancelled.
StatusOr<Analysis> analyze_in_arena(const AnalyzeRequest& request, int threads,
                                    tbb::task_group_context& ctx, spdlog::logger& log) {
  const auto t_start = Clock::now();
  AnalysisTiming timing;
  RawMesh raw;
  std::optional<StepPart> step;
  int scale_exponent = 0;
  StatusOr<Part> part = read_part(request, raw, step, timing, scale_exponent);
  if (!part.ok()) return part.status();
  auto impl = std::make_shared<Analysis::Impl>(std::move(*part));
  impl->options = request.options;
  impl->input_mesh = impl->part.mesh();  // back at the file's scale, for drawing and summaries
  mesh_internal::scale_exactly(impl->input_mesh.points, -scale_exponent);
  impl->summary = summarize(raw, impl->part, impl->input_mesh, step);

  std::vector<std::span<const uint32_t>> triangles;
  std::vector<Surface> surfaces = surfaces_of(impl->part, triangles);
  for (Surface& s : surfaces) {
    if (step && s.kind == Surface::Kind::kFeature) describe_cad(s, *step);
  }
  const auto t0 = Clock::now();
  timing.threads = static_cast<uint32_t>(threads);
  const OcclusionMethod method = method_of(request.options);
  Progress progress(surfaces.size(), request.progress, ctx, log);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, surfaces.size(), 1),
                    [&](const tbb::blocked_range<size_t>& range) {
                      for (size_t i = range.begin(); i != range.end(); ++i) {
                        interruption_point();
                        auto ts = Clock::now();
                        // Isolated: a thread waiting in this surface's inner loops helps
                        // with them only. Else it could take up another surface there and
                        // finish it first, holding this one back (the largest surface of a
                        // part is its critical path) and counting its time twice.
                        SurfaceVisibility vis = tbb::this_task_arena::isolate([&] {
                          return compute_surface_visibility(impl->part, triangles[i],
                                                            !request.options.lvm_only(), method);
                        });
                        surfaces[i].maps =
                            surface_maps(impl->part.mesh(), std::move(vis), seconds_since(ts));
                        const SurfaceStatistics& st = surfaces[i].maps.statistics;
                        log.debug("{} {}: |S| {} |O_S| {}, maps in {:.2f} s",
                                  surfaces[i].kind == Surface::Kind::kRegion ? "region" : "feature",
                                  surfaces[i].id, triangles[i].size(), st.potential_occluders, st.seconds);
                        progress.tick();
                      }
                    });
  interruption_point();  // surfaces left undone when cancelled
  timing.visibility = seconds_since(t0);

  const size_t region_count = impl->part.regions().size();
  for (const Surface& s : surfaces) {
    impl->surfaces_with_potential_occluders += s.maps.statistics.potential_occluders > 0;
  }
  impl->regions.assign(std::make_move_iterator(surfaces.begin()),
                       std::make_move_iterator(surfaces.begin() + region_count));
  impl->features.assign(std::make_move_iterator(surfaces.begin() + region_count),
                        std::make_move_iterator(surfaces.end()));
  timing.total = seconds_since(t_start);
  impl->timing = timing;
  return Analysis(std::move(impl));
}

Status validate_step(const v1::StepOptions& step) {
  if (!(std::isfinite(step.linear_deflection()) && step.linear_deflection() >= 0)) {
    return InvalidArgument("step.linear_deflection must be a length in mm > 0 (0: the default), not " +
                           std::to_string(step.linear_deflection()));
  }
  const double angle = step.angular_deflection_degrees();
  if (!(std::isfinite(angle) && angle >= 0 && angle < 90)) {
    return InvalidArgument("step.angular_deflection_degrees must be an angle in degrees, 0 < DEG < 90 (0: the default), not " +
                           std::to_string(angle));
  }
  if (!(std::isfinite(step.reader_seconds()) && step.reader_seconds() >= 0)) {
    return InvalidArgument("step.reader_seconds must be a number of seconds > 0 (0: the default), not " +
                           std::to_string(step.reader_seconds()));
  }
  if (step.reader_memory_mb() > 0 && step.reader_memory_mb() < 64) {
    return InvalidArgument("step.reader_memory_mb must be at least 64 MiB (0: the default), not " +
                           std::to_string(step.reader_memory_mb()));
  }
  if (!v1::StepFeatures_IsValid(step.features())) {
    return InvalidArgument("step.features " + std::to_string(step.features()) + " is not brep or auto");
  }
  if (step.group_holes() && step.features() == v1::STEP_FEATURES_AUTO) {
    return InvalidArgument("step.group_holes (--group-holes) groups B-rep faces: it needs step.features brep (--features brep), not auto");
  }
  return Status::Ok();
}

}  // namespace

Status validate(const v1::AnalyzeOptions& options) {
  const double angle = options.feature_angle_degrees();
  if (!(std::isfinite(angle) && angle >= 0 && angle < 180)) {
    return InvalidArgument("feature_angle_degrees must be an angle in degrees, 0 < DEG < 180 (0: the default), not " +
                           std::to_string(angle));
  }
  if (options.threads() > 1024) {
    return InvalidArgument("threads must be from 0 (all cores) to 1024, not " + std::to_string(options.threads()));
  }
  if (!v1::OcclusionMethod_IsValid(options.occlusion_method())) {
    return InvalidArgument("occlusion_method " + std::to_string(options.occlusion_method()) + " is not a method");
  }
  return validate_step(options.step());
}

StatusOr<SolidMesh> load_part_solid(const AnalyzeRequest& request) {
  if (Status s = validate(request.options); !s.ok()) return s;
  std::optional<StepPart> step;
  StatusOr<RawMesh> raw = read_input(request, step);
  if (!raw.ok()) return raw.status();
  return build_solid(*raw);
}

StatusOr<Analysis> analyze(const AnalyzeRequest& request) {
  if (Status s = validate(request.options); !s.ok()) return s;
  const int threads = arena_threads(static_cast<int>(request.options.threads()));
  const std::shared_ptr<spdlog::logger> log =
      request.logger ? request.logger : spdlog::default_logger();
  return cancellable_run<Analysis>(threads, request.stop, "analysis cancelled",
                                   [&](tbb::task_group_context& ctx) {
                                     return analyze_in_arena(request, threads, ctx, *log);
                                   });
}

}  // namespace gvm
