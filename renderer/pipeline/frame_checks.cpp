#include "pipeline/frame_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "common/error.h"
#include "common/quote.h"
#include "image/mipmap.h"
#include "math/eye_matrix.h"
#include "particles/particle_system.h"
#include "scene/memory_budget.h"
#include "scene/transfer_function.h"

namespace facet {
namespace {

// -1 (none) or a texture of the scene with an image.
bool textureUsable(const Scene& scene, int texture) {
  return texture == -1 || (texture >= 0 && texture < static_cast<int>(scene.textures.size()) &&
                           !scene.textures[static_cast<std::size_t>(texture)].image.empty());
}

}  // namespace

namespace {

std::string meshName(const Scene& scene, std::size_t m) {
  const std::string& name = scene.meshes[m].name;
  return "mesh " + std::to_string(m) + (name.empty() ? "" : " '" + name + "'");
}

void checkMesh(const Scene& scene, std::size_t m) {
  const Mesh& mesh = scene.meshes[m];
  const std::size_t n = mesh.positions.size();
  if (mesh.normals.size() != n)
    throw Error(meshName(scene, m) + ": " + std::to_string(mesh.normals.size()) + " normals for " + std::to_string(n) + " positions");
  for (int set = 0; set < 2; ++set)
    if (const std::vector<glm::vec2>& uv = mesh.texcoordSet(set); !uv.empty() && uv.size() != n)
      throw Error(meshName(scene, m) + ": " + std::to_string(uv.size()) + " TEXCOORD_" + std::to_string(set) + " texture coordinates for " +
                  std::to_string(n) + " positions");
  if (!mesh.colors.empty() && mesh.colors.size() != n)
    throw Error(meshName(scene, m) + ": " + std::to_string(mesh.colors.size()) + " vertex colours for " + std::to_string(n) + " positions");
  const bool untextured = mesh.texcoords.empty() && mesh.texcoords1.empty();
  if (!mesh.tangents.empty() && (mesh.tangents.size() != n || untextured))
    throw Error(meshName(scene, m) + ": " + std::to_string(mesh.tangents.size()) + " tangents for " + std::to_string(n) + " positions" +
                (untextured ? " and no texture coordinates" : ""));
  if (n >= kMaxFrameVertices) throw Error(meshName(scene, m) + ": " + std::to_string(n) + " vertices, more than a frame holds");
  for (const std::vector<std::uint32_t>* list : {&mesh.indices, &mesh.lines, &mesh.points})
    for (std::size_t i = 0; i < list->size(); ++i)
      if ((*list)[i] >= n)
        throw Error(meshName(scene, m) + ": " + (list == &mesh.indices ? "index " : list == &mesh.lines ? "line index " : "point index ") +
                    std::to_string((*list)[i]) + " (at " + std::to_string(i) + ") is not below its " + std::to_string(n) + " positions");
  if (mesh.material < -1 || mesh.material >= static_cast<int>(scene.materials.size()))
    throw Error(meshName(scene, m) + ": material " + std::to_string(mesh.material) + " does not exist");
}

// What the frame will work in, priced before a backend allocates it
// (scene/memory_budget.h): every instance's vertex and triangle buffers,
// then the shadow maps, against kFrameMemoryBudget. Arithmetic only while
// the frame fits: a settled frame allocates nothing here (the CPU
// backend's allocation test counts it); the messages are built on refusal.
void checkFrameMemory(const Scene& scene, const FrameInputs& frame) {
  std::uint64_t geometry = 0, vertices = 0, triangles = 0;
  for (const FrameInstance& instance : frame.instances) {
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
    vertices += mesh.positions.size();
    triangles += mesh.triangleCount();
    // a segment or a point is priced as a triangle: its set-up is no larger
    geometry += instanceFrameBytes(mesh.positions.size(), mesh.triangleCount() + mesh.segmentCount() + mesh.points.size());
  }
  const std::uint64_t shadows = shadowMapBytes(frame.shadows.mapSize, frame.shadowLayerCount);
  if (geometry <= kFrameMemoryBudget && shadows <= kFrameMemoryBudget - geometry) return;

  const std::string source = scene.source.empty() ? "" : scene.source + ": ";
  MemoryBudget budget(kFrameMemoryBudget, "frame budget");
  budget.charge(geometry, source + "the vertex and triangle buffers of " + countOf(frame.instances.size(), "instance") + " (" +
                              countOf(vertices, "vertex", "vertices") + ", " + countOf(triangles, "triangle") + ")");
  std::size_t lights = 0;
  for (const FrameLight& light : frame.lights) lights += light.hasShadowMap ? 1 : 0;
  try {
    budget.charge(shadows, source + "the shadow maps of " + countOf(lights, "light") + " (" + countOf(frame.shadowLayerCount, "face") + " of " +
                               std::to_string(frame.shadows.mapSize) + "x" + std::to_string(frame.shadows.mapSize) + " depth texels)");
  } catch (const Error& e) {
    // Here the geometry fit and the shadow maps did not, so there is at least one face.
    const std::uint64_t left = budget.limit() - budget.used();
    const auto fits = static_cast<std::uint64_t>(std::sqrt(static_cast<double>(left / shadowMapBytes(1, frame.shadowLayerCount))));
    throw Error(std::string(e.what()) + " (settings key 'shadows.mapSize': " +
                (fits >= static_cast<std::uint64_t>(kMinShadowMapSize) ? std::to_string(fits) + " or less fits" : "no size fits") +
                ", or shadows.enabled=false)");
  }
}

// Three significant digits: 1.23e+09.
std::string figure(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

// The shadow pass's work on sprite quads, which overlap by the thousand and
// may each cover a whole face: Σ over the shadow-casting sprites, lights and
// faces of the texels of the quad's bounding box in the face's window
// (clipped to the face; a quad across the plane of the light's eye counts
// the whole face), against kMaxShadowSpriteTexels. Only sprite meshes:
// ordinary surfaces do not stack so.
void checkSpriteShadows(const Scene& scene, const FrameInputs& frame) {
  if (frame.shadowLayerCount == 0) return;
  const double side = frame.shadows.mapSize;
  const double face = side * side;
  double texels = 0.0;
  std::uint64_t sprites = 0;
  for (const FrameInstance& instance : frame.instances) {
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
    if (!mesh.sprites || !frame.materials[static_cast<std::size_t>(instance.material)].castsShadow) continue;
    sprites += mesh.positions.size() / 4;
    for (const FrameLight& light : frame.lights) {
      if (!light.hasShadowMap) continue;
      for (int f = 0; f < light.frustum.faceCount; ++f) {
        const glm::mat4 clipFromModel = light.frustum.clipFromWorld[static_cast<std::size_t>(f)] * instance.worldFromModel;
        for (std::size_t q = 0; q + 3 < mesh.positions.size(); q += 4) {
          glm::vec2 low(1.0f), high(-1.0f);
          int behind = 0;
          for (std::size_t k = q; k < q + 4; ++k) {
            const glm::vec4 clip = clipFromModel * glm::vec4(mesh.positions[k], 1.0f);
            if (!(clip.w > 0.0f)) {
              ++behind;
              continue;
            }
            const glm::vec2 ndc = glm::vec2(clip) / clip.w;
            low = glm::min(low, ndc);
            high = glm::max(high, ndc);
          }
          if (behind == 4) continue;  // wholly behind the light's eye: not in this face
          if (behind > 0) {           // across the eye's plane: up to the whole face
            texels += face;
            continue;
          }
          low = glm::max(low, glm::vec2(-1.0f));
          high = glm::min(high, glm::vec2(1.0f));
          if (high.x > low.x && high.y > low.y)
            texels += static_cast<double>(high.x - low.x) * static_cast<double>(high.y - low.y) / 4.0 * face;
        }
      }
    }
  }
  if (texels > kMaxShadowSpriteTexels)
    throw Error("settings key 'shadows.mapSize': the shadow maps of " + std::to_string(sprites) + " sprites (volume splats, particles) would take " +
                figure(texels) + " texel writes, more than the " + figure(kMaxShadowSpriteTexels) +
                " a frame may take; a smaller shadows.mapSize, smaller sprites, or shadows.enabled=false");
}

}  // namespace

void checkEyeFrame(const CameraSettings& camera) {
  if (const char* problem = eyeFrameProblem(camera.eye, camera.reference, camera.up))
    throw Error(std::string("settings key 'camera': eye, reference and up do not define a view (") + problem + ")");
}

void checkSettings(const RenderSettings& settings) {
  // The control points do not depend on the data range; a preset fits any.
  parseTransferFunction(settings.volume.transfer, 0.0f, 1.0f);
  if (settings.camera.source == Source::Manual) checkEyeFrame(settings.camera);
  for (std::size_t i = 0; i < settings.particles.size(); ++i) {
    const std::string key = "particles." + std::to_string(i);
    try {
      checkEmitter(settings.particles[i], settings.particles[i].step, key);
    } catch (const Error& e) {
      const std::string message = e.what();  // "particles.0.drag: ..."
      const std::size_t colon = message.find(':');
      throw Error("settings key '" + message.substr(0, colon) + "'" + message.substr(colon));
    }
  }
}

void checkScene(const Scene& scene) {
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const int mesh = scene.instances[i].mesh;
    if (mesh < 0 || static_cast<std::size_t>(mesh) >= scene.meshes.size())
      throw Error("instance " + std::to_string(i) + ": mesh " + std::to_string(mesh) + " does not exist (the scene has " +
                  std::to_string(scene.meshes.size()) + ")");
  }
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) checkMesh(scene, m);
  // Both backends read a texture's levels by mipLevels' sizes.
  for (std::size_t t = 0; t < scene.textures.size(); ++t) {
    const Texture& texture = scene.textures[t];
    bool laidOut = texture.mips.size() == static_cast<std::size_t>(texture.image.empty() ? 0 : mipLevelCount(texture.image.width(), texture.image.height()));
    for (int k = 1; laidOut && k < texture.levelCount(); ++k)
      laidOut = texture.level(k).width() == std::max(1, texture.level(k - 1).width() / 2) &&
                texture.level(k).height() == std::max(1, texture.level(k - 1).height() / 2);
    if (!laidOut) throw Error("texture " + std::to_string(t) + " '" + texture.name + "': its mipmaps are not image/mipmap.h's levels of its image");
  }
  for (std::size_t m = 0; m < scene.materials.size(); ++m) {
    const Material& material = scene.materials[m];
    const std::pair<const char*, int> maps[] = {{"base colour", material.baseColorTexture},
                                                {"metallic-roughness", material.metallicRoughnessTexture},
                                                {"occlusion", material.occlusionTexture},
                                                {"emissive", material.emissiveTexture},
                                                {"normal", material.normalTexture}};
    for (const auto& [what, texture] : maps)
      if (!textureUsable(scene, texture))
        throw Error("material " + std::to_string(m) + " '" + material.name + "': " + what + " texture " + std::to_string(texture) + " is missing or empty");
  }
}

void checkFrame(const Scene& scene, const FrameInputs& frame) {
  if (frame.width < 1 || frame.height < 1 || frame.width > kMaxImageSide || frame.height > kMaxImageSide)
    throw Error("image size " + std::to_string(frame.width) + "x" + std::to_string(frame.height) + ": each side must be in [1, " +
                std::to_string(kMaxImageSide) + "]");
  if (frame.lights.size() > kMaxLights)
    throw Error(std::to_string(frame.lights.size()) + " lights: a frame shades at most " + std::to_string(kMaxLights));
  std::size_t vertices = 0;
  for (std::size_t i = 0; i < frame.instances.size(); ++i) {
    const FrameInstance& instance = frame.instances[i];
    if (instance.mesh < 0 || static_cast<std::size_t>(instance.mesh) >= scene.meshes.size())
      throw Error("frame instance " + std::to_string(i) + ": mesh " + std::to_string(instance.mesh) + " is not in the scene");
    if (instance.material < 0 || static_cast<std::size_t>(instance.material) >= frame.materials.size())
      throw Error("frame instance " + std::to_string(i) + ": material " + std::to_string(instance.material) + " is not in the frame");
    const CourseMaterial& material = frame.materials[static_cast<std::size_t>(instance.material)];
    for (const int texture : {material.baseColorTexture, material.metallicRoughnessMap.texture, material.occlusionMap.texture, material.emissiveMap.texture,
                               material.normalMap.texture})
      if (!textureUsable(scene, texture))
        throw Error("frame instance " + std::to_string(i) + ": texture " + std::to_string(texture) + " of its material is missing or empty");
    vertices += scene.meshes[static_cast<std::size_t>(instance.mesh)].positions.size();
  }
  if (vertices >= kMaxFrameVertices) throw Error(std::to_string(vertices) + " vertices over the frame's instances: more than a frame holds");
  int layers = 0;
  for (const FrameLight& light : frame.lights) {
    if (!light.hasShadowMap) continue;
    if (light.frustum.faceCount < 1 || light.frustum.faceCount > 6 || light.shadowLayer != layers)
      throw Error("a shadow-casting light's faces are not laid out as buildFrameInputs lays them out");
    layers += light.frustum.faceCount;
  }
  if (layers != frame.shadowLayerCount) throw Error("the frame's shadow layer count does not match its lights");
  if (layers > 0 && (frame.shadows.mapSize < 1 || frame.shadows.mapSize > kMaxShadowMapSize))
    throw Error("settings key 'shadows.mapSize': " + std::to_string(frame.shadows.mapSize) + " is not in [1, " +
                std::to_string(kMaxShadowMapSize) + "]");
  if (frame.shadows.pcfRadius < 0 || frame.shadows.pcfRadius > kMaxPcfRadius)
    throw Error("settings key 'shadows.pcfRadius': " + std::to_string(frame.shadows.pcfRadius) + " is not in [0, " + std::to_string(kMaxPcfRadius) +
                "]");
  checkFrameMemory(scene, frame);  // last: the sizes it prices are within their limits
  checkSpriteShadows(scene, frame);
}

void FrameCheck::operator()(const Scene& scene, const FrameInputs& frame) {
  if (!scene.identity.is(checked_)) {
    checkScene(scene);
    checked_ = scene.identity.token();
  }
  checkFrame(scene, frame);
}

}  // namespace facet
