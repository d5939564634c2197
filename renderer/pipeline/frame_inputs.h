#pragma once
// Everything a backend needs for one frame, computed once on the CPU by
// buildFrameInputs: every matrix (camera, viewport, normal, light), the
// resolved lights and course material coefficients. Backends consume these
// values; they never build a camera or light matrix themselves.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "pipeline/light_frustum.h"
#include "pipeline/material_coefficients.h"
#include "scene/scene.h"
#include "settings/render_settings.h"
#include "vocabulary/limits.h"

namespace facet {

struct FrameInstance {
  int mesh = 0;                   // index into Scene::meshes
  glm::mat4 worldFromModel{1.0f}; // TM
  glm::mat3 normalMatrix{1.0f};   // (TM^T)^-1, upper 3x3
  glm::mat4 clipFromModel{1.0f};  // PM·EM·TM
  int material = 0;               // index into FrameInputs::materials (never -1)
  bool cullBackFaces = true;      // culling is on and the material is single-sided
};

struct FrameLight {
  Light light;                    // world space, direction normalized
  glm::vec3 intensity{0.0f};      // I_p = colour · intensity, linear RGB
  float cosCutoff = -1.0f;        // cos β (spot); -1 for other kinds
  bool hasShadowMap = false;      // castsShadow and shadows enabled
  LightFrustum frustum;           // faces used in pass 1 and pass 2
  int shadowLayer = -1;           // first layer of this light's faces in the shadow-map array
  // Per face: maps a world point to the shadow map's window coordinates:
  // after the divide by w, (u, v) in [0,1]² and window z in [0,1].
  std::array<glm::mat4, 6> shadowFromWorld{};
};

// How llvmpipe's line set-up decides that the plain quad of a segment
// already draws an end's pixel (Mesa's lp_setup_line.c, try_setup_line,
// "Are we already drawing start/end?"): Mesa 22.3 compares the signs of the
// end's offsets from its pixel centre; Mesa 25.0 asks which edge of the quad
// the end lies on. They differ only for an end whose offset along the major
// axis is 0 (renderer/PIPELINE.md, "Lines and points"). The CPU
// backend follows the llvmpipe it is held against: gl::lineEndTestOf reads
// it from the driver's version string.
enum class LineEndTest { Mesa22, Mesa25 };

struct FrameInputs {
  int width = 0, height = 0;      // pixels
  CameraSettings camera;          // resolved (source = manual)
  glm::vec3 eyePosition{0.0f};    // P_eye, world space
  glm::vec3 towardEye{0.0f};      // -k, world space: V for parallel projection
  bool perspective = true;
  glm::mat4 eyeFromWorld{1.0f};   // EM
  glm::mat4 clipFromEye{1.0f};    // PM (perspective or parallel)
  glm::mat4 clipFromWorld{1.0f};  // PM·EM
  glm::mat4 windowFromNdc{1.0f};  // window-to-viewport: [-1,1]² -> [0,W]×[0,H], z unchanged
  LineEndTest lineEnds = LineEndTest::Mesa25;  // the CPU's segment ends: the newest llvmpipe's test unless told which

  std::vector<FrameInstance> instances;
  std::vector<CourseMaterial> materials;  // the scene's, then the default material last
  std::vector<FrameLight> lights;

  float ambient = 0;              // I_a
  ShadingMode shading = ShadingMode::Phong;
  SpecularModel specular = SpecularModel::BlinnPhong;
  bool cullBackFaces = true;      // the settings' switch; each instance says whether it is culled
  HiddenSurface hsr = HiddenSurface::ZBuffer;
  // hsr = painter: the frame's triangles (indices in the frame's triangle
  // list, instances in order) in the order they are drawn, back to front
  // (pipeline/painters_order.h); empty otherwise.
  std::vector<std::uint32_t> paintersOrder;
  // Transparency (PIPELINE.md, "Shading"): the blended triangles, drawn after
  // every other triangle and line in this order, back to front
  // (pipeline/transparency_order.h); empty when no material is blended.
  Blending blending = Blending::Straight;
  std::vector<std::uint32_t> transparentOrder;
  // Anti-aliasing (PIPELINE.md, "Shading"): the sample offsets of the frame's
  // passes (pipeline/antialiasing.h), empty for one sample at each pixel's
  // centre; and the offset a sample's frame is drawn at (sampleFrame).
  std::vector<glm::vec2> samples;
  glm::vec2 sampleOffset{0.0f};
  // antialiasing.pattern = area: the CPU's exact area-weighted averaging
  // (cpu/area_averaging.h) in place of samples, which stay empty.
  bool areaAveraged = false;
  ShadowSettings shadows;
  int shadowLayerCount = 0;       // S×S depth maps over all lights: one per face
  float time = 0.0f;              // seconds: where the scene's animation places the instances
  // The ray tracer's knobs (PIPELINE.md, "Ray tracing"), and the radius R of the
  // scene's bounding sphere that ray.epsilon scales.
  RaySettings ray;
  float sceneRadius = 1.0f;
  glm::vec3 background{0.0f};    // linear RGB
  float backgroundAlpha = 1.0f;   // alpha of empty pixels (the environment map's too)
  // Environment mapping (PIPELINE.md, "Textures"). `map` points into the Scene
  // the frame was built from (its environment), null when there is none.
  struct Environment {
    const EnvironmentMap* map = nullptr;
    float reflectivity = 0.0f;  // k_r
    bool background = false;    // empty pixels show env(D)
    // D at pixel (x, y) in NDC: (forward + x·right) + y·up (right = up = 0 under parallel projection).
    glm::vec3 forward{0.0f, 0.0f, -1.0f}, right{0.0f}, up{0.0f};
  } environment;
  // Bump mapping (PIPELINE.md, "Textures"), Phong and pbr: `map` points into the Scene (its bumpMap), null when none.
  struct Bump {
    const Texture* map = nullptr;
    float scale = 0.0f;  // k
  } bump;
  Procedural procedural = Procedural::None;  // a pattern in place of every base colour texture
  float proceduralScale = 1.0f;              // k: cells per model unit
  // Fog (PIPELINE.md, "Shading"): the settings', and cot θ for the eye depth d = (1/(1/w))·cot θ.
  struct Fog {
    FogMode mode = FogMode::None;
    glm::vec3 color{0.0f};  // C_fog, linear
    float start = 0.0f, end = 1.0f, density = 0.0f;
    float cotTheta = 1.0f;  // perspective: 1/tan θ, double precision rounded to float
  } fog;

  // Volume ray casting (PIPELINE.md, "Volume rendering"): `placed` points into the
  // Scene (its volume), null unless volume.mode = raycast and the scene has one.
  struct VolumeCasting {
    const Scene::PlacedVolume* placed = nullptr;
    float step = 0.5f;
    float earlyTermination = 0.99f;
    bool emptySpaceSkipping = true;
  } volume;

  std::vector<std::string> warnings;  // what building the frame dropped (lights beyond kMaxLights)
};

// The frame's triangle list (instances in order, each mesh's triangles in
// order): where each instance's triangles begin in it, then their total.
std::vector<std::size_t> firstTriangles(const Scene& scene, const FrameInputs& frame);

// The instance whose triangles hold list index `triangle` (below first.back()).
std::size_t instanceOfTriangle(const std::vector<std::size_t>& first, std::size_t triangle);

// Each instance's TM, normal matrix and PM·EM·TM at `time`: the scene's
// animation there (scene/animation.h), or the instances' own transforms in
// a scene without one. buildFrameInputs places them at settings.time; the
// ray tracer places its motion blur's slices at the shutter's times.
void placeInstances(const Scene& scene, float time, FrameInputs& frame);

// Throws facet::Error (naming the settings key) when the camera cannot be
// built (eye on the reference point, up along the line of sight), when the
// settings list more than kMaxLights lights, when an instance names a mesh
// the scene lacks, or when checkFrame (pipeline/frame_checks.h) refuses the
// frame. A scene with more lights than kMaxLights gives the first
// kMaxLights and a warning.
FrameInputs buildFrameInputs(const Scene& scene, const RenderSettings& settings);

// Whether empty pixels show the environment map rather than the background colour.
inline bool showsEnvironment(const FrameInputs& frame) { return frame.environment.map && frame.environment.background; }

}  // namespace facet
