// The course's pipeline for one triangle, start to finish, in the order
// renderer/PIPELINE.md gives it ("Rasterization", "Shading"):
//
//   vertex program    clip = PM·EM·TM·p and the varyings           (shading/lit_programs.h)
//   clipping          against the view volume, homogeneous         (clipper.h)
//   window            x_w, y_w, z_w and 1/w                        (window_transform.h)
//   set-up            the 1/256 grid, orientation, back-face culling (triangle_setup.h)
//   coverage          the pixel centres inside all three edges     (rasterize.h)
//   interpolation     window z, perspective-correct varyings       (interpolation.h)
//   z-buffer          a fragment is kept where z < the stored z
//   fragment program  flat, Gouraud, Phong or pbr, then fog        (shading/lit_programs.h)
//
// Pass 1 draws every triangle into each light's depth maps; pass 2 draws the
// opaque triangles, the lines and points, then the blended triangles back to
// front into a linear colour buffer (reference_renderer.cpp resolves it).
// No tiles, threads or batches: the fast renderer (cpu_renderer.cpp) gets
// the same pixels by the same rules and programs, and is held equal to this one.
#include "cpu/reference/course_pipeline.h"

#include <algorithm>
#include <string>
#include <vector>

#include "cpu/clipper.h"
#include "cpu/interpolation.h"
#include "cpu/line_pass.h"
#include "cpu/rasterize.h"
#include "cpu/triangle_setup.h"
#include "shading/alpha_mask.h"
#include "shading/blending.h"
#include "shading/fog.h"
#include "shading/lit_programs.h"
#include "shading/shadow_depth.h"

namespace facet::cpu::reference {
namespace {

// One triangle's draw: its uniforms and shadow maps (pass 2), the varyings it
// interpolates in `mode`'s layout, and what its fragments do.
struct TriangleDraw {
  const DrawUniforms* uniforms = nullptr;
  const ShadowMaps* maps = nullptr;
  ShadingMode mode = ShadingMode::Flat;
  int varyings = 0;
  bool cullBackFaces = false, masked = false, blended = false;
  std::uint32_t id = 0;     // 1 + its index in the frame's triangle list
  Illumination flat[2]{};   // flat: the face's, front and back
};

void drawTriangle(const ClipVertex (&vertex)[3], const TriangleDraw& draw, Target& target) {
  const float halfWidth = 0.5f * static_cast<float>(target.width), halfHeight = 0.5f * static_cast<float>(target.height);
  // Clipping: the triangle itself when it lies inside the view volume, else the clipped polygon as a fan.
  WindowVertex window[3];
  for (int k = 0; k < 3; ++k) window[k] = toWindow(vertex[k], halfWidth, halfHeight, draw.varyings);
  std::vector<WindowVertex> fan;
  clipTriangle(vertex[0], vertex[1], vertex[2], window[0], window[1], window[2], halfWidth, halfHeight, draw.varyings, fan);
  for (std::size_t f = 0; f + 2 < fan.size(); f += 3) {
    // Set-up: snapped to the grid, zero area dropped, back faces culled; the vertices in set-up order.
    const WindowVertex* v[3] = {&fan[f], &fan[f + 1], &fan[f + 2]};
    SnappedTriangle snapped;
    PixelBox box;
    if (!snapTriangle({v[0]->x, v[1]->x, v[2]->x}, {v[0]->y, v[1]->y, v[2]->y}, snapped)) continue;
    if (draw.cullBackFaces && !snapped.frontFacing) continue;
    if (!pixelBox(snapped, 0, 0, target.width - 1, target.height - 1, box)) continue;
    toSetUpOrder(snapped, v);
    InterpolationVertex corners[3];
    for (int k = 0; k < 3; ++k) corners[k] = {v[k]->x, v[k]->y, v[k]->z, v[k]->invW, v[k]->varyings.data()};
    Interpolation planes(corners[0], corners[1], corners[2]);
    planes.setUpVaryings(draw.varyings);
    // Coverage, then per pixel: the z-buffer test, the point the varyings describe, the fragment program.
    rasterize(snapped, box, [&](int px, int py) {
      const std::size_t pixel = static_cast<std::size_t>(py) * static_cast<std::size_t>(target.width) + static_cast<std::size_t>(px);
      if (target.counts) {
        ++(*target.counts)[pixel];
        return;
      }
      const float z = planes.depthAt(px, py);
      if (!(z < target.depth[pixel])) return;  // LESS
      const SurfacePoint p = draw.uniforms ? surfacePointAt(planes, *draw.uniforms, draw.mode, draw.varyings, snapped.frontFacing, draw.flat, px, py)
                                           : SurfacePoint{};
      // The alpha mask decides before the fragment writes depth; a blended fragment writes none.
      if (draw.masked && !alphaKept(*draw.uniforms->material, alphaAt(*draw.uniforms, p))) return;
      if (!draw.blended) target.depth[pixel] = z;
      if (target.ids) (*target.ids)[pixel] = draw.id;
      if (!target.color) return;
      const FrameInputs& frame = *draw.uniforms->frame;
      const glm::vec3 lit = fogged(frame.fog, litFragment(*draw.uniforms, *draw.maps, p), eyeDepth(frame, planes.oneOverWAt(px, py), z));
      glm::vec4& held = target.color->at(px, py);
      held = draw.blended ? blend(held, lit, alphaAt(*draw.uniforms, p), frame.blending, draw.uniforms->material->additive) : opaque(lit);
    });
  }
}

}  // namespace

ShadowMaps shadowPass(const Scene& scene, const FrameInputs& frame) {
  ShadowMaps maps;
  maps.reset(frame.shadows.mapSize, frame.shadowLayerCount);
  for (const FrameLight& light : frame.lights) {
    if (!light.hasShadowMap) continue;
    for (int face = 0; face < light.frustum.faceCount; ++face) {
      Target target{maps.size, maps.size, std::vector<float>(static_cast<std::size_t>(maps.size) * static_cast<std::size_t>(maps.size), 1.0f)};
      for (const FrameInstance& instance : frame.instances) {
        const DrawUniforms uniforms = drawUniforms(scene, frame, instance);
        if (!uniforms.material->castsShadow) continue;
        // An alpha-masked or blended material casts a shadow only where its fragments are kept (shadow_depth.frag).
        const bool masked = masksShadow(*uniforms.material);
        const TriangleDraw draw{&uniforms, nullptr, ShadingMode::Flat, masked ? ShadowDepthProgram::kMaskVaryings : 0, false, masked};
        const Mesh& mesh = *uniforms.mesh;
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
          ClipVertex v[3];
          for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t i = mesh.indices[t + k];
            const glm::vec3 world(transformPoint(instance.worldFromModel, mesh.positions[i]));
            v[k].clip = ShadowDepthProgram::vertex(light.frustum.clipFromWorld[static_cast<std::size_t>(face)], mesh, i, world, masked,
                                                   v[k].varyings.data());
          }
          drawTriangle(v, draw, target);
        }
      }
      std::copy(target.depth.begin(), target.depth.end(), maps.layer(light.shadowLayer + face));
    }
  }
  return maps;
}

// Each triangle through the mode's vertex program (flat: and the face's illumination), then drawTriangle.
void litPass(const Scene& scene, const FrameInputs& frame, const ShadowMaps& maps, Target& target, Drawn drawn) {
  const std::vector<std::size_t> first = firstTriangles(scene, frame);
  std::vector<std::uint32_t> order;  // the frame's triangle list, in the order drawn
  if (drawn == Drawn::Blended) order = frame.transparentOrder;
  else
    for (std::size_t i = 0; i < frame.instances.size(); ++i)
      if (drawn == Drawn::All || !frame.materials[static_cast<std::size_t>(frame.instances[i].material)].blended)
        for (std::size_t t = first[i]; t < first[i + 1]; ++t) order.push_back(static_cast<std::uint32_t>(t));
  const int count = varyingLayout(frame.shading).packed(frame.procedural);
  for (const std::uint32_t triangle : order) {
    const std::size_t i = instanceOfTriangle(first, triangle);
    const FrameInstance& instance = frame.instances[i];
    const DrawUniforms uniforms = drawUniforms(scene, frame, instance);
    const DrawMatrices matrices = drawMatrices(instance);
    const Mesh& mesh = *uniforms.mesh;
    TriangleDraw draw{&uniforms, &maps, frame.shading, count, instance.cullBackFaces, uniforms.material->masked, uniforms.material->blended,
                      triangle + 1};
    // Vertex program, at each corner.
    ClipVertex v[3];
    glm::vec3 world[3];
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t index = mesh.indices[3 * (triangle - first[i]) + k];
      world[k] = glm::vec3(transformPoint(instance.worldFromModel, mesh.positions[index]));
      v[k].clip = litVertex(uniforms, matrices, maps, index, world[k], count, v[k].varyings.data());
    }
    if (frame.shading == ShadingMode::Flat) LitFlatProgram::face(uniforms, maps, world[0], world[1], world[2], instance.cullBackFaces, draw.flat);
    drawTriangle(v, draw, target);
  }
}

void linePass(const Scene& scene, const FrameInputs& frame, Target& target) {
  const float halfWidth = 0.5f * static_cast<float>(frame.width), halfHeight = 0.5f * static_cast<float>(frame.height);
  std::vector<DrawnLine> lines;
  for (const FrameInstance& instance : frame.instances) {
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
    const glm::vec3 baseColor = frame.materials[static_cast<std::size_t>(instance.material)].baseColor;
    const auto vertex = [&](std::uint32_t i) {
      ClipVertex v;
      v.clip = transformPoint(instance.clipFromModel, mesh.positions[i]);
      const glm::vec4 rgba = mesh.colors.empty() ? glm::vec4(1.0f) : mesh.colors[i];
      for (int c = 0; c < 3; ++c) v.varyings[static_cast<std::size_t>(c)] = rgba[c];
      return v;
    };
    for (std::size_t s = 0; s + 1 < mesh.lines.size(); s += 2) {
      const ClipVertex a = vertex(mesh.lines[s]), b = vertex(mesh.lines[s + 1]);
      addSegment(a, b, toWindow(a, halfWidth, halfHeight, 3), toWindow(b, halfWidth, halfHeight, 3), frame, baseColor, lines);
    }
    for (const std::uint32_t i : mesh.points) {
      const ClipVertex v = vertex(i);
      addPoint(v, toWindow(v, halfWidth, halfHeight, 3), frame, baseColor, lines);
    }
  }
  drawLines(frame, lines, {0, 0, frame.width - 1, frame.height - 1}, target.depth.data(), frame.width, TilePixels::of(*target.color, 0, 0));
}

}  // namespace facet::cpu::reference
