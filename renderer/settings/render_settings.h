#pragma once
#include <cstddef>
#include <cstdint>
// Every knob of the pipeline, in one struct with one set of defaults (the
// member initializers below: the only place a default is written). The
// command line, the viewer, the tests and the benchmarks all go through it.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "vocabulary/emitter.h"
#include "vocabulary/enums.h"
#include "vocabulary/light.h"
#include "vocabulary/limits.h"

namespace facet {

// The course's environment (reflection) mapping (renderer/PIPELINE.md, "Textures").
struct EnvironmentSettings {
  std::string map;             // a cube map PNG (six square faces side by side); empty: none
  float reflectivity = 0.25f;  // k_r of k_r·I_r
  bool background = true;      // empty pixels show the map in their view direction
};

struct TextureSettings {
  TextureFilter filter = TextureFilter::Auto;
};

struct CameraSettings {
  Source source = Source::Auto;
  glm::vec3 eye{0.0f, 1.0f, 5.0f};        // P_eye, world space (manual)
  glm::vec3 reference{0.0f, 0.0f, 0.0f};  // P_ref, world space (manual)
  glm::vec3 up{0.0f, 1.0f, 0.0f};         // v_up, world space (manual)
  ProjectionKind projection = ProjectionKind::Perspective;
  float halfAngleDeg = 30.0f;             // θ, measured horizontally (perspective)
  float parallelWidth = 10.0f;            // W of the parallel box, world units; H = W / aspect
  float near = 0.1f;                      // N, eye-space distance
  float far = 100.0f;                     // F, eye-space distance
  // The ray tracer's thin lens (renderer/PIPELINE.md, "Ray tracing"): depth of field.
  float aperture = 0.0f;                  // lens radius, world units; 0: a pinhole, everything sharp
  float focusDistance = 0.0f;             // eye depth in focus, world units; 0: autofocus on the image's centre
  float shutter = 0.0f;                   // seconds the shutter stays open from `time` (motion blur); 0: an instant
};

// glTF materials carry no k_a, k_d, k_s, n; pipeline/material_coefficients
// derives them. A value set here overrides the derived one for every material.
struct MaterialOverrides {
  std::optional<float> ka;
  std::optional<float> kd;
  std::optional<float> ks;
  std::optional<float> shininess;  // n
  // α's factor for every material in place of the base colour factor's alpha;
  // below 1 every material is blended (PIPELINE.md, "Transparency").
  std::optional<float> opacity;
  // The ray tracer's k_r, k_t and index of refraction for every material
  // (renderer/PIPELINE.md, "Ray tracing"); unset: from glTF.
  std::optional<float> reflectivity;  // k_r = reflectivity·O_s
  std::optional<float> transmission;  // k_t
  std::optional<float> ior;           // n
  Procedural procedural = Procedural::None;
  float proceduralScale = 4.0f;     // k: pattern cells per model unit
  // Displacement mapping (PIPELINE.md, "Textures"): P' = P + (scale·h)·N at the
  // vertices of every textured mesh, subdivided first.
  std::string displacementMap;      // a greyscale PNG height map h in [0, 1], read at TEXCOORD_0; empty: none
  float displacementScale = 0.1f;   // model units at h = 1
  int displacementSubdivisions = 3; // each triangle split into 4^k
  // Bump mapping (PIPELINE.md, "Textures"): the course's N' = N + B_u·(N × P_t) - B_v·(N × P_s) per pixel, Phong and pbr.
  std::string bumpMap;              // a greyscale PNG height map h in [0, 1], read at TEXCOORD_0; empty: none
  float bumpScale = 0.05f;          // k: B = k·h, in texture-coordinate units
};

struct ShadowSettings {
  bool enabled = true;
  int mapSize = 2048;        // S of the S×S depth map (per cube face for point lights)
  // bias = max(b_slope·(1 - N·L), b_min), in the shadow map's window z. Point
  // and spot maps are perspective views, whose depth runs along each view's
  // axis: a surface facing the light 45° off-axis still slopes by one texel
  // of depth per texel, so b_min must cover that. 0.0005 left acne on
  // builtin:torus; 0.002 detached the default scene's torus shadow from it.
  float biasSlope = 0.01f;   // b_slope
  float biasMin = 0.001f;    // b_min
  int pcfRadius = 1;         // r: PCF averages (2r+1)² samples; 0 = hard shadows
};

// The course's atmospheric attenuation (renderer/PIPELINE.md, "Shading",
// "Fog"): C = f·C_surface + (1 - f)·C_fog by the eye-space depth d,
// linear f = (end - d)/(end - start), exponential e^(-density·d),
// exponential2 e^(-(density·d)²), f clamped to [0, 1].
struct FogSettings {
  FogMode mode = FogMode::None;
  glm::vec3 color{0.5f, 0.55f, 0.6f};  // C_fog, linear RGB
  float start = 1.0f;                  // linear: d where the fog begins (f = 1)
  float end = 20.0f;                   // linear: d where it hides everything (f = 0), > start
  float density = 0.1f;                // exponential and exponential2, per world unit
};

struct TransparencySettings {
  TransparencySort sort = TransparencySort::Object;
  float shadowCutoff = 0.5f;  // a blended fragment casts a shadow where α ≥ this
};

// s for s × s samples: the largest s with s² ≤ samples.
inline int samplesPerSide(int samples) {
  int side = 1;
  while ((side + 1) * (side + 1) <= samples) ++side;
  return side;
}
struct AntialiasingSettings {
  int samples = 1;
  SamplePattern pattern = SamplePattern::Grid;
  int seed = 1;  // jittered: the generator's seed
};

// The ray-tracing backend (renderer/PIPELINE.md, "Ray tracing").
struct RaySettings {
  int depth = 5;                  // levels of the ray tree: 1 casts primary rays only
  float minContribution = 0.01f;  // a ray whose weight (largest channel) is below this is not traced
  float epsilon = 1e-4f;          // a new ray starts ε·R off the surface, R the scene's bounding radius
  bool spheres = true;            // the builtin sphere traced as a sphere, not its triangles
  // Stochastic ray tracing: paths per pixel, each sampling the pixel, the
  // lens, the lights' areas, the gloss and translucency lobes once, from a seed.
  int samples = 1;
  int seed = 1;
  bool gloss = false;             // reflected rays spread by the surface's roughness
  bool translucency = false;      // transmitted rays spread likewise
};

struct VolumeSettings {
  std::string file;                   // a NRRD (.nrrd, .nhdr) or NIfTI-1 (.nii, .nii.gz) file, or builtin:marschner-lobb; empty: none
  int resolution = 64;                // builtin:marschner-lobb: samples along each axis
  VolumeMode mode = VolumeMode::Isosurface;  // the one every backend draws, and the quickest
  std::string transfer = "grey";      // a preset, or control points "value r g b a, ..." (scene/transfer_function.h)
  glm::vec3 center{0.0f, 1.0f, 0.0f};// world position of the volume box's centre
  float size = 2.0f;                  // world length of the box's longest side
  glm::vec3 rotation{0.0f};           // degrees about x, then y, then z (R = Rz·Ry·Rx), about the box's centre
  float step = 0.5f;                  // raycast: the distance between samples along a ray, in voxel spacings
  float earlyTermination = 0.99f;     // raycast: a ray stops once its accumulated opacity reaches this (1: never)
  bool emptySpaceSkipping = true;     // raycast: macro cells whose samples the transfer function makes transparent are stepped over
  float splatRadius = 1.5f;           // splat: the footprint's radius, in voxel spacings (a Gaussian of σ = radius / 3)
  std::optional<float> isoValue;      // isosurface: the value in the data's units; null: the mean of the data
  glm::vec3 isoColor{0.9f, 0.85f, 0.75f};  // isosurface: the mesh's base colour, linear RGB

  friend bool operator==(const VolumeSettings&, const VolumeSettings&) = default;
};

struct RenderSettings {
  int width = 800;   // image size in pixels
  int height = 600;
  CameraSettings camera;
  Source lightSource = Source::Auto;
  std::vector<Light> lights;              // used when lightSource is manual
  float ambient = 0.15f;                  // I_a (white)
  ShadingMode shading = ShadingMode::Phong;
  SpecularModel specular = SpecularModel::BlinnPhong;
  bool cullBackFaces = true;
  HiddenSurface hsr = HiddenSurface::ZBuffer;
  MaterialOverrides material;
  Blending blending = Blending::Straight;
  TransparencySettings transparency;
  AntialiasingSettings antialiasing;
  ShadowSettings shadows;
  TextureSettings textures;
  EnvironmentSettings environment;
  FogSettings fog;
  RaySettings ray;
  std::vector<Emitter> particles;
  VolumeSettings volume;
  float time = 0.0f;                      // seconds into the scene's animation (glTF node animations)
  glm::vec3 background{0.02f, 0.025f, 0.035f};  // linear RGB
  float backgroundAlpha = 1.0f;                  // the colour buffer's alpha where no surface is drawn
};

}  // namespace facet
