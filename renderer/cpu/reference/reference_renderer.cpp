// The course's pipeline for one triangle, start to finish, in the order
// renderer/PIPELINE.md (sections 6 and 7) gives it:
//
//   vertex stage    clip = PM·EM·TM·p, and what the shading mode interpolates
//   clipping        against the view volume, in homogeneous coordinates   (clipper.h)
//   window          x_w, y_w, z_w and 1/w                                  (window_transform.h)
//   set-up          the 1/256 grid, the orientation, back-face culling     (triangle_setup.h)
//   coverage        the pixel centres inside all three edges               (rasterize.h)
//   interpolation   window z and perspective-correct varyings by planes    (interpolation.h)
//   z-buffer        a fragment is kept where z < the stored z
//   shading         flat, Gouraud or Phong: the illumination equation      (lighting.h)
//
// Pass 1 draws every triangle into each light's depth maps; pass 2 draws
// them into a linear colour buffer, resolved to the image. No tiles, threads or batches: the fast renderer
// (cpu_renderer.cpp) gets the same pixels by the same rules. Area-weighted
// averaging (antialiasing.pattern=area) draws pass 2 twice, in place of
// coverage: once to cut the pixels into cells, once to shade them (area_averaging.h).
#include "shading/fog.h"
#include "cpu/reference/reference_renderer.h"
#include "cpu/reference/area_averaging.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <functional>
#include <vector>

#include "common/error.h"
#include "common/quote.h"
#include "common/stopwatch.h"
#include "cpu/alpha_mask.h"
#include "shading/bump_mapping.h"
#include "cpu/clipper.h"
#include "shading/environment.h"
#include "shading/procedural.h"
#include "cpu/interpolation.h"
#include "shading/normal_mapping.h"
#include "shading/lighting.h"
#include "cpu/line_pass.h"
#include "shading/physically_based.h"
#include "cpu/rasterize.h"
#include "shading/shadow_maps.h"
#include "shading/surface_shading.h"
#include "shading/texture.h"
#include "cpu/triangle_setup.h"
#include "cpu/varyings.h"
#include "shading/blending.h"
#include "shading/transform.h"
#include "image/srgb.h"
#include "pipeline/frame_checks.h"

namespace facet {
namespace {

using namespace cpu;

// A z-buffer, and in the lit pass the colour buffer (or the triangle ids) it guards.
struct Target {
  int width = 0, height = 0;
  std::vector<float> depth;                   // window z, cleared to 1
  ColorBuffer* color = nullptr;               // pass 2: the linear colour of each kept fragment
  std::vector<std::uint32_t>* ids = nullptr;  // or which triangle it came from
  std::vector<std::uint32_t>* counts = nullptr;  // or how many fragments each pixel received (no test, nothing drawn)
  AreaAveraging* area = nullptr;              // or, in place of coverage, area-weighted averaging's surfaces and cells
};

// The fragment stage: the pixel's interpolated varyings, the side seen, and
// the triangle's planes at the pixel (for the texture derivatives) -> linear colour.
using FragmentShader = std::function<glm::vec3(const float* varyings, bool frontFacing, const Interpolation& planes, int px, int py)>;

// Whether a fragment that passed the z-test is kept (the alpha mask), before it writes depth.
using FragmentTest = std::function<bool(const Interpolation& planes, int px, int py)>;

// Transparency: a blended fragment's α; it is tested, writes no depth and blends into the colour buffer.
using FragmentAlpha = std::function<float(const Interpolation& planes, int px, int py)>;

// One triangle, its three vertices after the vertex stage, to the z-buffer.
void drawTriangle(const ClipVertex (&vertex)[3], int varyingCount, bool cullBackFaces, std::uint32_t id, Target& target,
                  const FragmentShader& shade, const FragmentTest& keep = nullptr, const FragmentAlpha& blendedAlpha = nullptr,
                  Blending blending = Blending::Straight, bool additive = false) {
  const float halfWidth = 0.5f * static_cast<float>(target.width), halfHeight = 0.5f * static_cast<float>(target.height);
  // Clipping: the triangle itself when it lies inside the view volume, else the clipped polygon as a fan.
  WindowVertex window[3];
  for (int k = 0; k < 3; ++k) window[k] = toWindow(vertex[k], halfWidth, halfHeight, varyingCount);
  std::vector<WindowVertex> fan;
  clipTriangle(vertex[0], vertex[1], vertex[2], window[0], window[1], window[2], halfWidth, halfHeight, varyingCount, fan);
  for (std::size_t f = 0; f + 2 < fan.size(); f += 3) {
    // Set-up: snapped to the grid, zero area dropped, back faces culled; the vertices in set-up order.
    const WindowVertex* v[3] = {&fan[f], &fan[f + 1], &fan[f + 2]};
    SnappedTriangle snapped;
    PixelBox box;
    if (!snapTriangle({v[0]->x, v[1]->x, v[2]->x}, {v[0]->y, v[1]->y, v[2]->y}, snapped)) continue;
    if (cullBackFaces && !snapped.frontFacing) continue;
    // (Area-weighted averaging counts a triangle that covers no pixel centre too.)
    if (!target.area && !pixelBox(snapped, 0, 0, target.width - 1, target.height - 1, box)) continue;
    toSetUpOrder(snapped, v);
    InterpolationVertex corners[3];
    for (int k = 0; k < 3; ++k) corners[k] = {v[k]->x, v[k]->y, v[k]->z, v[k]->invW, v[k]->varyings.data()};
    Interpolation planes(corners[0], corners[1], corners[2]);
    planes.setUpVaryings(varyingCount);
    if (target.area) {  // area-weighted averaging: the triangle as a surface, or its fragments in the cells it shows in
      if (target.area->collecting()) {
        target.area->collect(snapped, planes, blendedAlpha ? AreaRole::Blended : keep ? AreaRole::Masked : AreaRole::Opaque, additive);
        continue;
      }
      target.area->shade(planes, [&](const Interpolation& moved, int px, int py) -> std::optional<glm::vec4> {
        if (keep && !keep(moved, px, py)) return std::nullopt;
        float varyings[kMaxVaryings];
        moved.varyingsAt(px, py, varyings);
        return glm::vec4(shade(varyings, snapped.frontFacing, moved, px, py), blendedAlpha ? blendedAlpha(moved, px, py) : 1.0f);
      });
      continue;
    }
    // Coverage, then per pixel: depth, the z-buffer test, the varyings, the fragment's colour.
    rasterize(snapped, box, [&](int px, int py) {
      const std::size_t pixel = static_cast<std::size_t>(py) * static_cast<std::size_t>(target.width) + static_cast<std::size_t>(px);
      if (target.counts) {
        ++(*target.counts)[pixel];
        return;
      }
      const float z = planes.depthAt(px, py);
      if (!(z < target.depth[pixel])) return;
      if (keep && !keep(planes, px, py)) return;
      if (!blendedAlpha) target.depth[pixel] = z;
      if (target.ids) (*target.ids)[pixel] = id;
      if (!target.color) return;
      float varyings[kMaxVaryings];
      planes.varyingsAt(px, py, varyings);
      const glm::vec3 lit = shade(varyings, snapped.frontFacing, planes, px, py);
      glm::vec4& held = target.color->at(px, py);
      held = blendedAlpha ? blend(held, lit, blendedAlpha(planes, px, py), blending, additive) : opaque(lit);
    });
  }
}

// Pass 1: every triangle, unculled, into each face of each shadow-casting light.
ShadowMaps shadowPass(const Scene& scene, const FrameInputs& frame) {
  ShadowMaps maps;
  maps.reset(frame.shadows.mapSize, frame.shadowLayerCount);
  for (const FrameLight& light : frame.lights) {
    if (!light.hasShadowMap) continue;
    for (int face = 0; face < light.frustum.faceCount; ++face) {
      Target target{maps.size, maps.size, std::vector<float>(static_cast<std::size_t>(maps.size) * static_cast<std::size_t>(maps.size), 1.0f)};
      for (const FrameInstance& instance : frame.instances) {
        const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
        // An alpha-masked material casts a shadow only where its fragments are kept: it
        // interpolates texture coordinates and vertex alpha, in the flat layout's places.
        const CourseMaterial& material = frame.materials[static_cast<std::size_t>(instance.material)];
        if (!material.castsShadow) continue;
        const VaryingLayout mask = varyingLayout(ShadingMode::Flat);
        const Texture* texture = baseColorTextureOf(scene, frame, material, mesh);
        const bool colored = !mesh.colors.empty();
        const FragmentTest keep = [&](const Interpolation& planes, int px, int py) {
          return keepsFragment(material, texture, colored, mask, planes, px, py);
        };
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
          ClipVertex v[3];
          for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t i = mesh.indices[t + k];
            const glm::vec3 world = glm::vec3(transformPoint(instance.worldFromModel, mesh.positions[i]));
            v[k].clip = transformPoint(light.frustum.clipFromWorld[static_cast<std::size_t>(face)], world);
            const glm::vec4 rgba = colored ? mesh.colors[i] : glm::vec4(1.0f);
            putTexcoords(v[k].varyings.data(), mask.uv, mesh, i);
            for (int c = 0; c < 4; ++c) v[k].varyings[static_cast<std::size_t>(mask.color + c)] = rgba[c];
          }
          drawTriangle(v, masksShadow(material) ? mask.count : 0, false, 0, target, nullptr, masksShadow(material) ? keep : nullptr);
        }
      }
      std::copy(target.depth.begin(), target.depth.end(), maps.layer(light.shadowLayer + face));
    }
  }
  return maps;
}

// Triangles [first, first + count) of one instance's mesh.
struct Run {
  std::size_t instance = 0;
  std::size_t first = 0, count = 0;
};

// Which triangles pass 2 draws, in their order: the opaque ones (instances in
// order), the blended ones (FrameInputs::transparentOrder), or every one.
enum class Drawn { Opaque, Blended, All };

std::vector<Run> runsOf(const Scene& scene, const FrameInputs& frame, Drawn drawn, std::vector<std::size_t>& firstTriangle) {
  firstTriangle = firstTriangles(scene, frame);
  std::vector<Run> runs;
  if (drawn == Drawn::Blended) {
    for (const std::uint32_t triangle : frame.transparentOrder) {
      const std::size_t i = instanceOfTriangle(firstTriangle, triangle);
      const std::size_t local = triangle - firstTriangle[i];
      if (!runs.empty() && runs.back().instance == i && runs.back().first + runs.back().count == local) ++runs.back().count;
      else runs.push_back({i, local, 1});
    }
    return runs;
  }
  for (std::size_t i = 0; i < frame.instances.size(); ++i)
    if (drawn == Drawn::All || !frame.materials[static_cast<std::size_t>(frame.instances[i].material)].blended)
      runs.push_back({i, 0, firstTriangle[i + 1] - firstTriangle[i]});
  return runs;
}

// Pass 2: the triangles `drawn` into the image, shaded by its mode, with the
// varyings of varyings.h (Phong: position, normal; Gouraud: the
// illumination of both sides; all: texture coordinates and vertex colour).
void litPass(const Scene& scene, const FrameInputs& frame, const ShadowMaps& maps, Target& target, Drawn drawn) {
  const VaryingLayout layout = varyingLayout(frame.shading);
  const int count = layout.packed(frame.procedural), color = layout.color, model = layout.model;
  std::vector<std::size_t> firstTriangle;
  for (const Run& run : runsOf(scene, frame, drawn, firstTriangle)) {
    const FrameInstance& instance = frame.instances[run.instance];
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
    const CourseMaterial& material = frame.materials[static_cast<std::size_t>(instance.material)];
    // What the fragment stage shades with (shading/surface_shading.h), and a texture coordinate set at a pixel, from its varyings.
    const SurfaceDraw draw = surfaceDraw(scene, frame, instance);
    const Texture* texture = draw.texture;
    const bool colored = draw.colored;
    const LaneMaterial<float> summed = draw.summed;
    const auto stOf = [&](const float* v, int set) { return glm::vec2(v[layout.texcoord(set)], v[layout.texcoord(set) + 1]); };
    const FragmentTest keep = [&](const Interpolation& planes, int px, int py) {
      return keepsFragment(material, texture, colored, layout, planes, px, py);
    };
    const FragmentAlpha alpha = [&](const Interpolation& planes, int px, int py) {
      return fragmentAlphaAt(material, texture, colored, layout, planes, px, py);
    };
    for (std::size_t t = 3 * run.first; t < 3 * (run.first + run.count); t += 3) {
      // Vertex stage.
      ClipVertex v[3];
      glm::vec3 world[3];
      for (std::size_t k = 0; k < 3; ++k) {
        const std::uint32_t i = mesh.indices[t + k];
        v[k].clip = transformPoint(instance.clipFromModel, mesh.positions[i]);
        world[k] = glm::vec3(transformPoint(instance.worldFromModel, mesh.positions[i]));
        const glm::vec3 N = normalize3(transformDirection(instance.normalMatrix, mesh.normals[i]));
        float* out = v[k].varyings.data();
        putTexcoords(out, layout.uv, mesh, i);
        const glm::vec4 rgba = colored ? mesh.colors[i] : glm::vec4(1.0f);
        for (int c = 0; c < 4; ++c) out[color + c] = rgba[c];
        if (count == layout.count)
          for (int c = 0; c < 3; ++c) out[model + c] = mesh.positions[i][c];
        if (interpolatesNormals(frame.shading)) {
          for (int c = 0; c < 3; ++c) out[c] = world[k][c], out[3 + c] = N[c];
          const glm::vec4 tangent = mesh.tangents.empty() ? glm::vec4(0.0f, 0.0f, 0.0f, 1.0f) : mesh.tangents[i];
          const glm::vec3 T = transformDirection(glm::mat3(instance.worldFromModel), glm::vec3(tangent));
          for (int c = 0; c < 3; ++c) out[layout.tangent + c] = T[c];
          out[layout.tangent + 3] = tangent.w;
        } else if (frame.shading == ShadingMode::Gouraud) {  // the illumination equation at the vertex, both sides
          const glm::vec3 V = viewVector<float>(frame, world[k]);
          const Illumination front = illuminate(frame, maps, summed, world[k], N, V);
          const Illumination back = instance.cullBackFaces ? Illumination{} : illuminate(frame, maps, summed, world[k], -N, V);
          for (int c = 0; c < 3; ++c)
            out[c] = front.diffuse[c], out[3 + c] = front.specular[c], out[6 + c] = back.diffuse[c], out[9 + c] = back.specular[c];
        }
      }
      // Flat: one illumination per side, from the geometric normal at the centroid.
      Illumination flat[2];
      if (frame.shading == ShadingMode::Flat) {
        const glm::vec3 N = normalize3(cross3(world[1] - world[0], world[2] - world[0]));
        const glm::vec3 centroid = (world[0] + world[1] + world[2]) / 3.0f;
        const glm::vec3 V = viewVector<float>(frame, centroid);
        flat[0] = illuminate(frame, maps, summed, centroid, N, V);
        if (!instance.cullBackFaces) flat[1] = illuminate(frame, maps, summed, centroid, -N, V);
      }
      // Fragment stage: the point the varyings describe at the pixel, shaded (shading/surface_shading.h).
      const auto surface = [&](const float* f, bool front, const Interpolation& planes, int px, int py) -> glm::vec3 {
        SurfacePoint p;
        p.front = front;
        for (int set = 0; set < 2; ++set) p.st[set] = stOf(f, set), p.derivatives[set] = planes.quadDerivatives(layout.texcoord(set), px, py);
        p.color = glm::vec4(f[color], f[color + 1], f[color + 2], f[color + 3]);
        if (count == layout.count) p.model = glm::vec3(f[model], f[model + 1], f[model + 2]);
        if (interpolatesNormals(frame.shading)) {
          p.P = glm::vec3(f[0], f[1], f[2]);
          p.normal = glm::vec3(f[3], f[4], f[5]);
          p.tangent = glm::vec4(f[layout.tangent], f[layout.tangent + 1], f[layout.tangent + 2], f[layout.tangent + 3]);
        } else if (frame.shading == ShadingMode::Gouraud) {
          const int side = front ? 0 : 6;
          p.lit = Illumination{{f[side], f[side + 1], f[side + 2]}, {f[side + 3], f[side + 4], f[side + 5]}};
        } else {
          p.lit = front ? flat[0] : flat[1];
        }
        return shadeSurface(draw, maps, p);
      };
      // Fog, by the pixel's eye depth (PIPELINE.md, section 7).
      const FragmentShader fragment = [&](const float* f, bool front, const Interpolation& planes, int px, int py) {
        return fogged(frame.fog, surface(f, front, planes, px, py), eyeDepth(frame, planes.oneOverWAt(px, py), planes.depthAt(px, py)));
      };
      const auto id = static_cast<std::uint32_t>(firstTriangle[run.instance] + t / 3 + 1);
      drawTriangle(v, count, instance.cullBackFaces, id, target, fragment, material.masked ? keep : nullptr, material.blended ? alpha : nullptr,
                   frame.blending, material.additive);
    }
  }
}

// Pass 2's lines and points, after every opaque triangle: each instance's
// segments, then its points, from their own vertex stage.
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

// The reference follows one triangle at a time through the z-buffer, its only hidden-surface removal.
void refuseHiddenSurface(const FrameInputs& frame) {
  if (!frame.samples.empty())
    throw Error("settings key 'antialiasing.samples': the reference backend draws one sample per pixel; --backend cpu and gl supersample");
  if (frame.hsr != HiddenSurface::ZBuffer)
    throw Error("settings key 'hsr': the reference backend has the z-buffer only; --backend cpu draws " +
                std::string(kHiddenSurfaceNames[static_cast<std::size_t>(frame.hsr)]));
}

class ReferenceRenderer final : public Renderer {
 public:
  std::string description() const override { return "cpu reference, one triangle at a time (renderer/cpu/reference)"; }

  // The image, triangle ids and fragment counts; the other stages are the fast renderer's.
  RenderResult render(const Scene& scene, const FrameInputs& frame, const FrameOutputs& asked) override {
    refuseUndrawn(asked, {FrameOutput::Image, FrameOutput::TriangleIds, FrameOutput::FragmentCounts});
    RenderResult result = asked.has(FrameOutput::Image) ? drawImage(scene, frame) : RenderResult{};
    if (asked.has(FrameOutput::TriangleIds)) result.triangleIds = visibleTriangles(scene, frame);
    if (asked.has(FrameOutput::FragmentCounts)) result.fragmentCounts = fragmentCounts(scene, frame);
    return result;
  }

 private:
  RenderResult drawImage(const Scene& scene, const FrameInputs& frame) {
    check_(scene, frame);
    if (frame.volume.placed)
      throw Error("settings key 'volume.mode': raycast is drawn by the CPU backend (--backend cpu); the readable reference draws splat and isosurface");
    if (frame.areaAveraged) return renderAreaAveraged(scene, frame);
    refuseHiddenSurface(frame);
    const auto start = std::chrono::steady_clock::now();
    const ShadowMaps maps = shadowPass(scene, frame);
    RenderResult result;
    ColorBuffer color(frame.width, frame.height, glm::vec4(0.0f));
    for (int y = 0; y < frame.height; ++y)
      for (int x = 0; x < frame.width; ++x) color.at(x, y) = backgroundPixel(frame, x, y);
    Target target{frame.width, frame.height, std::vector<float>(static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height), 1.0f)};
    target.color = &color;
    litPass(scene, frame, maps, target, Drawn::Opaque);
    linePass(scene, frame, target);
    litPass(scene, frame, maps, target, Drawn::Blended);
    // The resolve, one pixel at a time (shading/resolve.cpp does it four channels at once).
    result.image = Image(frame.width, frame.height);
    for (int y = 0; y < frame.height; ++y)
      for (int x = 0; x < frame.width; ++x) result.image.at(x, y) = encodePixel(unstored(color.at(x, y), frame.blending));
    result.timings.push_back({"both passes", millisecondsSince(start)});
    return result;
  }

  std::vector<std::uint32_t> visibleTriangles(const Scene& scene, const FrameInputs& frame) {
    check_(scene, frame);
    refuseHiddenSurface(frame);
    const ShadowMaps maps = shadowPass(scene, frame);  // Gouraud lights its vertices with them
    std::vector<std::uint32_t> ids(static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height), 0u);
    Target target{frame.width, frame.height, std::vector<float>(ids.size(), 1.0f)};
    target.ids = &ids;
    litPass(scene, frame, maps, target, Drawn::Opaque);  // blended triangles write no depth and keep no pixel
    return ids;
  }

  std::vector<std::uint32_t> fragmentCounts(const Scene& scene, const FrameInputs& frame) {
    check_(scene, frame);
    const ShadowMaps maps = shadowPass(scene, frame);
    std::vector<std::uint32_t> counts(static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height), 0u);
    Target target{frame.width, frame.height, std::vector<float>(counts.size(), 1.0f)};
    target.counts = &counts;
    litPass(scene, frame, maps, target, Drawn::All);
    return counts;
  }

  FrameCheck check_;
};

}  // namespace

RenderResult renderAreaAveraged(const Scene& scene, const FrameInputs& frame) {
  refuseOutsideArea(scene, frame);
  const auto start = std::chrono::steady_clock::now();
  const ShadowMaps maps = shadowPass(scene, frame);
  AreaAveraging area(frame.width, frame.height);
  Target target{frame.width, frame.height, {}};
  target.area = &area;
  // Pass 2 as the z-buffer draws it, twice: the surfaces, then (once every pixel is cut) their fragments.
  for (int step = 0; step < 2; ++step) {
    litPass(scene, frame, maps, target, Drawn::Opaque);
    litPass(scene, frame, maps, target, Drawn::Blended);
    if (step == 0) area.cut();
  }
  const ColorBuffer sum = area.composite(frame);
  RenderResult result;
  result.image = Image(frame.width, frame.height);
  for (int y = 0; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x) result.image.at(x, y) = encodePixel(unstored(sum.at(x, y), Blending::Premultiplied));
  result.timings.push_back({"area-weighted averaging", millisecondsSince(start)});
  result.notes.push_back(area.summary());
  return result;
}

std::unique_ptr<Renderer> makeReferenceRenderer() { return std::make_unique<ReferenceRenderer>(); }

}  // namespace facet
