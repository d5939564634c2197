#include "bench_rays.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/geometric.hpp>

#include "common/error.h"
#include "common/stopwatch.h"
#include "common/function_ref.h"
#include "common/thread_pool.h"
#include "ray/camera_rays.h"
#include "ray/traced_scene.h"
#include "scene/memory_budget.h"

#if FACET_HAVE_EMBREE == 3
#include <embree3/rtcore.h>
#elif FACET_HAVE_EMBREE == 4
#include <embree4/rtcore.h>
#endif

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;
constexpr std::size_t kChunk = 256;  // rays a worker takes at a time

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

// trace(k) for every ray k, chunk by chunk on the pool; the milliseconds it took.
double timed(ThreadPool& pool, std::size_t count, FunctionRef<void(std::size_t)> trace) {
  const auto start = Clock::now();
  std::atomic<std::size_t> next{0};
  pool.run([&](int) {
    for (std::size_t begin = next.fetch_add(kChunk); begin < count; begin = next.fetch_add(kChunk))
      for (std::size_t k = begin; k < std::min(begin + kChunk, count); ++k) trace(k);
  });
  return millisecondsSince(start);
}

// The three kinds of ray, the same for every tracer: a primary ray through
// each pixel's centre; from each primary hit a shadow ray toward the first
// light and a ray reflected about the geometric normal (the incoherent kind).
struct RaySet {
  std::vector<ray::Ray> primary, shadow, secondary;
};

RaySet raysOf(const ray::TracedScene& traced, const FrameInputs& frame) {
  RaySet set;
  const ray::CameraRays camera(frame);
  for (int y = 0; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x) set.primary.push_back(camera.at(x, y));
  const float offset = frame.ray.epsilon * frame.sceneRadius;
  for (const ray::Ray& r : set.primary) {
    ray::Hit hit;
    if (!traced.bvh().intersect(r, hit)) continue;
    const glm::vec3 P = traced.pointOf(hit, r), Ng = traced.geometricNormal(hit, P);
    const auto leaving = [&](glm::vec3 d) {
      ray::Ray out;
      out.origin = P + (glm::dot(Ng, d) >= 0.0f ? offset : -offset) * Ng;
      out.direction = d;
      return out;
    };
    if (!frame.lights.empty()) {
      const Light& light = frame.lights.front().light;
      if (light.kind == LightKind::Directional) {
        set.shadow.push_back(leaving(-light.direction));
      } else {
        ray::Ray s = leaving(light.position - P);
        s.direction = light.position - s.origin;
        s.tMax = 1.0f;
        set.shadow.push_back(s);
      }
    }
    const glm::vec3 D = glm::normalize(r.direction);
    set.secondary.push_back(leaving(D - 2.0f * glm::dot(D, Ng) * Ng));
  }
  return set;
}

struct Rates {
  double primary = 0, shadow = 0, secondary = 0;  // million rays per second
  double buildMilliseconds = 0;
  std::size_t bytes = 0;
};

double mrays(std::size_t count, double milliseconds) { return milliseconds > 0 ? static_cast<double>(count) / (milliseconds * 1e3) : 0.0; }

#if FACET_HAVE_EMBREE
// The same primitives in Embree: the triangles as one triangle mesh, the spheres as sphere points.
class EmbreePeer {
 public:
  explicit EmbreePeer(const ray::Primitives& p) : device_(rtcNewDevice(nullptr)) {
    if (!device_) throw Error("bench: Embree could not start a device");
    scene_ = rtcNewScene(device_);
    if (p.triangleCount() > 0) {
      RTCGeometry mesh = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      auto* vertices = static_cast<float*>(
          rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), p.triangleCorners.size()));
      auto* indices = static_cast<unsigned*>(
          rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), p.triangleCount()));
      for (std::size_t k = 0; k < p.triangleCorners.size(); ++k)
        for (int c = 0; c < 3; ++c) vertices[3 * k + static_cast<std::size_t>(c)] = p.triangleCorners[k][c];
      for (std::size_t k = 0; k < p.triangleCorners.size(); ++k) indices[k] = static_cast<unsigned>(k);
      rtcCommitGeometry(mesh);
      rtcAttachGeometryByID(scene_, mesh, 0);
      rtcReleaseGeometry(mesh);
    }
    if (p.sphereCount() > 0) {
      RTCGeometry spheres = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
      auto* points = static_cast<float*>(
          rtcSetNewGeometryBuffer(spheres, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), p.sphereCount()));
      for (std::size_t k = 0; k < p.sphereCount(); ++k)
        for (int c = 0; c < 4; ++c) points[4 * k + static_cast<std::size_t>(c)] = p.spheres[k][c];
      rtcCommitGeometry(spheres);
      rtcAttachGeometryByID(scene_, spheres, 1);
      rtcReleaseGeometry(spheres);
    }
    triangles_ = static_cast<unsigned>(p.triangleCount());
    const auto start = Clock::now();
    rtcCommitScene(scene_);
    buildMilliseconds_ = millisecondsSince(start);
  }
  ~EmbreePeer() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  EmbreePeer(const EmbreePeer&) = delete;
  EmbreePeer& operator=(const EmbreePeer&) = delete;

  double buildMilliseconds() const { return buildMilliseconds_; }

  // The primitive hit (facet's numbering), or -1.
  long intersect(const ray::Ray& r) const {
    RTCRayHit h;
    set(h.ray, r);
    h.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    h.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
#if FACET_HAVE_EMBREE == 3
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcIntersect1(scene_, &context, &h);
#else
    rtcIntersect1(scene_, &h);  // Embree 4 dropped the context argument (its arguments struct is optional)
#endif
    if (h.hit.geomID == RTC_INVALID_GEOMETRY_ID) return -1;
    return h.hit.geomID == 0 ? static_cast<long>(h.hit.primID) : static_cast<long>(triangles_ + h.hit.primID);
  }
  bool occluded(const ray::Ray& r) const {
    RTCRay ray;
    set(ray, r);
#if FACET_HAVE_EMBREE == 3
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcOccluded1(scene_, &context, &ray);
#else
    rtcOccluded1(scene_, &ray);
#endif
    return ray.tfar < 0.0f;
  }

 private:
  static void set(RTCRay& out, const ray::Ray& r) {
    out.org_x = r.origin.x, out.org_y = r.origin.y, out.org_z = r.origin.z;
    out.dir_x = r.direction.x, out.dir_y = r.direction.y, out.dir_z = r.direction.z;
    out.tnear = r.tMin;
    out.tfar = r.tMax;
    out.time = 0.0f;
    out.mask = ~0u;
    out.id = 0;
    out.flags = 0;
  }

  RTCDevice device_;
  RTCScene scene_ = nullptr;
  unsigned triangles_ = 0;
  double buildMilliseconds_ = 0;
};
#endif

}  // namespace

void printRayRates(const Scene& scene, const FrameInputs& frame, int threads, int frames) {
  ThreadPool pool(threads);
  std::vector<double> builds;
  std::unique_ptr<ray::TracedScene> traced;
  for (int i = 0; i < frames; ++i) {
    traced.reset();
    const auto start = Clock::now();
    traced = std::make_unique<ray::TracedScene>(scene, frame, frame.ray.spheres, pool);
    builds.push_back(millisecondsSince(start));
  }
  const RaySet rays = raysOf(*traced, frame);
  const ray::Bvh& bvh = traced->bvh();
  Rates facet;
  facet.buildMilliseconds = median(builds);
  facet.bytes = traced->bytes();
  std::vector<double> primary, shadow, secondary;
  std::vector<long> facetHits(rays.primary.size());
  for (int i = 0; i < frames; ++i) {
    primary.push_back(timed(pool, rays.primary.size(), [&](std::size_t k) {
      ray::Hit hit;
      facetHits[k] = bvh.intersect(rays.primary[k], hit) ? static_cast<long>(hit.primitive) : -1;
    }));
    shadow.push_back(timed(pool, rays.shadow.size(), [&](std::size_t k) { (void)bvh.occluded(rays.shadow[k]); }));
    secondary.push_back(timed(pool, rays.secondary.size(), [&](std::size_t k) {
      ray::Hit hit;
      (void)bvh.intersect(rays.secondary[k], hit);
    }));
  }
  facet.primary = mrays(rays.primary.size(), median(primary));
  facet.shadow = mrays(rays.shadow.size(), median(shadow));
  facet.secondary = mrays(rays.secondary.size(), median(secondary));
  std::printf("  ray   BVH: %zu nodes, %s, built in %.2f ms (median of %d, %d thread(s))\n", bvh.stats().nodes, byteCount(facet.bytes).c_str(),
              facet.buildMilliseconds, frames, threads);
  std::printf("  ray   %-9s %9s %12s %13s %9s\n", "rays", "count", "facet Mray/s", "embree Mray/s", "facet/em");
#if FACET_HAVE_EMBREE
  EmbreePeer embree(traced->primitives());
  std::vector<double> ePrimary, eShadow, eSecondary;
  std::vector<long> embreeHits(rays.primary.size());
  for (int i = 0; i < frames; ++i) {
    ePrimary.push_back(timed(pool, rays.primary.size(), [&](std::size_t k) { embreeHits[k] = embree.intersect(rays.primary[k]); }));
    eShadow.push_back(timed(pool, rays.shadow.size(), [&](std::size_t k) { (void)embree.occluded(rays.shadow[k]); }));
    eSecondary.push_back(timed(pool, rays.secondary.size(), [&](std::size_t k) { (void)embree.intersect(rays.secondary[k]); }));
  }
  const double embreeRates[3] = {mrays(rays.primary.size(), median(ePrimary)), mrays(rays.shadow.size(), median(eShadow)),
                                 mrays(rays.secondary.size(), median(eSecondary))};
#endif
  const char* kinds[3] = {"primary", "shadow", "secondary"};
  const double facetRates[3] = {facet.primary, facet.shadow, facet.secondary};
  const std::size_t counts[3] = {rays.primary.size(), rays.shadow.size(), rays.secondary.size()};
  for (int k = 0; k < 3; ++k) {
#if FACET_HAVE_EMBREE
    std::printf("  ray   %-9s %9zu %12.2f %13.2f %9.2f\n", kinds[k], counts[k], facetRates[k], embreeRates[k],
                embreeRates[k] > 0 ? facetRates[k] / embreeRates[k] : 0.0);
#else
    std::printf("  ray   %-9s %9zu %12.2f %13s %9s\n", kinds[k], counts[k], facetRates[k], "-", "-");
#endif
  }
#if FACET_HAVE_EMBREE
  std::size_t same = 0;
  for (std::size_t k = 0; k < facetHits.size(); ++k) same += facetHits[k] == embreeHits[k] ? 1 : 0;
  std::printf("  ray   Embree built in %.2f ms; the same primitive for %zu of %zu primary rays (%.3f%%)\n", embree.buildMilliseconds(), same,
              facetHits.size(), facetHits.empty() ? 100.0 : 100.0 * static_cast<double>(same) / static_cast<double>(facetHits.size()));
#else
  std::printf("  ray   Embree: not in this build (install libembree-dev and configure again for the peer column)\n");
#endif
}

}  // namespace facet
