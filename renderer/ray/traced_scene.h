#pragma once
// The frame's geometry as rays see it (renderer/PIPELINE.md, "Ray tracing"):
// every instance's world triangles, the rasterizers' corners, or a sphere in
// place of the builtin sphere's; which instance and which of its mesh's
// triangles each primitive is; the BVH over them; and what a hit point
// carries for the fragment stage (shading/lit_programs.h).
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "shading/draw_uniforms.h"
#include "shading/lit_varyings.h"
#include "common/thread_pool.h"
#include "pipeline/frame_inputs.h"
#include "ray/bvh.h"
#include "ray/primitives.h"
#include "ray/ray.h"
#include "scene/scene.h"

namespace facet::ray {

// What a primitive is in the frame.
struct TracedPrimitive {
  std::uint32_t instance = 0;       // index into FrameInputs::instances
  std::uint32_t frameTriangle = 0;  // a triangle's index in the frame's list (instances in order); a sphere's: its mesh's first
  std::uint32_t first = 0;          // a triangle's first index in its mesh's `indices`
};

// A sphere in world space and the model space it came from (its texture coordinates, procedural patterns).
struct TracedSphere {
  glm::vec3 center{0.0f};
  float radius = 0.0f;
  glm::mat4 modelFromWorld{1.0f};
};

// A primary hit's texture level of detail from the rays of its pixel's 2×2
// quad, as the rasterizer differences its quad (PIPELINE.md, "Textures"):
// d/dx between the quad's two columns in the pixel's row, d/dy between its
// two rows in the pixel's column, each where those rays meet the hit's plane.
struct RayDifferentials {
  Ray left, right;  // pixels (px & ~1, py) and (px | 1, py)
  Ray below, above; // pixels (px, py & ~1) and (px, py | 1)
};

class TracedScene {
 public:
  // The frame's primitives and their BVH, built on `pool`. With `spheres`,
  // an instance of a sphere mesh (Mesh::sphere) whose TM scales alike on
  // every axis is one sphere instead of its triangles.
  TracedScene(const Scene& scene, const FrameInputs& frame, bool spheres, ThreadPool& pool);

  // Whether this was built from `scene` and the instances of `frame` as they are now.
  bool builtFrom(const Scene& scene, const FrameInputs& frame, bool spheres) const;
  // The frame whose materials and settings the hits are shaded with (each
  // frame, before tracing: the geometry may be kept from an earlier one).
  void bind(const Scene& scene, const FrameInputs& frame);

  const Primitives& primitives() const { return primitives_; }
  const Bvh& bvh() const { return bvh_; }
  const TracedPrimitive& primitive(std::uint32_t p) const { return traced_[p]; }
  const FrameInstance& instanceOf(const FrameInputs& frame, std::uint32_t p) const { return frame.instances[traced_[p].instance]; }
  const DrawUniforms& drawOf(std::uint32_t p) const { return draws_[traced_[p].instance]; }

  // The unit geometric normal at a hit: (p1 - p0) × (p2 - p0) of a triangle's world corners, (P - C)/r on a sphere.
  glm::vec3 geometricNormal(const Hit& hit, glm::vec3 P) const;
  // Whether the ray sees the side the geometric normal points to.
  bool frontFacing(const Hit& hit, const Ray& ray) const;
  // The world point of a hit: the corners weighted by the barycentrics, or origin + t·D on a sphere.
  glm::vec3 pointOf(const Hit& hit, const Ray& ray) const;

  // What the fragment stage reads at the hit: world position and normal,
  // tangent, texture coordinates (with their derivatives from `differentials`
  // where given, else 0: level 0), COLOR_0, model position, the side seen.
  SurfacePoint surfaceAt(const Hit& hit, const Ray& ray, const RayDifferentials* differentials) const;

  // α of a masked or blended material at the ray's hit (alpha_mask.h's product, texture read at level 0).
  float alphaAt(const Hit& hit, const Ray& ray) const;

  std::size_t bytes() const;  // what the primitives, their records and the BVH hold

 private:
  glm::vec2 sphereTexcoords(const TracedSphere& s, glm::vec3 P) const;

  const Scene* scene_;
  const FrameInputs* frame_;
  std::weak_ptr<const char> sceneToken_;
  std::vector<glm::mat4> transforms_;  // each instance's TM when built
  std::vector<int> meshes_;            // and its mesh
  bool spheres_;
  Primitives primitives_;
  std::vector<TracedPrimitive> traced_;
  std::vector<TracedSphere> sphereFrames_;
  std::vector<DrawUniforms> draws_;  // per instance
  Bvh bvh_;
};

}  // namespace facet::ray
