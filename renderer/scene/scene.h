#pragma once
// The scene in memory: what every loader produces and both backends draw.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <limits>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "image/image.h"
#include "image/mipmap.h"
#include "scene/animation.h"
#include "vocabulary/emitter.h"
#include "vocabulary/enums.h"
#include "vocabulary/light.h"
#include "scene/transfer_function.h"
#include "scene/volume.h"

namespace facet {

// One triangle list with one material (a glTF primitive).
struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;   // model space
  std::vector<glm::vec3> normals;     // model space, unit length, one per position
  std::vector<glm::vec2> texcoords;   // TEXCOORD_0, empty when the mesh has none
  std::vector<glm::vec2> texcoords1;  // TEXCOORD_1, empty when the mesh has none
  std::vector<glm::vec4> colors;      // COLOR_0, linear RGBA, empty when the mesh has none
  // TANGENT: xyz the model-space unit tangent (along increasing s), w = ±1 the bitangent's side
  // (B = w·(N × T)); read or computed (scene/vertex_tangents.h) where a normal texture needs it, else empty.
  std::vector<glm::vec4> tangents;
  std::vector<std::uint32_t> indices; // three per triangle, counter-clockwise = front
  // glTF's POINTS and LINES (LINE_LOOP and LINE_STRIP as their segments), drawn
  // unlit after the triangles (renderer/PIPELINE.md, "Lines and points").
  // A mesh from a glTF primitive holds one kind: triangles, segments or points.
  std::vector<std::uint32_t> lines;   // two per segment
  std::vector<std::uint32_t> points;  // one per point
  // The builtin unit sphere (scene/primitives.h): the ray tracer may trace it
  // as the sphere it approximates (renderer/PIPELINE.md, "Ray tracing").
  bool sphere = false;
  // One camera-facing quad per sprite, four positions each (particles/sprites.h):
  // thousands overlap, so their shadow pass is priced by the texels they cover.
  bool sprites = false;
  int material = -1;                  // index into Scene::materials, -1 = the default material

  // The texture coordinate set a texture reference names (Material::TexcoordSets): TEXCOORD_0 or TEXCOORD_1.
  const std::vector<glm::vec2>& texcoordSet(int set) const { return set == 1 ? texcoords1 : texcoords; }
  std::size_t triangleCount() const { return indices.size() / 3; }
  std::size_t segmentCount() const { return lines.size() / 2; }
};

// A mesh placed in the world: TM is the node's world transform (T·R·S, parents first).
struct MeshInstance {
  int mesh = 0;                            // index into Scene::meshes
  glm::mat4 worldFromModel{1.0f};          // TM
};

// glTF 2.0's alphaMode: MASK discards fragments below alphaCutoff, BLEND
// blends them by α (renderer/PIPELINE.md, "Transparency").
enum class AlphaMode { Opaque, Mask, Blend };

// KHR_texture_transform of a texture reference: uv' = T(offset)·R(rotation)·S(scale)·uv.
struct TextureTransform {
  glm::vec2 offset{0.0f};
  float rotation = 0.0f;  // radians
  glm::vec2 scale{1.0f};
  bool identity() const { return offset == glm::vec2(0.0f) && rotation == 0.0f && scale == glm::vec2(1.0f); }
};

// The TEXCOORD_n set (0 or 1) each texture reference of a material reads
// (glTF's `texCoord`; renderer/PIPELINE.md, "Textures").
struct TexcoordSets {
  int baseColor = 0, metallicRoughness = 0, occlusion = 0, emissive = 0, normal = 0;
};

// glTF metallic-roughness material; the course coefficients k_a, k_d, k_s, n
// are derived from it in pipeline/material_coefficients.
struct Material {
  std::string name;
  glm::vec4 baseColor{1.0f};      // O_d (linear RGB) and alpha
  int baseColorTexture = -1;      // index into Scene::textures, -1 = none
  TextureTransform baseColorTransform;  // its KHR_texture_transform
  int metallicRoughnessTexture = -1;    // G: roughness, B: metallic, as data (shading=pbr)
  int occlusionTexture = -1;            // R: ambient occlusion, as data (shading=pbr)
  float occlusionStrength = 1.0f;       // ao = 1 + strength·(R - 1)
  int emissiveTexture = -1;             // multiplies k_e, as colour (shading=pbr)
  int normalTexture = -1;               // tangent-space normals, as data (Phong and pbr)
  float normalScale = 1.0f;             // scales the normal texture's x and y
  TexcoordSets texcoordSets;            // which set each of the textures above reads
  glm::vec3 emissive{0.0f};       // k_e, linear RGB
  float metallic = 1.0f;          // glTF default
  float roughness = 1.0f;         // glTF default
  bool doubleSided = false;
  AlphaMode alphaMode = AlphaMode::Opaque;
  float alphaCutoff = 0.5f;       // MASK: a fragment whose alpha is below it is discarded
  // KHR_materials_unlit: the colour is O_d (factor · COLOR_0 · texel) with no
  // illumination, as lines and points are (particles' sprites, volume splats).
  bool unlit = false;
  // BLEND adds the fragment's light instead of laying it over
  // (renderer/PIPELINE.md, "Transparency"): additive particles.
  bool additive = false;
  // Whether it casts a shadow in the shadow maps (sprites: their emitter's castsShadow).
  bool castsShadow = true;
  // What the ray tracer refracts (renderer/PIPELINE.md, "Ray tracing"):
  // KHR_materials_transmission, KHR_materials_ior, KHR_materials_volume.
  float transmission = 0.0f;      // the share of light transmitted, [0, 1]
  float ior = 1.5f;               // index of refraction
  glm::vec3 attenuationColor{1.0f};  // linear RGB a ray keeps after attenuationDistance inside
  float attenuationDistance = std::numeric_limits<float>::infinity();  // world units; infinite: no attenuation
};

// A glTF sampler (5.26); its absence means REPEAT and filters of the
// renderer's choice, which for facet are bilinear and trilinear.
enum class MagFilter { Nearest, Linear };
enum class MinFilter { Nearest, Linear, NearestMipmapNearest, LinearMipmapNearest, NearestMipmapLinear, LinearMipmapLinear };
enum class Wrap { Repeat, ClampToEdge, MirroredRepeat };
struct Sampler {
  MagFilter mag = MagFilter::Linear;
  MinFilter min = MinFilter::LinearMipmapLinear;
  Wrap wrapS = Wrap::Repeat, wrapT = Wrap::Repeat;
  friend bool operator==(const Sampler&, const Sampler&) = default;
};

struct Texture {
  std::string name;
  Image image;                     // level 0: RGBA8, sRGB-encoded colour or linear data (encoding)
  TexelEncoding encoding = TexelEncoding::Srgb;  // as its materials read it (image/mipmap.h)
  std::vector<Image> mips;         // levels 1 .. down to 1×1 (image/mipmap.h), built once by the loader
  Sampler sampler;

  int levelCount() const { return 1 + static_cast<int>(mips.size()); }
  const Image& level(int k) const { return k == 0 ? image : mips[static_cast<std::size_t>(k - 1)]; }
};

// A cube map for environment mapping (scene/environment_map.h): six square
// faces side by side in one image, +x -x +y -y +z -z; empty when none.
struct EnvironmentMap {
  std::string path;  // the file it was read from, as the settings name it
  Image faces;       // 6N × N, sRGB-encoded, bottom row first
  std::vector<Image> mips;  // levels 1 .. of the strip, each face's own chain down to 1×1 (shading=pbr)
  // E(N)/π, the irradiance over π, as nine RGB coefficients of a quadratic in N (PIPELINE.md, "Textures"):
  // k0 + k1·x + k2·y + k3·z + k4·xy + k5·yz + k6·xz + k7·(x² - y²) + k8·z².
  std::array<glm::vec3, 9> irradiance{};
  bool empty() const { return faces.empty(); }
  int faceSize() const { return faces.height(); }
  int levelCount() const { return 1 + static_cast<int>(mips.size()); }
  const Image& level(int k) const { return k == 0 ? faces : mips[static_cast<std::size_t>(k - 1)]; }
};


// A camera as a scene file gives it. Its angle of view is vertical, as in
// glTF; pipeline/camera turns it into the course's horizontal half-angle.
struct SceneCamera {
  std::string name;
  glm::vec3 eye{0.0f};             // world space
  glm::vec3 reference{0.0f, 0.0f, -1.0f};  // a point on the line of sight, world space
  glm::vec3 up{0.0f, 1.0f, 0.0f};  // world space
  ProjectionKind projection = ProjectionKind::Perspective;
  float yfov = 0.8f;               // full vertical angle of view, radians (perspective)
  std::optional<float> aspectRatio;// the file's W/H, informational
  float xmag = 1.0f, ymag = 1.0f;  // half width and half height of the view (parallel)
  float near = 0.1f;               // eye-space distance
  std::optional<float> far;        // none: infinite (glTF), fitted to the scene later
};

// A point along `direction` from `eye`, for a view's reference point: one
// unit along for an eye within 8192 of the origin (where eye + d turns d by
// at most 5e-4 rad in rounding), and as far along as the eye is from the
// origin (a power of two) beyond, because eye + d loses d to eye's rounding
// (past 2^24 it is eye itself, and the view direction NaN).
glm::vec3 pointAlong(glm::vec3 eye, glm::vec3 direction);

struct Bounds {
  glm::vec3 min{0.0f}, max{0.0f};
  bool empty = true;

  void include(glm::vec3 p);
  glm::vec3 center() const { return (min + max) * 0.5f; }
  float radius() const;  // of the sphere around the box, centred at center()
};

// Which scene content a renderer last derived something from (the GL
// backend's buffers and textures, the checked meshes): a token of its own
// for every Scene made or copied, so that a renderer given the same Scene
// object again can keep what it has, and one given another (even at the
// same address) cannot mistake it. Moving a Scene moves its token.
class SceneIdentity {
 public:
  SceneIdentity() : token_(std::make_shared<char>()) {}
  SceneIdentity(const SceneIdentity&) : SceneIdentity() {}
  SceneIdentity& operator=(const SceneIdentity&) {
    token_ = std::make_shared<char>();
    return *this;
  }
  SceneIdentity(SceneIdentity&&) = default;
  SceneIdentity& operator=(SceneIdentity&&) = default;

  // A new token: the content changed in place.
  void renew() { token_ = std::make_shared<char>(); }
  // Whether `seen` (a token kept by a renderer) is this one.
  bool is(const std::weak_ptr<const char>& seen) const { return !seen.expired() && seen.lock() == token_; }
  std::weak_ptr<const char> token() const { return token_; }

 private:
  std::shared_ptr<const char> token_;
};

struct Scene {
  std::string source;                // file path, or "default scene"
  std::vector<std::string> files;    // what it was read from: the glTF file, then each buffer and image it names; empty: built in
  std::vector<Mesh> meshes;
  std::vector<MeshInstance> instances;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<Light> lights;
  std::vector<SceneCamera> cameras;
  EnvironmentMap environment;        // the settings' environment.map, once loaded
  std::string displacement;          // the settings its meshes were displaced with (pipeline/displacement.h); empty: none
  std::string bumpMapPath;           // the settings' material.bumpMap, once loaded (pipeline/bump_map.h); empty: none
  Texture bumpMap;                   // its heights as a data texture (grey / 255), level 0 read
  // The node tree and its animations (glTF, scene/animation.h): a frame
  // places the instances at settings.time with them; empty: the
  // instances' transforms are all there is.
  SceneAnimation animation;
  // Particle emitters glTF nodes place (extras.facet_particles), drawn with the settings' own.
  std::vector<Emitter> emitters;
  // The settings' volume once read (pipeline/frame_spine.h): its samples,
  // where it sits and its transfer function; ray casting draws it from here.
  struct PlacedVolume {
    std::string file;                    // the scene's own: a volume named as the scene (load_scene.h); volume.file replaces it
    std::shared_ptr<const Volume> data;  // null: none
    glm::mat4 worldFromVolume{1.0f};     // the volume's model space (samples at (i, j, k)·spacing) to world
    TransferFunction transfer;
  } volume;
  // What the scene draws without meshes (a ray-cast or splatted volume's
  // box), counted in worldBounds so that auto cameras and lights frame it.
  Bounds unmeshed;
  std::vector<std::string> warnings; // what a loader skipped or repaired

  std::size_t triangleCount() const;  // over all instances
  Bounds worldBounds() const;         // over all instances' finite world positions

  // For scenes built in code: an opaque material of base colour `color`
  // (linear RGB), metallic and roughness; returns its index.
  int addMaterial(std::string name, glm::vec3 color, float metallic, float roughness);
  // Appends `mesh` with `material` and one instance of it placed by worldFromModel.
  void addObject(Mesh mesh, int material, const glm::mat4& worldFromModel);

  // A code that changes a scene's meshes, materials or textures in place
  // after a renderer has drawn it calls identity.renew() (addMaterial and
  // addObject do).
  SceneIdentity identity;
};

}  // namespace facet
