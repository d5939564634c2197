#include "ray/ray_tracer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <glm/geometric.hpp>

#include "shading/alpha_mask.h"
#include "shading/blending.h"
#include "shading/environment.h"
#include "shading/fog.h"
#include "shading/lit_programs.h"
#include "shading/transform.h"
#include "ray/camera_rays.h"
#include "ray/optics.h"

namespace facet::ray {
namespace {

float largest(glm::vec3 v) { return std::max({v.x, v.y, v.z}); }

}  // namespace

void RayStatistics::add(const RayStatistics& o) {
  primary += o.primary, shadow += o.shadow, reflected += o.reflected, transmitted += o.transmitted;
  totalInternal += o.totalInternal, continued += o.continued;
  stoppedByDepth += o.stoppedByDepth, stoppedByContribution += o.stoppedByContribution;
  depthSum += o.depthSum;
  maxDepth = std::max(maxDepth, o.maxDepth);
}

std::string RayStatistics::summary() const {
  const std::uint64_t traced = primary + reflected + transmitted;
  char text[400];
  std::snprintf(text, sizeof text,
                "ray tree: %llu primary, %llu shadow, %llu reflected, %llu transmitted (%llu total internal reflections), %llu past blended "
                "surfaces; depth mean %.3f, max %d; not traced: %llu at ray.depth, %llu below ray.minContribution",
                static_cast<unsigned long long>(primary), static_cast<unsigned long long>(shadow), static_cast<unsigned long long>(reflected),
                static_cast<unsigned long long>(transmitted), static_cast<unsigned long long>(totalInternal),
                static_cast<unsigned long long>(continued), traced ? static_cast<double>(depthSum) / static_cast<double>(traced) : 0.0, maxDepth,
                static_cast<unsigned long long>(stoppedByDepth), static_cast<unsigned long long>(stoppedByContribution));
  return text;
}

float shadowFactorLanes(const TracedShadows& shadows, const FrameLight& light, const ShadowSettings&, glm::vec3 P, glm::vec3, glm::vec3,
                        bool) {
  return shadows.tracer->shadowFactor(light, P, shadows.geometricNormal, *shadows.sampler, *shadows.statistics);
}

// Where a ray is in its tree.
struct RayTracer::Path {
  int depth = 1;                       // the primary ray's level is 1
  glm::vec3 weight{1.0f};              // the product of k_r or k_t along the way
  glm::vec3 medium{0.0f};              // σ of the medium the ray travels in (Beer's law); 0 outside
  bool primary = true;                 // the eye's ray, or its continuation past blended surfaces: culled, fogged, the pixel's background
  bool continuation = false;           // going on past a blended surface: the same level, not counted again
  int px = 0, py = 0;                  // the pixel, for its background
  glm::vec2 offset{0.0f};
  const RayDifferentials* differentials = nullptr;  // primary hits: the neighbouring pixels' rays
  PathSampler* sampler = nullptr;      // the path's random numbers
};

RayTracer::RayTracer(const TracedScene& scene, const FrameInputs& frame)
    : scene_(scene), frame_(frame), camera_(frame), offset_(frame.ray.epsilon * frame.sceneRadius), focus_(frame.camera.focusDistance) {
  if (focus_ > 0.0f || !(frame.camera.aperture > 0.0f)) return;
  Hit hit;
  const Ray centre = centreRay(frame);
  focus_ = nearestHit(centre, true, hit) ? hit.t : (frame.eyeFromWorld * glm::vec4(frame.camera.reference, 1.0f)).z;
}

Ray RayTracer::leaving(glm::vec3 P, glm::vec3 Ng, glm::vec3 direction) const {
  Ray ray;
  ray.origin = P + (glm::dot(Ng, direction) >= 0.0f ? offset_ : -offset_) * Ng;
  ray.direction = direction;
  return ray;
}

bool RayTracer::nearestHit(const Ray& ray, bool primary, Hit& hit, bool throughBlended) const {
  return scene_.bvh().intersect(ray, hit, [&](const Hit& candidate) {
    if (primary && scene_.instanceOf(frame_, candidate.primitive).cullBackFaces && !scene_.frontFacing(candidate, ray)) return false;
    const CourseMaterial& material = *scene_.drawOf(candidate.primitive).material;
    if (throughBlended && material.blended) return false;
    return !material.masked || alphaKept(material, scene_.alphaAt(candidate, ray));
  });
}

float RayTracer::shadowFactor(const FrameLight& light, glm::vec3 P, glm::vec3 Ng, PathSampler& sampler, RayStatistics& statistics) const {
  if (!light.hasShadowMap) return 1.0f;
  ++statistics.shadow;
  const Light& l = light.light;
  const bool directional = l.kind == LightKind::Directional;
  // The point aimed at: the light's centre, or for an area light a point of its disk facing P
  // (a sphere's silhouette), or a direction in a directional light's cone.
  glm::vec3 target = l.position, direction = -l.direction;
  if (l.radius > 0.0f) {
    if (directional) {
      direction = uniformCone(-l.direction, std::cos(l.radius * std::numbers::pi_v<float> / 180.0f), sampler.uniform2());
    } else {
      glm::vec3 a, b;
      frameAround(normalize3(P - l.position), a, b);
      const glm::vec2 d = diskPoint(sampler.uniform2());
      target = l.position + l.radius * (d.x * a + d.y * b);
    }
  }
  Ray ray = leaving(P, Ng, directional ? direction : target - P);
  if (!directional) {
    ray.direction = target - ray.origin;  // t = 1 at the light
    ray.tMax = 1.0f;
  }
  float S = 1.0f;
  scene_.bvh().forEachHit(ray, [&](const Hit& hit) {
    const CourseMaterial& material = *scene_.drawOf(hit.primitive).material;
    if (!material.castsShadow) return false;  // as the shadow maps leave it out
    // The shadow pass's alpha test (blended: transparency.shadowCutoff): what it discards casts nothing.
    if ((material.masked || material.blended) && !alphaKept(material, scene_.alphaAt(hit, ray))) return false;
    S = material.transmission > 0.0f ? S * material.transmission : 0.0f;
    return !(S > 0.0f);  // an opaque surface ends the search
  });
  return S;
}

glm::vec4 RayTracer::trace(const Ray& ray, const Path& path, RayStatistics& statistics) const {
  if (!path.continuation) {
    statistics.depthSum += static_cast<std::uint64_t>(path.depth);
    statistics.maxDepth = std::max(statistics.maxDepth, path.depth);
  }
  Hit hit;
  if (!nearestHit(ray, path.primary, hit)) {
    if (path.primary) return stored(backgroundAt(frame_, path.px, path.py, path.offset), frame_.backgroundAlpha, Blending::Straight);
    const glm::vec3 D = normalize3(ray.direction);
    return glm::vec4(frame_.environment.map ? environmentAt(*frame_.environment.map, D, 0) : frame_.background, 1.0f);
  }
  const DrawUniforms& base = scene_.drawOf(hit.primitive);
  const CourseMaterial& material = *base.material;
  const glm::vec3 P = scene_.pointOf(hit, ray);
  const glm::vec3 Ng = scene_.geometricNormal(hit, P);
  SurfacePoint p = scene_.surfaceAt(hit, ray, path.differentials);
  const bool sphere = scene_.primitives().isSphere(hit.primitive);
  const FrameInstance& instance = scene_.instanceOf(frame_, hit.primitive);

  // The recursive terms' coefficients and directions first: k_r = reflectivity·O_s, k_t, and
  // Snell's law with Fresnel's share or total internal reflection; then which rays are traced.
  const float kt = std::clamp(material.transmission, 0.0f, 1.0f);
  glm::vec3 kr{0.0f}, R{0.0f}, T{0.0f};
  float kTransmit = 0.0f;
  if (material.reflectivity > 0.0f || kt > 0.0f) {
    const glm::vec3 D = normalize3(ray.direction);
    // The normal the rays turn about, facing the incoming ray (the geometric one where the interpolated one does not).
    glm::vec3 N = interpolatesNormals(frame_.shading) && !sphere ? LitPhongProgram::shadingNormal(base, p) : (p.front ? Ng : -Ng);
    if (!(glm::dot(N, D) < 0.0f)) N = glm::dot(Ng, D) < 0.0f ? Ng : -Ng;
    const float m = material.metallic;
    kr = material.reflectivity * (glm::vec3(1.0f - m) + m * baseColorAt(base, p));
    kTransmit = kt;
    if (kt > 0.0f) {
      // Snell's law from n1 into n2: entering through a front face, leaving through a back one.
      const float n1 = p.front ? 1.0f : material.ior, n2 = p.front ? material.ior : 1.0f;
      const std::optional<Refraction> refraction = refracted(D, N, n1, n2);
      if (!refraction) {  // total internal reflection: the transmitted share reflects
        ++statistics.totalInternal;
        kr = kr + glm::vec3(kt);
        kTransmit = 0.0f;
      } else {
        T = refraction->T;
        const float F = fresnelSchlick(n1, n2, -glm::dot(D, N), refraction->cosTransmitted);
        kr = kr + glm::vec3(kt * F);
        kTransmit = kt * (1.0f - F);
        // Translucency: the transmitted ray spread over the Phong lobe of the surface's n about T (below the surface only).
        if (frame_.ray.translucency) {
          const glm::vec3 spread = phongLobe(T, material.shininess, path.sampler->uniform2());
          if (glm::dot(spread, N) < 0.0f) T = spread;
        }
      }
    }
    R = reflected(D, N);
    // Gloss: the reflected ray spread likewise about R (above the surface only).
    if (frame_.ray.gloss && largest(kr) > 0.0f) {
      const glm::vec3 spread = phongLobe(R, material.shininess, path.sampler->uniform2());
      if (glm::dot(spread, N) > 0.0f) R = spread;
    }
  }
  // A ray is traced below ray.depth and at a weight of at least ray.minContribution.
  const auto traced = [&](bool wanted, glm::vec3 weight) {
    if (!wanted) return false;
    if (path.depth >= frame_.ray.depth) {
      ++statistics.stoppedByDepth;
      return false;
    }
    if (largest(path.weight * weight) < frame_.ray.minContribution) {
      ++statistics.stoppedByContribution;
      return false;
    }
    return true;
  };
  const bool reflects = traced(largest(kr) > 0.0f, kr), transmits = traced(kTransmit > 0.0f, glm::vec3(kTransmit));

  // The local term: a surface loses the diffuse share it reflects or transmits as a traced ray, k_a and
  // k_d times (1 - reflectivity) and (1 - k_t); its highlights stay. Where no ray is traced it keeps all of it.
  DrawUniforms draw = base;
  CourseMaterial shared;
  const float keep = (reflects ? 1.0f - material.reflectivity : 1.0f) * (transmits ? 1.0f - kt : 1.0f);
  if (keep < 1.0f) {
    shared = material;
    shared.ka = shared.ka * keep;
    shared.kd = shared.kd * keep;
    draw.material = &shared;
    draw.summed = laneMaterial(shared, draw.emissiveMap ? glm::vec3(0.0f) : shared.emissive);
  }
  TracedShadows shadows{this, Ng, &statistics, path.sampler};
  if (!interpolatesNormals(frame_.shading) && !sphere) {
    // Gouraud lights the triangle's vertices and weights them by the barycentrics; flat lights its centroid.
    const glm::vec3* corner = &scene_.primitives().triangleCorners[3 * static_cast<std::size_t>(hit.primitive)];
    if (frame_.shading == ShadingMode::Flat) {
      p.lit = LitFlatProgram::faceSide(draw, shadows, corner[0], corner[1], corner[2], p.front);
    } else {
      const Mesh& mesh = *base.mesh;
      const DrawMatrices matrices = drawMatrices(instance);
      const std::uint32_t* index = &mesh.indices[scene_.primitive(hit.primitive).first];
      const float w[3] = {1.0f - hit.u - hit.v, hit.u, hit.v};
      Illumination sum;
      for (int k = 0; k < 3; ++k) {
        const Illumination I = LitGouraudProgram::vertexSide(draw, shadows, corner[k], worldNormal(matrices, mesh, index[k]), p.front);
        sum.diffuse = sum.diffuse + w[k] * I.diffuse;
        sum.specular = sum.specular + w[k] * I.specular;
      }
      p.lit = sum;
    }
  } else if (!interpolatesNormals(frame_.shading)) {
    // A traced sphere has no vertices or facets: every mode lights it at the hit.
    p.lit = illuminate(frame_, shadows, draw.summed, P, p.front ? p.normal : -p.normal, viewVector<float>(frame_, P));
  }
  glm::vec3 color = litFragment(draw, shadows, p);

  // The recursive terms k_r·I_r + k_t·I_t.
  Path next;
  next.depth = path.depth + 1;
  next.primary = false;
  next.sampler = path.sampler;
  if (reflects) {
    ++statistics.reflected;
    next.weight = path.weight * kr;
    next.medium = path.medium;
    color = color + kr * glm::vec3(trace(leaving(P, Ng, R), next, statistics));
  }
  if (transmits) {
    ++statistics.transmitted;
    next.weight = path.weight * kTransmit;
    next.medium = p.front ? material.absorption : glm::vec3(0.0f);  // into the medium, or out of it
    color = color + kTransmit * glm::vec3(trace(leaving(P, Ng, T), next, statistics));
  }
  if (path.primary) color = fogged(frame_.fog, color, (frame_.eyeFromWorld * glm::vec4(P, 1.0f)).z);
  glm::vec4 result(color, 1.0f);
  if (material.blended) {
    // Past a blended surface the same ray goes on; what lies behind is blended under it by the straight equation.
    ++statistics.continued;
    Ray behind = leaving(P, Ng, ray.direction);
    behind.tMax = ray.tMax - hit.t;
    Path onward = path;
    onward.continuation = true;
    const float alpha = scene_.alphaAt(hit, ray);
    onward.weight = material.additive ? path.weight : path.weight * (1.0f - clampUnit(alpha));
    result = blend(trace(behind, onward, statistics), color, alpha, Blending::Straight, material.additive);
  }
  // Beer's law over the distance travelled inside a medium.
  if (largest(path.medium) > 0.0f) {
    const float distance = hit.t * glm::length(ray.direction);
    for (int c = 0; c < 3; ++c) result[c] = result[c] * std::exp(-path.medium[c] * distance);
  }
  return result;
}

glm::vec4 RayTracer::pixel(int px, int py, glm::vec2 offset, PathSampler& sampler, RayStatistics& statistics) const {
  const Ray ray = frame_.camera.aperture > 0.0f ? throughLens(frame_, camera_.at(px, py, offset), diskPoint(sampler.uniform2()), focus_)
                                                : camera_.at(px, py, offset);
  const RayDifferentials differentials{camera_.at(px & ~1, py, offset), camera_.at(px | 1, py, offset),
                                       camera_.at(px, py & ~1, offset), camera_.at(px, py | 1, offset)};
  ++statistics.primary;
  Path path;
  path.px = px, path.py = py, path.offset = offset;
  path.differentials = &differentials;
  path.sampler = &sampler;
  return trace(ray, path, statistics);
}

std::uint32_t RayTracer::visibleTriangle(int px, int py) const {
  const Ray ray = camera_.at(px, py);
  Hit hit;
  // Blended surfaces keep no pixel: they write no depth.
  return nearestHit(ray, true, hit, true) ? scene_.primitive(hit.primitive).frameTriangle + 1 : 0;
}

std::uint32_t RayTracer::surfacesCrossed(int px, int py) const {
  const Ray ray = camera_.at(px, py);
  std::uint32_t count = 0;
  scene_.bvh().forEachHit(ray, [&](const Hit& hit) {
    if (!(scene_.instanceOf(frame_, hit.primitive).cullBackFaces && !scene_.frontFacing(hit, ray))) ++count;
    return false;
  });
  return count;
}

}  // namespace facet::ray
