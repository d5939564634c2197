// Pass 2: the camera's z-buffer pass with flat, Gouraud or Phong shading.
//
// Varyings per mode (indices into ClipVertex::varyings):
//   Phong:   world position 0-2, normal 3-5, texture coordinates 6-7
//   Gouraud: front diffuse 0-2, front specular 3-5, back diffuse 6-8,
//            back specular 9-11, texture coordinates 12-13
//   Flat:    texture coordinates 0-1 (illumination is per triangle)
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "cpu/interpolation.h"
#include "cpu/lighting.h"
#include "cpu/passes.h"
#include "cpu/rasterize.h"
#include "cpu/texture_sampling.h"
#include "cpu/vertex_math.h"

namespace facet::cpu {
namespace {

struct Layout {
  int count = 0;  // varyings in use
  int uv = 0;     // first texture coordinate
};

Layout layoutFor(ShadingMode mode) {
  switch (mode) {
    case ShadingMode::Phong: return {8, 6};
    case ShadingMode::Gouraud: return {14, 12};
    default: return {2, 0};
  }
}

void put(std::array<float, kMaxVaryings>& v, int at, glm::vec3 value) {
  for (int k = 0; k < 3; ++k) v[static_cast<std::size_t>(at + k)] = value[k];
}

glm::vec3 get3(const Interpolation& in, int at) { return {in.varying(at), in.varying(at + 1), in.varying(at + 2)}; }

Rgba8 toPixel(glm::vec3 linear) {
  const glm::vec3 encoded = encodeSrgb(linear);
  return {quantize(encoded.r), quantize(encoded.g), quantize(encoded.b), 255};
}

}  // namespace

void litPass(const Scene& scene, const FrameInputs& frame, const ShadowMaps& maps, int rowBegin, int rowEnd, Image& image,
             std::vector<float>& depth) {
  const Layout layout = layoutFor(frame.shading);
  const bool twoSided = !frame.cullBackFaces;
  const float halfWidth = 0.5f * static_cast<float>(frame.width), halfHeight = 0.5f * static_cast<float>(frame.height);
  const auto width = static_cast<std::size_t>(frame.width);
  std::vector<ClipVertex> clip;
  std::vector<WindowVertex> window, triangles;
  std::vector<glm::vec3> worldPositions;

  for (const FrameInstance& instance : frame.instances) {
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
    const CourseMaterial& material = frame.materials[static_cast<std::size_t>(instance.material)];
    const Image* texture = material.baseColorTexture >= 0 && !mesh.texcoords.empty()
                               ? &scene.textures[static_cast<std::size_t>(material.baseColorTexture)].image
                               : nullptr;

    // Vertex stage.
    const std::size_t vertexCount = mesh.positions.size();
    clip.resize(vertexCount);
    window.resize(vertexCount);
    worldPositions.resize(vertexCount);
    for (std::size_t v = 0; v < vertexCount; ++v) {
      ClipVertex& out = clip[v];
      out.clip = transformPoint(instance.clipFromModel, mesh.positions[v]);
      const glm::vec3 P = glm::vec3(transformPoint(instance.worldFromModel, mesh.positions[v]));
      worldPositions[v] = P;
      const glm::vec2 uv = mesh.texcoords.empty() ? glm::vec2(0.0f) : mesh.texcoords[v];
      out.varyings[static_cast<std::size_t>(layout.uv)] = uv.x;
      out.varyings[static_cast<std::size_t>(layout.uv + 1)] = uv.y;
      if (frame.shading == ShadingMode::Phong) {
        put(out.varyings, 0, P);
        put(out.varyings, 3, glm::normalize(transformDirection(instance.normalMatrix, mesh.normals[v])));
      } else if (frame.shading == ShadingMode::Gouraud) {
        const glm::vec3 N = glm::normalize(transformDirection(instance.normalMatrix, mesh.normals[v]));
        const glm::vec3 V = viewVector(frame, P);
        const Illumination front = illuminate(frame, maps, material, P, N, V);
        put(out.varyings, 0, front.diffuse);
        put(out.varyings, 3, front.specular);
        if (twoSided) {
          const Illumination back = illuminate(frame, maps, material, P, -N, V);
          put(out.varyings, 6, back.diffuse);
          put(out.varyings, 9, back.specular);
        }
      }
      window[v] = toWindow(out, halfWidth, halfHeight, layout.count);
    }

    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
      triangles.clear();
      clipTriangle(clip[i0], clip[i1], clip[i2], window[i0], window[i1], window[i2], halfWidth, halfHeight, layout.count, triangles);
      if (triangles.empty()) continue;

      // Flat: one illumination per triangle, from its geometric normal at its centroid.
      Illumination flatFront, flatBack;
      if (frame.shading == ShadingMode::Flat) {
        const glm::vec3 p0 = worldPositions[i0], p1 = worldPositions[i1], p2 = worldPositions[i2];
        const glm::vec3 N = glm::normalize(glm::cross(p1 - p0, p2 - p0));
        const glm::vec3 centroid = (p0 + p1 + p2) / 3.0f;
        const glm::vec3 V = viewVector(frame, centroid);
        flatFront = illuminate(frame, maps, material, centroid, N, V);
        if (twoSided) flatBack = illuminate(frame, maps, material, centroid, -N, V);
      }

      for (std::size_t k = 0; k < triangles.size(); k += 3) {
        TriangleSetup setup;
        if (!setupTriangle(triangles[k], triangles[k + 1], triangles[k + 2], frame.width, frame.height, setup)) continue;
        if (frame.cullBackFaces && !setup.frontFacing) continue;  // signed area ≤ 0 is dropped
        const bool back = !setup.frontFacing;
        Interpolation in(triangles[k], triangles[k + 1], triangles[k + 2]);
        rasterize(setup, rowBegin, rowEnd, [&](int px, int py) {
          const float z = in.at(px, py);
          const std::size_t index = static_cast<std::size_t>(py) * width + static_cast<std::size_t>(px);
          if (!(z < depth[index])) return;  // LESS
          depth[index] = z;
          glm::vec3 baseColor = material.baseColor;
          if (texture) baseColor *= sampleBaseColor(*texture, {in.varying(layout.uv), in.varying(layout.uv + 1)});
          glm::vec3 color;
          if (frame.shading == ShadingMode::Phong) {
            const glm::vec3 P = get3(in, 0);
            glm::vec3 N = glm::normalize(get3(in, 3));
            if (back) N = -N;  // two-sided lighting
            color = shade(illuminate(frame, maps, material, P, N, viewVector(frame, P)), baseColor);
          } else if (frame.shading == ShadingMode::Gouraud) {
            const int side = back ? 6 : 0;
            color = shade({get3(in, side), get3(in, side + 3)}, baseColor);
          } else {
            color = shade(back ? flatBack : flatFront, baseColor);
          }
          image.at(px, py) = toPixel(color);
        });
      }
    }
  }
}

}  // namespace facet::cpu
