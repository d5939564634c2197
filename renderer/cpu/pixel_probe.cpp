#include "cpu/pixel_probe.h"

#include <cstdio>

#include <glm/ext/matrix_double4x4.hpp>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "common/error.h"
#include "cpu/cpu_renderer.h"
#include "shading/lighting.h"
#include "cpu/passes.h"
#include "shading/transform.h"
#include "image/srgb.h"

namespace facet {
namespace {

using namespace cpu;

// The world point the pixel centre's ray meets in the triangle's plane, as
// barycentric weights of the corners (Möller-Trumbore, in double): the
// perspective-correct weights, whatever clipping did to the triangle.
glm::dvec3 pixelWeights(const FrameInputs& frame, int x, int y, const glm::vec3 (&corner)[3]) {
  const glm::dmat4 worldFromWindow = glm::inverse(glm::dmat4(frame.clipFromWorld)) * glm::inverse(glm::dmat4(frame.windowFromNdc));
  const auto unproject = [&](double z) {
    const glm::dvec4 p = worldFromWindow * glm::dvec4(x + 0.5, y + 0.5, z, 1.0);
    return glm::dvec3(p) / p.w;
  };
  const glm::dvec3 from = unproject(0.0), direction = unproject(1.0) - from;
  const glm::dvec3 a(corner[0]), e1 = glm::dvec3(corner[1]) - a, e2 = glm::dvec3(corner[2]) - a;
  const glm::dvec3 p = glm::cross(direction, e2);
  const double det = glm::dot(e1, p);
  if (det == 0.0) return {1.0, 0.0, 0.0};  // the triangle seen edge on: it covers no pixel centre
  const glm::dvec3 s = from - a;
  const double u = glm::dot(s, p) / det;
  const double v = glm::dot(direction, glm::cross(s, e1)) / det;
  return {1.0 - u - v, u, v};
}

template <class T>
T weighted(const glm::dvec3& w, const T& a, const T& b, const T& c) {
  return T(static_cast<float>(w.x) * a + static_cast<float>(w.y) * b + static_cast<float>(w.z) * c);
}

std::string vec3Text(glm::vec3 v) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.4f, %.4f, %.4f)", static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z));
  return text;
}

}  // namespace

PixelProbe probePixel(const Scene& scene, const FrameInputs& frame, int x, int y) {
  if (x < 0 || y < 0 || x >= frame.width || y >= frame.height)
    throw Error("probe: pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " + std::to_string(frame.width) + "x" +
                std::to_string(frame.height) + " frame");
  PixelProbe probe;
  probe.x = x;
  probe.y = y;
  const std::size_t pixel = static_cast<std::size_t>(y) * static_cast<std::size_t>(frame.width) + static_cast<std::size_t>(x);
  const RenderResult drawn = makeCpuRenderer(1)->render(scene, frame, {FrameOutput::Image, FrameOutput::TriangleIds});
  probe.triangle = (*drawn.triangleIds)[pixel];
  probe.drawn = drawn.image.at(x, y);
  probe.covered = probe.triangle != 0;
  if (!probe.covered) return probe;

  // The triangle: instances in order, each mesh's triangles in order.
  const std::vector<std::size_t> first = firstTriangles(scene, frame);
  const std::size_t instanceIndex = instanceOfTriangle(first, probe.triangle - 1);
  probe.instance = static_cast<int>(instanceIndex);
  probe.meshTriangle = static_cast<std::uint32_t>(probe.triangle - 1 - first[instanceIndex]);
  const FrameInstance& instance = frame.instances[static_cast<std::size_t>(probe.instance)];
  const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
  const CourseMaterial& material = frame.materials[static_cast<std::size_t>(instance.material)];
  std::uint32_t index[3];
  glm::vec3 normal[3];
  glm::vec4 color[3];
  for (int k = 0; k < 3; ++k) {
    index[k] = mesh.indices[3 * probe.meshTriangle + static_cast<std::uint32_t>(k)];
    probe.vertices[k] = glm::vec3(transformPoint(instance.worldFromModel, mesh.positions[index[k]]));
    normal[k] = normalize3(transformDirection(instance.normalMatrix, mesh.normals[index[k]]));  // as the vertex stage
    color[k] = mesh.colors.empty() ? glm::vec4(1.0f) : mesh.colors[index[k]];
  }
  const glm::dvec3 w = pixelWeights(frame, x, y, probe.vertices);
  probe.weights = glm::vec3(w);
  probe.P = weighted(w, probe.vertices[0], probe.vertices[1], probe.vertices[2]);
  // Two-sided lighting: the back of a triangle that is not culled is lit with -N.
  const glm::vec3 faceNormal = normalize3(cross3(probe.vertices[1] - probe.vertices[0], probe.vertices[2] - probe.vertices[0]));
  const bool front = dot3(faceNormal, viewVector<float>(frame, probe.P)) > 0.0f;
  const float side = front || instance.cullBackFaces ? 1.0f : -1.0f;
  probe.N = side * normalize3(weighted(w, normal[0], normal[1], normal[2]));
  probe.baseColor = material.baseColor * glm::vec3(weighted(w, color[0], color[1], color[2]));

  // Pass 1, as the CPU backend draws it.
  ThreadPool pool(1);
  FrameBuffers buffers;
  ShadowMaps maps;
  prepareFrame(pool, buffers, scene, frame);
  if (frame.shadowLayerCount > 0) {
    maps.reset(frame.shadows.mapSize, frame.shadowLayerCount);
    for (const FrameLight& light : frame.lights)
      if (light.hasShadowMap)
        for (int face = 0; face < light.frustum.faceCount; ++face) shadowPass(pool, buffers, scene, frame, light, face, maps);
  }

  // Where each mode evaluates the equation.
  glm::vec3 P = probe.P, N = probe.N;
  switch (frame.shading) {
    case ShadingMode::Flat:
      P = (probe.vertices[0] + probe.vertices[1] + probe.vertices[2]) / 3.0f;
      N = side * faceNormal;
      probe.shadingNote = "flat: once per triangle, at its centroid with its geometric normal";
      break;
    case ShadingMode::Gouraud:
      probe.shadingNote = "gouraud: the equation at the three vertices, their colours blended by the weights; the terms below are at the pixel's P and N";
      break;
    case ShadingMode::Phong:
      probe.shadingNote = "phong: at the pixel's interpolated P and N";
      break;
    default:
      probe.shadingNote = "pbr shades with the microfacet BRDF; the terms below are the course's equation at the pixel's P and N";
      break;
  }
  if (material.normalMap.texture >= 0 || !scene.bumpMapPath.empty()) probe.shadingNote += "; a normal or bump map bends N per pixel, not shown here";
  if (material.baseColorTexture >= 0) probe.shadingNote += "; O_d's texel is not in the terms";
  if (frame.fog.mode != FogMode::None) probe.shadingNote += "; fog is applied after";
  probe.P = P;
  probe.N = N;
  probe.V = viewVector<float>(frame, P);
  probe.specularColor = (1.0f - material.metallic) + material.metallic * probe.baseColor;
  probe.emissive = material.emissive;
  probe.ka = material.ka, probe.kd = material.kd, probe.ks = material.ks, probe.shininess = material.shininess;
  probe.ambient = (material.ka * frame.ambient) * probe.baseColor;

  // Each light's terms, by the functions illuminate() calls.
  probe.sum = probe.emissive + probe.ambient;
  for (const FrameLight& fl : frame.lights) {
    ProbedLight l;
    const TowardLight<float> toward = towardLight<float>(fl, P);
    l.L = toward.L;
    l.fAtt = toward.fAtt;
    l.reaches = toward.reaches;
    l.NdotL = dot3(N, l.L);
    l.lit = l.reaches && l.NdotL > 0.0f;
    l.RorH = frame.specular == SpecularModel::Phong ? (2.0f * dot3(l.L, N)) * N - l.L : normalize3(l.L + probe.V);
    l.specularBase = frame.specular == SpecularModel::Phong ? dot3(l.RorH, probe.V) : dot3(N, l.RorH);
    l.spec = specularTerm<float>(N, l.L, probe.V, material.shininess, frame.specular);
    l.shadowMapped = fl.hasShadowMap;
    if (fl.hasShadowMap) {
      const ShadowLookup at = shadowLookup(maps, fl, frame.shadows, P, N, l.L);
      l.outsideMap = at.outside;
      l.face = at.face;
      l.texelX = at.tx, l.texelY = at.ty;
      l.depthCompared = at.z;
      l.bias = at.bias;
      if (!at.outside && at.tx >= 0 && at.ty >= 0 && at.tx < maps.size && at.ty < maps.size) l.depthRead = maps.texelFetch(at.layer, at.tx, at.ty);
      l.S = shadowFactor(maps, fl, frame.shadows, P, N, l.L);
    }
    if (l.lit) {
      l.diffuse = (l.S * l.fAtt) * ((material.kd * l.NdotL) * fl.intensity) * probe.baseColor;
      l.specular = (l.S * l.fAtt) * ((material.ks * l.spec) * fl.intensity) * probe.specularColor;
    }
    probe.sum += l.diffuse + l.specular;
    probe.lights.push_back(l);
  }

  // The lit pass's own arithmetic for the same inputs.
  const LaneMaterial<float> lane = laneMaterial(material);
  if (frame.shading == ShadingMode::Gouraud) {
    glm::vec3 vertexColor[3];
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 at = probe.vertices[k], n = side * normal[k];
      vertexColor[k] = shade(illuminate(frame, maps, lane, at, n, viewVector<float>(frame, at)), probe.baseColor);
    }
    probe.shaded = weighted(w, vertexColor[0], vertexColor[1], vertexColor[2]);
  } else {
    probe.shaded = shade(illuminate(frame, maps, lane, P, N, probe.V), probe.baseColor);
  }
  probe.encoded = encodePixel(probe.shaded);
  return probe;
}

std::vector<std::string> describeProbe(const PixelProbe& p) {
  std::vector<std::string> lines;
  char line[256];
  const auto add = [&](const char* format, auto... values) {
    std::snprintf(line, sizeof line, format, values...);
    lines.emplace_back(line);
  };
  add("pixel (%d, %d) from the bottom left; drawn %d %d %d", p.x, p.y, p.drawn.r, p.drawn.g, p.drawn.b);
  if (!p.covered) {
    lines.emplace_back("no triangle covers it: the background");
    return lines;
  }
  add("triangle %u of the frame: instance %d, triangle %u of its mesh", p.triangle, p.instance, p.meshTriangle);
  add("weights %.4f %.4f %.4f (perspective-correct, of the pixel centre)", static_cast<double>(p.weights.x), static_cast<double>(p.weights.y),
      static_cast<double>(p.weights.z));
  lines.push_back(p.shadingNote);
  lines.push_back("P " + vec3Text(p.P) + "  N " + vec3Text(p.N) + "  V " + vec3Text(p.V));
  add("k_a %.3f  k_d %.3f  k_s %.3f  n %.1f", static_cast<double>(p.ka), static_cast<double>(p.kd), static_cast<double>(p.ks),
      static_cast<double>(p.shininess));
  lines.push_back("O_d " + vec3Text(p.baseColor) + "  O_s " + vec3Text(p.specularColor));
  lines.push_back("k_e " + vec3Text(p.emissive) + "  k_a I_a O_d " + vec3Text(p.ambient));
  for (std::size_t i = 0; i < p.lights.size(); ++i) {
    const ProbedLight& l = p.lights[i];
    add("light %zu: L %s  N.L %.4f  f_att %.4f%s", i, vec3Text(l.L).c_str(), static_cast<double>(l.NdotL), static_cast<double>(l.fAtt),
        l.reaches ? "" : "  (outside the spot's cone)");
    add("  R or H %s  base %.4f  spec %.4f", vec3Text(l.RorH).c_str(), static_cast<double>(l.specularBase), static_cast<double>(l.spec));
    if (l.shadowMapped && l.outsideMap) lines.emplace_back("  shadow: outside the map, lit");
    else if (l.shadowMapped)
      add("  shadow: face %d texel (%d, %d) holds %.6f; z %.6f - bias %.6f %s it; S = %.3f", l.face, l.texelX, l.texelY,
          static_cast<double>(l.depthRead), static_cast<double>(l.depthCompared), static_cast<double>(l.bias),
          l.depthCompared - l.bias > l.depthRead ? "is behind" : "is not behind", static_cast<double>(l.S));
    lines.push_back("  diffuse " + vec3Text(l.diffuse) + "  specular " + vec3Text(l.specular) + (l.lit ? "" : " (no light: N.L <= 0 or outside the cone)"));
  }
  lines.push_back("I = sum of the terms " + vec3Text(p.sum) + "; the lit pass: " + vec3Text(p.shaded));
  add("encoded %d %d %d; drawn %d %d %d", p.encoded.r, p.encoded.g, p.encoded.b, p.drawn.r, p.drawn.g, p.drawn.b);
  return lines;
}

}  // namespace facet
