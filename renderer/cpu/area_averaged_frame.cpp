#include "cpu/area_averaged_frame.h"

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "common/error.h"
#include "common/quote.h"
#include "common/stopwatch.h"
#include "cpu/area_averaging.h"
#include "cpu/clipper.h"
#include "cpu/interpolation.h"
#include "cpu/triangle_setup.h"
#include "image/srgb.h"
#include "shading/alpha_mask.h"
#include "shading/blending.h"
#include "shading/fog.h"
#include "shading/lit_programs.h"

namespace facet::cpu {
namespace {

// Area-weighted averaging covers triangles by the z-buffer's visibility.
void refuseOutsideArea(const Scene& scene, const FrameInputs& frame) {
  if (frame.hsr == HiddenSurface::Painter)
    throw Error("settings key 'hsr': area-weighted averaging (antialiasing.pattern=area) resolves visibility by depth; painter is drawn with grid or jittered samples");
  for (const FrameInstance& instance : frame.instances) {
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
    if (!mesh.lines.empty() || !mesh.points.empty())
      throw Error("settings key 'antialiasing.pattern': area covers triangles only, and mesh " + quoteInput(mesh.name) +
                  " has lines or points; draw them with grid or jittered samples");
  }
}

// Pass 2's triangles in the z-buffer's order (the opaque ones, instances in
// order, then the blended ones back to front), each as set up: collected as
// surfaces, or (once every pixel is cut) shaded in the cells it shows in.
void drawInto(AreaAveraging& area, const Scene& scene, const FrameInputs& frame, const ShadowMaps& maps) {
  const std::vector<std::size_t> first = firstTriangles(scene, frame);
  std::vector<std::uint32_t> order;
  for (std::size_t i = 0; i < frame.instances.size(); ++i)
    if (!frame.materials[static_cast<std::size_t>(frame.instances[i].material)].blended)
      for (std::size_t t = first[i]; t < first[i + 1]; ++t) order.push_back(static_cast<std::uint32_t>(t));
  order.insert(order.end(), frame.transparentOrder.begin(), frame.transparentOrder.end());
  const int count = varyingLayout(frame.shading).packed(frame.procedural);
  const float halfWidth = 0.5f * static_cast<float>(frame.width), halfHeight = 0.5f * static_cast<float>(frame.height);
  for (const std::uint32_t triangle : order) {
    const std::size_t i = instanceOfTriangle(first, triangle);
    const FrameInstance& instance = frame.instances[i];
    const DrawUniforms uniforms = drawUniforms(scene, frame, instance);
    const DrawMatrices matrices = drawMatrices(instance);
    const CourseMaterial& material = *uniforms.material;
    ClipVertex vertex[3];
    glm::vec3 world[3];
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t index = uniforms.mesh->indices[3 * (triangle - first[i]) + k];
      world[k] = glm::vec3(transformPoint(instance.worldFromModel, uniforms.mesh->positions[index]));
      vertex[k].clip = litVertex(uniforms, matrices, maps, index, world[k], count, vertex[k].varyings.data());
    }
    Illumination flat[2];
    if (frame.shading == ShadingMode::Flat) LitFlatProgram::face(uniforms, maps, world[0], world[1], world[2], instance.cullBackFaces, flat);
    WindowVertex window[3];
    for (int k = 0; k < 3; ++k) window[k] = toWindow(vertex[k], halfWidth, halfHeight, count);
    std::vector<WindowVertex> fan;
    clipTriangle(vertex[0], vertex[1], vertex[2], window[0], window[1], window[2], halfWidth, halfHeight, count, fan);
    for (std::size_t f = 0; f + 2 < fan.size(); f += 3) {
      const WindowVertex* v[3] = {&fan[f], &fan[f + 1], &fan[f + 2]};
      SnappedTriangle snapped;
      if (!snapTriangle({v[0]->x, v[1]->x, v[2]->x}, {v[0]->y, v[1]->y, v[2]->y}, snapped)) continue;
      if (instance.cullBackFaces && !snapped.frontFacing) continue;  // a triangle that covers no pixel centre counts too
      toSetUpOrder(snapped, v);
      InterpolationVertex corners[3];
      for (int k = 0; k < 3; ++k) corners[k] = {v[k]->x, v[k]->y, v[k]->z, v[k]->invW, v[k]->varyings.data()};
      Interpolation planes(corners[0], corners[1], corners[2]);
      planes.setUpVaryings(count);
      if (area.collecting()) {
        area.collect(snapped, planes, material.blended ? AreaRole::Blended : material.masked ? AreaRole::Masked : AreaRole::Opaque, material.additive);
        continue;
      }
      // A cell's fragment: the fragment program at the cell's centroid (the planes moved there), through the fog.
      area.shade(planes, [&](const Interpolation& moved, int px, int py) -> std::optional<glm::vec4> {
        const SurfacePoint p = surfacePointAt(moved, uniforms, frame.shading, count, snapped.frontFacing, flat, px, py);
        if (material.masked && !alphaKept(material, alphaAt(uniforms, p))) return std::nullopt;
        const glm::vec3 lit = fogged(frame.fog, litFragment(uniforms, maps, p), eyeDepth(frame, moved.oneOverWAt(px, py), moved.depthAt(px, py)));
        return glm::vec4(lit, material.blended ? alphaAt(uniforms, p) : 1.0f);
      });
    }
  }
}

}  // namespace

RenderResult renderAreaAveraged(const Scene& scene, const FrameInputs& frame, const ShadowMaps& maps) {
  refuseOutsideArea(scene, frame);
  const auto start = std::chrono::steady_clock::now();
  AreaAveraging area(frame.width, frame.height);
  drawInto(area, scene, frame, maps);  // the surfaces
  area.cut();
  drawInto(area, scene, frame, maps);  // their fragments
  const ColorBuffer sum = area.composite(frame);
  RenderResult result;
  result.image = Image(frame.width, frame.height);
  for (int y = 0; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x) result.image.at(x, y) = encodePixel(unstored(sum.at(x, y), Blending::Premultiplied));
  result.timings.push_back({"area-weighted averaging", millisecondsSince(start)});
  result.notes.push_back(area.summary());
  return result;
}

}  // namespace facet::cpu
