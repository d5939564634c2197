#pragma once
// The lit pass's programs on the CPU, one per pair of shaders: vertex()
// mirrors shaders/lit_*.vert (a mesh vertex's clip position and the
// varyings of lit_varyings.h), fragment() mirrors lit_*.frag (the colour of
// a point of the surface, before fog: a rasterizer fogs it by the pixel's
// depth, the ray tracer after the recursive terms). The fast tiled
// renderer, the readable reference and the ray tracer all call these; none
// of them writes a stage of its own. Phong's lighting also runs on lanes
// (F = float, Float4, Float8, Float16: lanes.h), in the fast renderer's batch.
//
// `Shadows` gives S: the light's shadow maps for a rasterizer
// (shadowFactorLanes(const ShadowMaps&, ...), lighting.h), or shadow rays
// for the ray tracer (an overload of shadowFactorLanes for its own type).
//
// [SECTION] The vertex stage's per-instance part
// [SECTION] LitFlatProgram       lit_flat.vert, lit_flat.frag
// [SECTION] LitGouraudProgram    lit_gouraud.vert, lit_gouraud.frag
// [SECTION] LitPhongProgram      lit_phong.vert, lit_phong.frag
// [SECTION] LitPbrProgram        lit_phong.vert, lit_phong.frag with FACET_PBR
// [SECTION] By the frame's mode
#include <cstddef>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "pipeline/frame_inputs.h"
#include "shading/bump_mapping.h"
#include "shading/draw_uniforms.h"
#include "shading/lighting.h"
#include "shading/lit_varyings.h"
#include "shading/normal_mapping.h"
#include "shading/physically_based.h"
#include "shading/transform.h"

namespace facet {

// [SECTION] The vertex stage's per-instance part

// The matrices of a draw (draw_uniforms.glsl's clipFromModel, normalMatrix,
// and worldFromModel's upper 3×3 that turns a tangent), copied once per
// instance: the vertex stage's stores cannot alias a local copy.
struct DrawMatrices {
  glm::mat4 clipFromModel{1.0f};  // PM·EM·TM
  glm::mat3 normalMatrix{1.0f};   // (TM^T)^-1
  glm::mat3 tangentMatrix{1.0f};  // TM's upper 3×3
  bool cullBackFaces = true;      // the instance's back faces are never drawn: nothing lights them
};
inline DrawMatrices drawMatrices(const FrameInstance& instance) {
  return {instance.clipFromModel, instance.normalMatrix, glm::mat3(instance.worldFromModel), instance.cullBackFaces};
}

// A mesh normal in world space, unit length: what every mode that lights a vertex or a pixel interpolates.
inline glm::vec3 worldNormal(const DrawMatrices& m, const Mesh& mesh, std::size_t i) {
  return normalize3(transformDirection(m.normalMatrix, mesh.normals[i]));
}

// The varyings every mode packs after its own: both texture coordinate sets,
// COLOR_0 (1 without one) and the model-space position, those below `packed`.
inline void putSurfaceVaryings(VaryingLayout layout, const Mesh& mesh, std::size_t i, int packed, float* v) {
  if (packed >= layout.uv + 4) putTexcoords(v, layout.uv, mesh, i);
  if (packed >= layout.color + 4) {
    const glm::vec4 rgba = mesh.colors.empty() ? glm::vec4(1.0f) : mesh.colors[i];
    for (int c = 0; c < 4; ++c) v[layout.color + c] = rgba[c];
  }
  if (packed == layout.count)
    for (int c = 0; c < 3; ++c) v[layout.model + c] = mesh.positions[i][c];
}

// [SECTION] LitFlatProgram

struct LitFlatProgram {
  static constexpr ShadingMode kMode = ShadingMode::Flat;
  static constexpr VaryingLayout kLayout = varyingLayout(kMode);

  // gl_Position of mesh vertex i, and its varyings below `packed`; the
  // illumination is the face's (face(), once per triangle).
  template <class Shadows>
  static glm::vec4 vertex(const DrawUniforms& d, const DrawMatrices& m, const Shadows&, std::size_t i, glm::vec3 /*world*/, int packed,
                          float* v) {
    putSurfaceVaryings(kLayout, *d.mesh, i, packed, v);
    return transformPoint(m.clipFromModel, d.mesh->positions[i]);
  }

  // The face's geometric normal normalize(cross(p1 - p0, p2 - p0)), from its world corners.
  static glm::vec3 faceNormal(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2) { return normalize3(cross3(p1 - p0, p2 - p0)); }

  // The illumination of one side of the face (front: lit with N, else -N), at its centroid, V from there.
  template <class Shadows>
  static Illumination faceSide(const DrawUniforms& d, const Shadows& shadows, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, bool front) {
    const glm::vec3 N = faceNormal(p0, p1, p2), centroid = (p0 + p1 + p2) / 3.0f;
    return illuminate(*d.frame, shadows, d.summed, centroid, front ? N : -N, viewVector<float>(*d.frame, centroid));
  }
  // Both sides, the vertex shader's flat outputs: the back only where back faces are drawn (0 where they are culled).
  template <class Shadows>
  static void face(const DrawUniforms& d, const Shadows& shadows, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, bool cullBackFaces,
                   Illumination (&out)[2]) {
    const glm::vec3 N = faceNormal(p0, p1, p2), centroid = (p0 + p1 + p2) / 3.0f;
    const glm::vec3 V = viewVector<float>(*d.frame, centroid);
    out[0] = illuminate(*d.frame, shadows, d.summed, centroid, N, V);
    out[1] = !cullBackFaces ? illuminate(*d.frame, shadows, d.summed, centroid, -N, V) : Illumination{};
  }

  // The side's illumination (p.lit, the face's) times O_d, k_e·E added with an emissive texture.
  static glm::vec3 fragment(const DrawUniforms& d, const SurfacePoint& p) { return shadeLit(d, p); }

  // What the illumination of a vertex or a face gives at a point: I·O_d, with
  // I.specular + k_e·E where the draw has an emissive texture (summed with
  // k_e = 0); KHR_materials_unlit's O_d itself.
  static glm::vec3 shadeLit(const DrawUniforms& d, const SurfacePoint& p) {
    if (d.material->unlit) return baseColorAt(d, p);
    Illumination I = p.lit;
    if (d.emissiveMap) I.specular = emissionAt(d, p) + I.specular;
    return shade(I, baseColorAt(d, p));
  }
};

// [SECTION] LitGouraudProgram

struct LitGouraudProgram {
  static constexpr ShadingMode kMode = ShadingMode::Gouraud;
  static constexpr VaryingLayout kLayout = varyingLayout(kMode);

  // The illumination equation at a vertex (world P, unit world N), lit from one side.
  template <class Shadows>
  static Illumination vertexSide(const DrawUniforms& d, const Shadows& shadows, glm::vec3 P, glm::vec3 N, bool front) {
    return illuminate(*d.frame, shadows, d.summed, P, front ? N : -N, viewVector<float>(*d.frame, P));
  }

  // gl_Position of mesh vertex i (world position `world`), and its varyings
  // below `packed`: the illumination of both sides (the back only where back
  // faces are drawn), then the surface's.
  template <class Shadows>
  static glm::vec4 vertex(const DrawUniforms& d, const DrawMatrices& m, const Shadows& shadows, std::size_t i, glm::vec3 world, int packed,
                          float* v) {
    const glm::vec3 N = worldNormal(m, *d.mesh, i);
    const Illumination front = vertexSide(d, shadows, world, N, true);
    const Illumination back = !m.cullBackFaces ? vertexSide(d, shadows, world, N, false) : Illumination{};
    for (int c = 0; c < 3; ++c)
      v[c] = front.diffuse[c], v[3 + c] = front.specular[c], v[6 + c] = back.diffuse[c], v[9 + c] = back.specular[c];
    putSurfaceVaryings(kLayout, *d.mesh, i, packed, v);
    return transformPoint(m.clipFromModel, d.mesh->positions[i]);
  }

  // The side's interpolated illumination (p.lit) times O_d.
  static glm::vec3 fragment(const DrawUniforms& d, const SurfacePoint& p) { return LitFlatProgram::shadeLit(d, p); }
};

// [SECTION] LitPhongProgram

struct LitPhongProgram {
  static constexpr ShadingMode kMode = ShadingMode::Phong;
  static constexpr VaryingLayout kLayout = varyingLayout(kMode);

  // The mesh tangent turned to world space by TM's upper 3×3, w riding along; (0, 0, 0, 1) without one.
  static glm::vec4 worldTangent(const DrawMatrices& m, const Mesh& mesh, std::size_t i) {
    const glm::vec4 t = mesh.tangents.empty() ? glm::vec4(0.0f, 0.0f, 0.0f, 1.0f) : mesh.tangents[i];
    return glm::vec4(transformDirection(m.tangentMatrix, glm::vec3(t)), t.w);
  }

  // gl_Position of mesh vertex i, and its varyings below `packed`: world position and unit normal, then the surface's.
  template <class Shadows>
  static glm::vec4 vertex(const DrawUniforms& d, const DrawMatrices& m, const Shadows&, std::size_t i, glm::vec3 world, int packed, float* v) {
    const glm::vec3 N = worldNormal(m, *d.mesh, i);
    for (int c = 0; c < 3; ++c) v[c] = world[c], v[3 + c] = N[c];
    putSurfaceVaryings(kLayout, *d.mesh, i, packed, v);
    if (packed >= kLayout.tangent + 4) {
      const glm::vec4 t = worldTangent(m, *d.mesh, i);
      for (int c = 0; c < 4; ++c) v[kLayout.tangent + c] = t[c];
    }
    return transformPoint(m.clipFromModel, d.mesh->positions[i]);
  }

  // The normal the point is lit with before it is normalized and turned to
  // the side seen: the interpolated one bent by the normal texture (whose
  // result is normalized as the interpolated one is), then by the bump map.
  static glm::vec3 bentNormal(const DrawUniforms& d, const SurfacePoint& p) {
    const CourseMaterial& material = *d.material;
    glm::vec3 n = p.normal;
    const int set = material.normalMap.set;
    if (d.normalMap) n = normalMapped(*d.normalMap, material, normalize3(n), p.tangent, p.st[set], p.derivatives[set]);
    if (d.bumpable) n = bumped(*d.frame->bump.map, d.frame->bump.scale, normalize3(n), p.tangent, p.st[0]);
    return n;
  }
  // N: the bent normal, normalized, negated on a back face (two-sided lighting).
  template <class F>
  static Vec3Of<F> twoSided(const Vec3Of<F>& bent, MaskOf<F> back) {
    const Vec3Of<F> unit = normalize3(bent);
    return select(back, -unit, unit);
  }
  static glm::vec3 shadingNormal(const DrawUniforms& d, const SurfacePoint& p) { return twoSided<float>(bentNormal(d, p), !p.front); }

  // The illumination equation at P with N (twoSided's), which the caller
  // shades O_d with: on one pixel or on a lane per pixel (the fast
  // renderer's batch queues P, the bent normal, O_d and the material of many
  // pixels, and lights them here together; O_d is read after, so it waits in
  // memory while the lights are summed).
  template <class F, class Shadows>
  static IlluminationOf<F> lit(const FrameInputs& frame, const Shadows& shadows, const LaneMaterial<F>& material, const Vec3Of<F>& P,
                               const Vec3Of<F>& N) {
    return illuminate(frame, shadows, material, P, N, viewVector<F>(frame, P));
  }

  // KHR_materials_unlit's O_d itself, else the lit colour, k_e·E in k_e's place with an emissive texture.
  template <class Shadows>
  static glm::vec3 fragment(const DrawUniforms& d, const Shadows& shadows, const SurfacePoint& p) {
    const glm::vec3 O = baseColorAt(d, p);
    if (d.material->unlit) return O;
    const glm::vec3 emissive = d.emissiveMap ? emissionAt(d, p) : d.material->emissive;
    return shade(lit<float>(*d.frame, shadows, laneMaterial(*d.material, emissive), p.P, shadingNormal(d, p)), O);
  }
};

// [SECTION] LitPbrProgram

struct LitPbrProgram {
  static constexpr ShadingMode kMode = ShadingMode::Pbr;
  static constexpr VaryingLayout kLayout = varyingLayout(kMode);

  template <class Shadows>
  static glm::vec4 vertex(const DrawUniforms& d, const DrawMatrices& m, const Shadows& shadows, std::size_t i, glm::vec3 world, int packed,
                          float* v) {
    return LitPhongProgram::vertex(d, m, shadows, i, world, packed, v);
  }

  // glTF's metallic-roughness BRDF at the point (physically_based.h), or KHR_materials_unlit's O_d.
  template <class Shadows>
  static glm::vec3 fragment(const DrawUniforms& d, const Shadows& shadows, const SurfacePoint& p) {
    const glm::vec3 O = baseColorAt(d, p);
    if (d.material->unlit) return O;
    const PbrSurface surface = pbrSurfaceAt(*d.scene, *d.material, *d.mesh, O, p.st, p.derivatives);
    return shadePhysicallyBased(*d.frame, shadows, surface, p.P, LitPhongProgram::shadingNormal(d, p), viewVector<float>(*d.frame, p.P));
  }
};

// [SECTION] By the frame's mode

// The fragment program of the draw's mode at the point, before fog.
template <class Shadows>
glm::vec3 litFragment(const DrawUniforms& d, const Shadows& shadows, const SurfacePoint& p) {
  switch (d.frame->shading) {
    case ShadingMode::Pbr: return LitPbrProgram::fragment(d, shadows, p);
    case ShadingMode::Phong: return LitPhongProgram::fragment(d, shadows, p);
    case ShadingMode::Gouraud: return LitGouraudProgram::fragment(d, p);
    default: return LitFlatProgram::fragment(d, p);
  }
}

// The vertex program of the draw's mode (flat's illumination is the face's: LitFlatProgram::face).
template <class Shadows>
glm::vec4 litVertex(const DrawUniforms& d, const DrawMatrices& m, const Shadows& shadows, std::size_t i, glm::vec3 world, int packed, float* v) {
  switch (d.frame->shading) {
    case ShadingMode::Pbr:
    case ShadingMode::Phong: return LitPhongProgram::vertex(d, m, shadows, i, world, packed, v);
    case ShadingMode::Gouraud: return LitGouraudProgram::vertex(d, m, shadows, i, world, packed, v);
    default: return LitFlatProgram::vertex(d, m, shadows, i, world, packed, v);
  }
}

}  // namespace facet
