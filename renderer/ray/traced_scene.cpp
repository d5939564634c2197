#include "ray/traced_scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "math/elementary.h"
#include "shading/alpha_mask.h"
#include "shading/lit_programs.h"
#include "shading/transform.h"

namespace facet::ray {
namespace {

// A TM that scales alike on every axis (and does not shear): its columns are
// orthogonal and of one length, so a sphere stays a sphere; that length.
std::optional<float> uniformScale(const glm::mat4& m) {
  const glm::vec3 x(m[0]), y(m[1]), z(m[2]);
  const float lx = glm::length(x), ly = glm::length(y), lz = glm::length(z);
  const float tolerance = 1e-5f * std::max({lx, ly, lz});
  if (!(lx > 0.0f) || std::abs(lx - ly) > tolerance || std::abs(lx - lz) > tolerance) return std::nullopt;
  if (std::abs(glm::dot(x, y)) > tolerance * lx || std::abs(glm::dot(y, z)) > tolerance * lx || std::abs(glm::dot(x, z)) > tolerance * lx)
    return std::nullopt;
  return lx;
}

// The barycentrics (u, v) where the ray meets the plane of p0, p1, p2 (inside
// the triangle or not): the neighbouring pixels' rays of a ray differential.
std::optional<glm::vec2> planeBarycentrics(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, const Ray& ray) {
  const glm::dvec3 e1 = glm::dvec3(p1) - glm::dvec3(p0), e2 = glm::dvec3(p2) - glm::dvec3(p0);
  const glm::dvec3 D(ray.direction), s = glm::dvec3(ray.origin) - glm::dvec3(p0);
  const glm::dvec3 p = glm::cross(D, e2);
  const double det = glm::dot(e1, p);
  if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return std::nullopt;
  const glm::dvec3 q = glm::cross(s, e1);
  return glm::vec2(static_cast<float>(glm::dot(s, p) / det), static_cast<float>(glm::dot(D, q) / det));
}

}  // namespace

TracedScene::TracedScene(const Scene& scene, const FrameInputs& frame, bool spheres, ThreadPool& pool)
    : scene_(&scene), frame_(&frame), sceneToken_(scene.identity.token()), spheres_(spheres) {
  std::uint32_t frameTriangle = 0;
  std::vector<TracedPrimitive> sphereRecords;  // each sphere's instance and its mesh's first triangle in the frame
  for (std::size_t i = 0; i < frame.instances.size(); ++i) {
    const FrameInstance& instance = frame.instances[i];
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
    transforms_.push_back(instance.worldFromModel);
    meshes_.push_back(instance.mesh);
    const auto triangles = static_cast<std::uint32_t>(mesh.indices.size() / 3);
    const std::optional<float> scale = mesh.sphere && spheres ? uniformScale(instance.worldFromModel) : std::nullopt;
    if (scale) {
      TracedSphere s;
      s.center = glm::vec3(transformPoint(instance.worldFromModel, glm::vec3(0.0f)));
      s.radius = *scale;
      s.modelFromWorld = glm::inverse(instance.worldFromModel);
      sphereFrames_.push_back(s);
      sphereRecords.push_back({static_cast<std::uint32_t>(i), frameTriangle, 0});
    } else {
      // The corners the rasterizers' vertex stage computes: TM·p in float.
      for (std::uint32_t t = 0; t < triangles; ++t) {
        for (std::uint32_t k = 0; k < 3; ++k)
          primitives_.triangleCorners.push_back(glm::vec3(transformPoint(instance.worldFromModel, mesh.positions[mesh.indices[3 * t + k]])));
        traced_.push_back({static_cast<std::uint32_t>(i), frameTriangle + t, 3 * t});
      }
    }
    frameTriangle += triangles;
  }
  // Spheres after every triangle: the primitives' numbering (primitives.h).
  for (std::size_t k = 0; k < sphereFrames_.size(); ++k) {
    primitives_.spheres.push_back(glm::vec4(sphereFrames_[k].center, sphereFrames_[k].radius));
    traced_.push_back(sphereRecords[k]);
  }
  checkPrimitiveCounts(primitives_.triangleCorners.size(), primitives_.spheres.size());
  bvh_ = Bvh(primitives_, pool);
  bind(scene, frame);
}

bool TracedScene::builtFrom(const Scene& scene, const FrameInputs& frame, bool spheres) const {
  if (!scene.identity.is(sceneToken_) || spheres != spheres_ || frame.instances.size() != transforms_.size()) return false;
  for (std::size_t i = 0; i < frame.instances.size(); ++i)
    if (frame.instances[i].mesh != meshes_[i] || frame.instances[i].worldFromModel != transforms_[i]) return false;
  return true;
}

void TracedScene::bind(const Scene& scene, const FrameInputs& frame) {
  scene_ = &scene;
  frame_ = &frame;
  draws_.clear();
  for (const FrameInstance& instance : frame.instances) draws_.push_back(drawUniforms(scene, frame, instance));
}

glm::vec3 TracedScene::geometricNormal(const Hit& hit, glm::vec3 P) const {
  if (primitives_.isSphere(hit.primitive)) {
    const glm::vec4 s = primitives_.spheres[hit.primitive - primitives_.triangleCount()];
    return normalize3((P - glm::vec3(s)) / s.w);
  }
  const glm::vec3* c = &primitives_.triangleCorners[3 * static_cast<std::size_t>(hit.primitive)];
  return normalize3(cross3(c[1] - c[0], c[2] - c[0]));
}

bool TracedScene::frontFacing(const Hit& hit, const Ray& ray) const {
  if (primitives_.isSphere(hit.primitive)) return glm::dot(geometricNormal(hit, pointOf(hit, ray)), ray.direction) < 0.0f;
  const glm::vec3* c = &primitives_.triangleCorners[3 * static_cast<std::size_t>(hit.primitive)];
  return glm::dot(cross3(c[1] - c[0], c[2] - c[0]), ray.direction) < 0.0f;
}

glm::vec3 TracedScene::pointOf(const Hit& hit, const Ray& ray) const {
  if (primitives_.isSphere(hit.primitive)) return ray.origin + hit.t * ray.direction;
  const glm::vec3* c = &primitives_.triangleCorners[3 * static_cast<std::size_t>(hit.primitive)];
  const float w = 1.0f - hit.u - hit.v;
  return (w * c[0] + hit.u * c[1]) + hit.v * c[2];
}

// The builtin sphere's texture coordinates (scene/primitives.cpp): s = θ/2π
// with θ = atan2(x, z) in [0, 2π), t = φ/π with φ = acos(y), of the model-space direction.
glm::vec2 TracedScene::sphereTexcoords(const TracedSphere& s, glm::vec3 P) const {
  const glm::vec3 d = normalize3(glm::vec3(transformPoint(s.modelFromWorld, P)));
  float theta = elementary::atan2(d.x, d.z);
  if (theta < 0.0f) theta += 2.0f * std::numbers::pi_v<float>;
  return {theta / (2.0f * std::numbers::pi_v<float>), elementary::acos(std::clamp(d.y, -1.0f, 1.0f)) / std::numbers::pi_v<float>};
}

SurfacePoint TracedScene::surfaceAt(const Hit& hit, const Ray& ray, const RayDifferentials* differentials) const {
  const TracedPrimitive& traced = traced_[hit.primitive];
  const FrameInstance& instance = frame_->instances[traced.instance];
  const Mesh& mesh = scene_->meshes[static_cast<std::size_t>(instance.mesh)];
  SurfacePoint p;
  p.front = frontFacing(hit, ray);
  if (primitives_.isSphere(hit.primitive)) {
    const TracedSphere& s = sphereFrames_[hit.primitive - primitives_.triangleCount()];
    p.P = pointOf(hit, ray);
    p.normal = geometricNormal(hit, p.P);
    p.model = glm::vec3(transformPoint(s.modelFromWorld, p.P));
    p.st[0] = p.st[1] = sphereTexcoords(s, p.P);
    // ∂P/∂s along the parallel, the bitangent down the meridian (increasing t).
    const glm::vec3 m = normalize3(p.model);
    p.tangent = glm::vec4(normalize3(transformDirection(glm::mat3(instance.worldFromModel), glm::vec3(m.z, 0.0f, -m.x))), -1.0f);
    if (differentials) {
      // The neighbouring rays met on the tangent plane, their points read as directions from the centre.
      const auto texcoordsThrough = [&](const Ray& r, glm::vec2& st) {
        const float d = glm::dot(p.normal, r.direction);
        if (!(std::abs(d) > 0.0f)) return false;
        const float t = glm::dot(p.normal, p.P - r.origin) / d;
        st = sphereTexcoords(s, r.origin + t * r.direction);
        return std::isfinite(st.x) && std::isfinite(st.y);
      };
      glm::vec2 left, right, below, above;
      if (texcoordsThrough(differentials->left, left) && texcoordsThrough(differentials->right, right) &&
          texcoordsThrough(differentials->below, below) && texcoordsThrough(differentials->above, above)) {
        glm::vec2 dx = right - left, dy = above - below;
        for (glm::vec2* d : {&dx, &dy}) d->x -= std::round(d->x);  // across the seam at s = 0 = 1
        p.derivatives[0] = p.derivatives[1] = glm::vec4(dx.x, dx.y, dy.x, dy.y);
      }
    }
    return p;
  }
  const std::uint32_t* index = &mesh.indices[traced.first];
  const float w[3] = {1.0f - hit.u - hit.v, hit.u, hit.v};
  // Each vertex as the vertex stage computes it, weighted by the barycentrics.
  const auto weighted = [&](auto&& value) {
    auto sum = w[0] * value(index[0]);
    sum = sum + w[1] * value(index[1]);
    return sum + w[2] * value(index[2]);
  };
  p.P = pointOf(hit, ray);
  // The vertex programs' world normal and tangent (shading/lit_programs.h).
  const DrawMatrices matrices = drawMatrices(instance);
  p.normal = weighted([&](std::uint32_t i) { return worldNormal(matrices, mesh, i); });
  p.model = weighted([&](std::uint32_t i) { return mesh.positions[i]; });
  if (!mesh.colors.empty()) p.color = weighted([&](std::uint32_t i) { return mesh.colors[i]; });
  if (!mesh.tangents.empty()) {
    const glm::vec3 T = weighted([&](std::uint32_t i) { return glm::vec3(LitPhongProgram::worldTangent(matrices, mesh, i)); });
    p.tangent = glm::vec4(T, mesh.tangents[index[0]].w);
  }
  for (int set = 0; set < 2; ++set) {
    const std::vector<glm::vec2>& st = mesh.texcoordSet(set);
    if (st.empty()) continue;
    p.st[set] = weighted([&](std::uint32_t i) { return st[i]; });
    if (!differentials) continue;
    const glm::vec3* c = &primitives_.triangleCorners[3 * static_cast<std::size_t>(hit.primitive)];
    const std::optional<glm::vec2> left = planeBarycentrics(c[0], c[1], c[2], differentials->left);
    const std::optional<glm::vec2> right = planeBarycentrics(c[0], c[1], c[2], differentials->right);
    const std::optional<glm::vec2> below = planeBarycentrics(c[0], c[1], c[2], differentials->below);
    const std::optional<glm::vec2> above = planeBarycentrics(c[0], c[1], c[2], differentials->above);
    if (!left || !right || !below || !above) continue;
    const auto stAt = [&](glm::vec2 b) { return ((1.0f - b.x - b.y) * st[index[0]] + b.x * st[index[1]]) + b.y * st[index[2]]; };
    const glm::vec2 dx = stAt(*right) - stAt(*left), dy = stAt(*above) - stAt(*below);
    p.derivatives[set] = glm::vec4(dx.x, dx.y, dy.x, dy.y);
  }
  return p;
}

float TracedScene::alphaAt(const Hit& hit, const Ray& ray) const {
  // Only what α reads (it runs inside traversals, for each masked or blended candidate): the base
  // colour texture's coordinates and COLOR_0's alpha at the hit, weighted as surfaceAt weights them.
  const TracedPrimitive& traced = traced_[hit.primitive];
  const DrawUniforms& draw = draws_[traced.instance];
  const Mesh& mesh = *draw.mesh;
  const int set = draw.material->baseColorSet;
  glm::vec2 st{0.0f};
  float vertexAlpha = 1.0f;
  if (primitives_.isSphere(hit.primitive)) {
    st = sphereTexcoords(sphereFrames_[hit.primitive - primitives_.triangleCount()], pointOf(hit, ray));
  } else {
    const std::uint32_t* index = &mesh.indices[traced.first];
    const float w[3] = {1.0f - hit.u - hit.v, hit.u, hit.v};
    const std::vector<glm::vec2>& texcoords = mesh.texcoordSet(set);
    if (!texcoords.empty()) st = (w[0] * texcoords[index[0]] + w[1] * texcoords[index[1]]) + w[2] * texcoords[index[2]];
    if (draw.colored) vertexAlpha = (w[0] * mesh.colors[index[0]].a + w[1] * mesh.colors[index[1]].a) + w[2] * mesh.colors[index[2]].a;
  }
  glm::vec4 texel{1.0f};
  if (draw.texture) texel = sampleBaseColorTexture(*draw.texture, *draw.material, st, glm::vec4(0.0f));
  return fragmentAlpha(*draw.material, draw.colored ? &vertexAlpha : nullptr, draw.texture ? &texel : nullptr);
}

std::size_t TracedScene::bytes() const {
  return primitives_.triangleCorners.size() * sizeof(glm::vec3) + primitives_.spheres.size() * sizeof(glm::vec4) +
         traced_.size() * sizeof(TracedPrimitive) + sphereFrames_.size() * sizeof(TracedSphere) + bvh_.stats().bytes;
}

}  // namespace facet::ray
