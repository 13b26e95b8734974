#include "support/ray_sampler.h"

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace gvm::bench {
namespace {

using Vec = std::array<double, 3>;

Vec minus(const Point3& a, const Point3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The scene Embree intersects: the whole part, in floats as every such sampler has it.
class Scene {
 public:
  Scene(const SolidMesh& mesh, unsigned threads) {
    const std::string config = "threads=" + std::to_string(threads);
    device_ = rtcNewDevice(config.c_str());
    if (!device_) throw std::runtime_error("Embree: no device");
    scene_ = rtcNewScene(device_);
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), mesh.points.size()));
    for (size_t i = 0; i < mesh.points.size(); ++i) {
      v[3 * i] = float(mesh.points[i].x), v[3 * i + 1] = float(mesh.points[i].y), v[3 * i + 2] = float(mesh.points[i].z);
    }
    auto* t = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                             3 * sizeof(unsigned), mesh.triangles.size()));
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
      for (int k = 0; k < 3; ++k) t[3 * i + k] = mesh.triangles[i][k];
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene_);
  }
  ~Scene() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  bool blocked(const Vec& origin, const Vec& u, float tnear) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray{};
    ray.org_x = float(origin[0]), ray.org_y = float(origin[1]), ray.org_z = float(origin[2]);
    ray.dir_x = float(u[0]), ray.dir_y = float(u[1]), ray.dir_z = float(u[2]);
    ray.tnear = tnear;
    ray.tfar = std::numeric_limits<float>::infinity();
    ray.mask = ~0u;
    rtcOccluded1(scene_, &context, &ray);
    return ray.tfar < 0;  // Embree sets tfar to -inf on a hit
  }

 private:
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

struct TriangleRays {
  std::vector<Vec> centroid, normal;
};

TriangleRays triangle_rays(const SolidMesh& mesh) {
  TriangleRays r;
  for (const Triangle& t : mesh.triangles) {
    const Point3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
    r.centroid.push_back({(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3});
    r.normal.push_back(cross(minus(b, a), minus(c, a)));
  }
  return r;
}

// Far enough along the ray that floats do not hit the triangle it starts from.
float start_offset(const SolidMesh& mesh) {
  double extent = 0;
  for (const Point3& p : mesh.points) extent = std::max({extent, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  return float(extent * 1e-5);
}

}  // namespace

SampledVisibility sample_visibility(const SolidMesh& mesh, const std::vector<std::vector<uint32_t>>& features,
                                    const std::vector<Vec>& directions, unsigned threads) {
  const auto t0 = std::chrono::steady_clock::now();
  const TriangleRays rays = triangle_rays(mesh);
  const float tnear = start_offset(mesh);
  SampledVisibility out;
  out.seen.resize(directions.size());
  std::vector<uint64_t> rays_cast(directions.size(), 0);
  tbb::task_arena arena(static_cast<int>(threads));
  arena.execute([&] {
    const Scene scene(mesh, threads);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, directions.size()), [&](const tbb::blocked_range<size_t>& range) {
      std::vector<char> open(mesh.triangles.size());  // faces u and its ray escapes
      for (size_t d = range.begin(); d != range.end(); ++d) {
        const Vec& u = directions[d];
        for (size_t t = 0; t < open.size(); ++t) {
          open[t] = dot(rays.normal[t], u) > 0;
          if (open[t]) {
            ++rays_cast[d];
            open[t] = !scene.blocked(rays.centroid[t], u, tnear);
          }
        }
        for (uint32_t f = 0; f < features.size(); ++f) {
          bool seen = true;
          for (uint32_t t : features[f]) seen = seen && open[t];
          if (seen) out.seen[d].push_back(f);
        }
      }
    });
  });
  for (uint64_t n : rays_cast) out.rays += n;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace gvm::bench
