// Pass 2: the camera's z-buffer pass with flat, Gouraud, Phong or pbr shading.
// The varyings of each mode (packed after x, y, z, 1/w in
// PassVertices::window) are varyings.h's.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "common/error.h"

#include "cpu/alpha_mask.h"
#include "cpu/binning.h"
#include "cpu/depth_rows.h"
#include "cpu/interpolation.h"
#include "cpu/line_pass.h"
#include "cpu/passes.h"
#include "cpu/phong_batch.h"
#include "cpu/scanline_zbuffer.h"
#include "cpu/tile_pixels.h"
#include "cpu/tile_raster.h"
#include "shading/blending.h"
#include "shading/draw_uniforms.h"
#include "shading/environment.h"
#include "shading/fog.h"
#include "shading/lit_programs.h"
#include "shading/resolve.h"
#include "shading/texture.h"

namespace facet::cpu {
namespace {


constexpr std::uint32_t kNoTriangle = std::numeric_limits<std::uint32_t>::max();
// Tiles start at multiples of kTileSize, blocks (tile_raster.h) at multiples of 8: a block's eight
// pixels of a row lie in one tile's row, which lessCovered reads from the block's first column.
static_assert(kTileSize % 8 == 0);

// The varyings the frame's vertex stage packs (PassVertices::window): the
// most that any instance reads, in its fragments and their α
// (DrawUniforms::used: every reader sets up that prefix at most) or in its
// lines and points (COLOR_0). A frame of plain Phong surfaces packs P and N
// alone: 40 bytes a vertex instead of 88, written once and read by binning
// and by every tile.
int packedVaryings(const Scene& scene, const FrameInputs& frame, const std::vector<DrawUniforms>& draws) {
  const VaryingLayout layout = varyingLayout(frame.shading);
  int packed = 0;
  for (std::size_t i = 0; i < frame.instances.size(); ++i) {
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(frame.instances[i].mesh)];
    packed = std::max(packed, draws[i].used);
    if (!mesh.lines.empty() || !mesh.points.empty()) packed = std::max(packed, layout.color + 4);
  }
  return packed;
}

// How many pixels from row[0] (which names `id`) name it, up to `most`
// (at most sixteen): row[0..16) is read whatever `most` is, and the tile's
// arrays have room for it (WorkerBins::TileScratch::kRunSlack).
int runOf(const std::uint32_t* row, std::uint32_t id, int most) {
#if defined(__SSE2__)
  const __m128i want = _mm_set1_epi32(static_cast<int>(id));
  unsigned same = 0;
  for (int q = 0; q < 4; ++q) {
    const __m128i four = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row + 4 * q));
    same |= static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(four, want)))) << (4 * q);
  }
  return std::min(__builtin_ctz(~same), most);  // ~same has bit 16 set
#else
  int run = 1;
  while (run < most && row[run] == id) ++run;
  return run;
#endif
}

// The program of each mode the tile shades with (shading/lit_programs.h).
template <ShadingMode kMode>
struct LitProgramOf;
template <>
struct LitProgramOf<ShadingMode::Flat> { using Type = LitFlatProgram; };
template <>
struct LitProgramOf<ShadingMode::Gouraud> { using Type = LitGouraudProgram; };
template <>
struct LitProgramOf<ShadingMode::Phong> { using Type = LitPhongProgram; };
template <>
struct LitProgramOf<ShadingMode::Pbr> { using Type = LitPbrProgram; };

// The fragment stage of one shading mode: no branch on the mode per pixel.
// It shades the pixels of `box` (within tile r) where `ids` (the tile's, row
// by row) names a triangle, and writes (colour, 1) there into `color`; with
// `normals`, (N, 1) of the normal shading reads there instead (the normals
// stage: flat's triangle normal, which the bins hold in their illumination's
// place, or Phong's and pbr's bent, normalized and two-sided normal). With
// `over` (a blended triangle's pass), each colour blends over what `color`
// holds with the pixel's α from `alpha` (the tile's, row by row) instead.
// Each pixel is the mode's fragment program at the point its varyings
// describe; Phong's lighting goes to the batch, many pixels at a time.
template <ShadingMode kMode>
void shadeTile(const FrameInputs& frame, const DrawUniforms* draws, const ShadowMaps& maps, WorkerBins::TileScratch& scratch,
               const std::uint32_t* ids, const TileRect& r, const TileRect& box, const TilePixels& color, bool normals, int lanes, const BlendOver* over,
               const float* alpha) {
  using Program = typename LitProgramOf<kMode>::Type;
  const int tx0 = box.x0, ty0 = box.y0, tx1 = box.x1, ty1 = box.y1;
  std::uint32_t current = kNoTriangle;
  std::uint32_t currentInstance = std::numeric_limits<std::uint32_t>::max();  // whose uniforms `draw` holds: none yet
  Interpolation* in = nullptr;
  const DrawUniforms* draw = nullptr;  // the instance's
  const bool foggy = frame.fog.mode != FogMode::None;  // fog reads 1/w, set up with the varyings
  bool back = false;
  bool plain = false;
  const Illumination* flat = nullptr;
  PhongBatch batch(frame, maps, color.first(), lanes, over);  // Phong: 4, 8, 16 or 32 pixels' illumination at a time
  for (int py = ty0; py <= ty1; ++py)
    for (int px = tx0; px <= tx1; ++px) {
      const int k = (py - r.y0) * kTileSize + (px - r.x0);  // the pixel in the tile's arrays (ids, alpha)
      const float a = over ? alpha[k] : 1.0f;             // its α in a blended pass
      const std::uint32_t id = ids[k];
      if (id == kNoTriangle) {  // the background the image was cleared to (a blended pass: a pixel its triangle does not take)
        for (const std::uint32_t* next = &ids[k + 1]; px < tx1 && *next == kNoTriangle; ++next) ++px;  // the rest of their run, in a tight loop
        continue;
      }
      if (id != current) {
        current = id;
        WorkerBins::TileTriangle& winner = scratch.triangles[id];
        const WorkerBins& bins = *winner.bins;
        const std::size_t index = winner.index;
        const BinnedTriangle& t = bins.triangles[index];
        in = &winner.interpolation;
        if (t.instance != currentInstance) {  // what the pixel reads of its mesh and material: once per run of one instance's triangles
          currentInstance = t.instance;
          draw = &draws[t.instance];
          // Phong's plain pixel: lit, without texture, vertex colours, procedural pattern, bent normal,
          // emission map or fog; its P and N go to the batch as they are interpolated.
          plain = kMode == ShadingMode::Phong && !normals && !draw->texture && !draw->colored && !draw->procedural && !draw->normalMap && !draw->bumpable &&
                  !draw->emissiveMap && !foggy && !draw->material->unlit;
        }
        back = !t.snapped.frontFacing;
        if (draw->used || foggy) in->setUpVaryings(draw->used);
        if constexpr (kMode == ShadingMode::Flat) flat = &bins.flat[2 * index];
      }
      if constexpr (kMode == ShadingMode::Phong)
        if (plain) {
          // The triangle's run of pixels in the row from here, up to the batch's width: interpolated on
          // lanes straight into the batch (a lone pixel on four). The pixels one by one, by the same
          // operations, took 34 % of sphere-100k's shaded pixels through 23 scalar stores each.
          const int run = runOf(&ids[k], id, std::min(lanes, tx1 - px + 1));
          batch.addRun(run, color.offset(px, py), *in, px, py, back, draw->material->baseColor, *draw->material, over ? &alpha[k] : nullptr);
          px += run - 1;
          continue;
        }
      // The point the varyings describe at the pixel.
      const SurfacePoint p = surfacePointAt(*in, *draw, kMode, draw->used, !back, flat, px, py);
      if (normals) {  // the normals stage: N as shading reads it, two-sided; Gouraud frames arrive as Phong ones (normalsFrame)
        glm::vec3 N(0.0f);
        if constexpr (kMode == ShadingMode::Flat) N = p.lit.diffuse;
        else if constexpr (kMode == ShadingMode::Pbr || kMode == ShadingMode::Phong) N = LitPhongProgram::shadingNormal(*draw, p);
        color.at(px, py) = glm::vec4(N, 1.0f);
        continue;
      }
      // The pixel's eye depth d, for fog.
      const float depth = foggy ? eyeDepth(frame, in->oneOverWAt(px, py), in->depthAt(px, py)) : 0.0f;
      glm::vec3 lit;
      if constexpr (kMode == ShadingMode::Phong) {
        const glm::vec3 O = baseColorAt(*draw, p);
        if (!draw->material->unlit) {  // lit in the batch
          batch.add(color.offset(px, py), p.P, LitPhongProgram::bentNormal(*draw, p), back, O, *draw->material,
                    draw->emissiveMap ? emissionAt(*draw, p) : draw->material->emissive, depth, a);
          continue;
        }
        lit = O;  // KHR_materials_unlit: O_d itself, through the fog
      } else if constexpr (kMode == ShadingMode::Pbr) {
        lit = Program::fragment(*draw, maps, p);
      } else {
        lit = Program::fragment(*draw, p);
      }
      writeFragment(color.at(px, py), fogged(frame.fog, lit, depth), a, over);
    }
  batch.flush();
}

// hsr = scanline: the tile's z-buffer and winners from the frame's visible
// polygons (scanline_zbuffer.h), each polygon set up once, in submission order.
void gatherVisible(const std::vector<WorkerBins>& workers, const PolygonNumbering& numbering, const PassVertices& v,
                   const std::vector<std::uint32_t>& visible, int width, const TileRect& r, WorkerBins::TileScratch& scratch) {
  const auto pixel = [&](int px, int py) { return visible[static_cast<std::size_t>(py) * static_cast<std::size_t>(width) + static_cast<std::size_t>(px)]; };
  std::vector<std::uint32_t> kept;
  for (int py = r.y0; py <= r.y1; ++py)
    for (int px = r.x0; px <= r.x1; ++px)
      if (pixel(px, py) != kNoPolygon && (kept.empty() || kept.back() != pixel(px, py))) kept.push_back(pixel(px, py));
  std::sort(kept.begin(), kept.end());
  kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
  for (const std::uint32_t polygon : kept) {
    const std::size_t w = numbering.workerOf(polygon);
    const auto index = static_cast<std::uint32_t>(polygon - numbering.first[w]);
    const BinnedTriangle& t = workers[w].triangles[index];
    InterpolationVertex corner[3];
    for (int k = 0; k < 3; ++k) {
      const float* p = workers[w].vertex(v, t.vertex[k]);
      corner[k] = {p[0], p[1], p[2], p[3], p + 4};
    }
    scratch.triangles.emplace_back(corner, &workers[w], index);
  }
  for (int py = r.y0; py <= r.y1; ++py)
    for (int px = r.x0; px <= r.x1; ++px) {
      const int k = (py - r.y0) * kTileSize + (px - r.x0);
      const std::uint32_t polygon = pixel(px, py);
      if (polygon == kNoPolygon) continue;  // cleared: no triangle, depth 1
      const auto id = static_cast<std::uint32_t>(std::lower_bound(kept.begin(), kept.end(), polygon) - kept.begin());
      scratch.id[k] = id;
      scratch.depth[k] = scratch.triangles[id].interpolation.depthAt(px, py);  // what lines and points test against
    }
}

// Shading in the frame's mode.
void shadeIn(const FrameInputs& frame, const DrawUniforms* draws, const ShadowMaps& maps, WorkerBins::TileScratch& scratch, const std::uint32_t* ids,
             const TileRect& r, const TileRect& box, const TilePixels& color, int lanes, bool normals, const BlendOver* over = nullptr,
             const float* alpha = nullptr) {
  switch (frame.shading) {
    case ShadingMode::Pbr: shadeTile<ShadingMode::Pbr>(frame, draws, maps, scratch, ids, r, box, color, normals, lanes, over, alpha); break;
    case ShadingMode::Phong: shadeTile<ShadingMode::Phong>(frame, draws, maps, scratch, ids, r, box, color, normals, lanes, over, alpha); break;
    case ShadingMode::Gouraud: shadeTile<ShadingMode::Gouraud>(frame, draws, maps, scratch, ids, r, box, color, normals, lanes, over, alpha); break;
    default: shadeTile<ShadingMode::Flat>(frame, draws, maps, scratch, ids, r, box, color, normals, lanes, over, alpha); break;
  }
}

// Transparency (PIPELINE.md, "Shading"): the tile's blended triangles in
// their order, after everything opaque. Each one's fragments that pass the
// depth test (no depth write) get their α, are shaded as a visible fragment
// is, and blend into the colour buffer.
void blendTile(const FrameInputs& frame, const DrawUniforms* draws, const ShadowMaps& maps, VaryingLayout layout, WorkerBins::TileScratch& scratch,
               const TileRect& r, const TilePixels& color, int lanes) {
  std::fill(std::begin(scratch.fragment), std::end(scratch.fragment), kNoTriangle);
  for (const WorkerBins::TileScratch::Blended& blended : scratch.blended) {
    WorkerBins::TileTriangle& triangle = scratch.triangles[blended.id];
    const BinnedTriangle& t = triangle.bins->triangles[triangle.index];
    const DrawUniforms& draw = draws[t.instance];
    const CourseMaterial& material = *draw.material;
    const Texture* texture = draw.texture;
    const bool colored = draw.colored;
    Interpolation& in = triangle.interpolation;
    const float constantAlpha = fragmentAlpha(material, nullptr, nullptr);
    const float* const uniformAlpha = texture || colored ? nullptr : &constantAlpha;  // fragmentAlphaAt's value at every pixel
    if (!uniformAlpha) in.setUpVaryings(draw.used);  // α's texture coordinates, COLOR_0
    TileRect drawn{r.x1 + 1, r.y1 + 1, r.x0 - 1, r.y0 - 1};  // the pixels it reaches, as a box
    // A fragment in front of the opaque surfaces (LESS, no depth write) takes its pixel, with its alpha.
    const auto inFront = [&](int px, int py) {
      const int k = (py - r.y0) * kTileSize + (px - r.x0);
      if (!(in.depthAt(px, py) < scratch.depth[k])) return false;
      scratch.fragment[k] = blended.id;
      scratch.alpha[k] = uniformAlpha ? *uniformAlpha : fragmentAlphaAt(material, texture, colored, layout, in, px, py);
      return true;
    };
    const auto reach = [&](int x0, int x1, int py) {
      drawn = {std::min(drawn.x0, x0), std::min(drawn.y0, py), std::max(drawn.x1, x1), std::max(drawn.y1, py)};
    };
    rasterizeBlocks(
        t.snapped, blended.box,
        [&](int px, int py) {
          if (inFront(px, py)) reach(px, px, py);
        },
        [&](int x0, int x1, int py) {  // a row across blocks wholly inside: the depth tests four or sixteen at a time, the box grown once
          const int k0 = (py - r.y0) * kTileSize + (x0 - r.x0);
          const TakenRun taken = frontRowOnLanes(lanes, in.depthPlane(), x0, x1, py, &scratch.depth[k0], &scratch.fragment[k0], blended.id);
          if (taken.first > taken.last) return;
          // α where it was taken; one α for the triangle without texture or COLOR_0, written over the whole
          // run (a pixel not taken keeps kNoTriangle, and its α is never read).
          if (uniformAlpha) std::fill(&scratch.alpha[k0 + (taken.first - x0)], &scratch.alpha[k0 + (taken.last - x0)] + 1, *uniformAlpha);
          else
            for (int px = taken.first; px <= taken.last; ++px) {
              const int k = k0 + (px - x0);
              if (scratch.fragment[k] == blended.id) scratch.alpha[k] = fragmentAlphaAt(material, texture, colored, layout, in, px, py);
            }
          reach(taken.first, taken.last, py);
        });
    if (drawn.x0 > drawn.x1) continue;
    // Shaded as a visible fragment is, and blended over the colour buffer with its α as it is written.
    const BlendOver over{frame.blending, material.additive};
    shadeIn(frame, draws, maps, scratch, scratch.fragment, r, drawn, color, lanes, false, &over, scratch.alpha);
    for (int py = drawn.y0; py <= drawn.y1; ++py)  // the box holds this triangle's pixels or none
      std::fill_n(&scratch.fragment[(py - r.y0) * kTileSize + (drawn.x0 - r.x0)], drawn.x1 - drawn.x0 + 1, kNoTriangle);
  }
}

}  // namespace

void litPass(ThreadPool& pool, FrameBuffers& buffers, const Scene& scene, const FrameInputs& frame, const ShadowMaps& maps, ColorBuffer& color,
             const LitPassOutput& output) {
  std::vector<std::uint32_t>* const triangleIds = output.triangleIds;
  std::vector<std::uint32_t>* const fragmentCounts = output.fragmentCounts;
  const bool normals = output.normals && !triangleIds && !fragmentCounts;
  if (normals && frame.shading == ShadingMode::Gouraud) throw Error("the normals stage draws a Gouraud frame as normalsFrame makes it (Phong)");
  const VaryingLayout layout = varyingLayout(frame.shading);
  const float halfWidth = 0.5f * static_cast<float>(frame.width), halfHeight = 0.5f * static_cast<float>(frame.height);
  PassVertices& v = buffers.vertices;
  const std::size_t vertexCount = v.world.size();
  // Each instance's uniforms, once for the frame (the vector keeps its capacity).
  buffers.draws.clear();
  for (const FrameInstance& instance : frame.instances) buffers.draws.push_back(drawUniforms(scene, frame, instance));
  const std::vector<DrawUniforms>& draws = buffers.draws;
  const int packed = packedVaryings(scene, frame, draws);
  const auto stride = static_cast<std::size_t>(4 + packed);
  v.stride = 4 + packed;
  v.window.resize(vertexCount * stride);

  // Vertex stage: the mode's vertex program (shading/lit_programs.h) on
  // each vertex, writing the packed prefix of its varyings, an instance's
  // vertices at a time: its matrices are copied to a local once, which the
  // stores to the packed vertices cannot alias (read through the instance,
  // they were loaded again for every vertex).
  forEachRange(pool, vertexCount, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t g = begin, i = 0; g < end;) {
      while (g >= v.firstVertex[i + 1]) ++i;
      const std::size_t first = v.firstVertex[i], last = std::min(end, v.firstVertex[i + 1]);
      const DrawMatrices matrices = drawMatrices(frame.instances[i]);
      const auto vertices = [&](auto program) {
        for (; g < last; ++g) {
          float* out = v.window.data() + g * stride;
          const glm::vec4 clip = decltype(program)::vertex(draws[i], matrices, maps, g - first, v.world[g], packed, out + 4);
          v.clip[g] = clip;
          v.flags[g] = vertexFlags(clip);
          packWindow(clip, halfWidth, halfHeight, out);
        }
      };
      switch (frame.shading) {
        case ShadingMode::Pbr:
        case ShadingMode::Phong: vertices(LitPhongProgram{}); break;
        case ShadingMode::Gouraud: vertices(LitGouraudProgram{}); break;
        default: vertices(LitFlatProgram{}); break;
      }
    }
  });

  // Primitive stage. Flat: one illumination per triangle, from its geometric normal at its centroid.
  const auto flatLighting = [&](std::uint32_t instance, const std::uint32_t (&vertex)[3], Illumination (&out)[2]) {
    LitFlatProgram::face(draws[instance], maps, v.world[vertex[0]], v.world[vertex[1]], v.world[vertex[2]], frame.instances[instance].cullBackFaces,
                         out);
  };
  // The normals stage: the bins hold the triangle's normal, N and -N, in its illumination's diffuse place.
  const auto flatNormal = [&](std::uint32_t, const std::uint32_t (&vertex)[3], Illumination (&out)[2]) {
    const glm::vec3 N = LitFlatProgram::faceNormal(v.world[vertex[0]], v.world[vertex[1]], v.world[vertex[2]]);
    out[0] = {N, glm::vec3(0.0f)};
    out[1] = {-N, glm::vec3(0.0f)};
  };
  const FlatIllumination flat = normals ? FlatIllumination(flatNormal) : FlatIllumination(flatLighting);  // the lambdas outlive the pass
  const TileGrid grid = TileGrid::over(frame.width, frame.height);
  // The painter's algorithm bins (and so draws) the triangles in its order, back to front.
  const bool painter = frame.hsr == HiddenSurface::Painter;
  if (painter && frame.paintersOrder.size() != v.firstTriangle.back())
    throw Error("hsr painter: the frame's order has " + std::to_string(frame.paintersOrder.size()) + " triangles, the scene " +
                std::to_string(v.firstTriangle.back()));
  // Transparency: the opaque triangles in order, then the blended ones back to front.
  const bool blending = !frame.transparentOrder.empty();
  if (blending) {
    std::vector<std::uint32_t>& order = buffers.submission;
    order.clear();
    for (std::size_t i = 0; i < frame.instances.size(); ++i)
      if (!frame.materials[static_cast<std::size_t>(frame.instances[i].material)].blended)
        for (std::size_t t = v.firstTriangle[i]; t < v.firstTriangle[i + 1]; ++t) order.push_back(static_cast<std::uint32_t>(t));
    order.insert(order.end(), frame.transparentOrder.begin(), frame.transparentOrder.end());
    if (order.size() != v.firstTriangle.back())
      throw Error("transparency: the frame's order has " + std::to_string(order.size()) + " triangles, the scene " + std::to_string(v.firstTriangle.back()));
  }
  const std::uint32_t* order = painter ? frame.paintersOrder.data() : blending ? buffers.submission.data() : nullptr;
  forEachRange(pool, v.firstTriangle.back(), [&](std::size_t begin, std::size_t end, int w) {
    binTriangles(scene, frame, v, grid, true, begin, end, buffers.workers[static_cast<std::size_t>(w)],
                 frame.shading == ShadingMode::Flat ? &flat : nullptr, order);
  });
  // The scanline z-buffer decides every pixel's polygon first, a row at a time; the tiles then shade what it kept.
  const bool scanline = frame.hsr == HiddenSurface::Scanline && !fragmentCounts;
  std::optional<PolygonNumbering> numbering;
  if (scanline) scanlineVisibility(pool, buffers.workers, v, scene, frame, numbering.emplace(buffers.workers), buffers.visible);

  // Segments and points, drawn after every opaque triangle (not in the triangle-id pass).
  if (triangleIds || fragmentCounts || normals) buffers.lines.clear();
  else setUpLines(scene, frame, v, layout.color, buffers.lines);

  // Tiles: visibility (z-buffer, triangle order), then shading of what is visible, then lines and points.
  // Which worker takes which tile changes from frame to frame; every worker
  // sizes its tile scratch for the fullest tile, so none grows later.
  std::size_t fullestTile = 0;
  for (int tile = 0; tile < grid.count(); ++tile) fullestTile = std::max(fullestTile, trianglesInTile(buffers.workers, tile));
  for (WorkerBins& bins : buffers.workers) bins.tile.triangles.reserve(fullestTile), bins.tile.blended.reserve(fullestTile);
  const bool keepDepth = (frame.volume.placed || output.keepDepth) && !triangleIds && !fragmentCounts && !normals;
  if (keepDepth) buffers.depth.assign(static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height), 1.0f);
  const bool background = output.background && !triangleIds && !fragmentCounts && !normals;
  const bool environment = showsEnvironment(frame);
  const glm::vec4 oneColour = backgroundPixel(frame, 0, 0);
  Image* const image = background ? output.image : nullptr;
  // The tile's colours: the worker's own, resolved into `image` once drawn, or the colour buffer's.
  const auto pixelsOf = [&](int worker, const TileRect& r) {
    return image ? TilePixels(buffers.workers[static_cast<std::size_t>(worker)].tile.pixels, kTileSize, r.x0, r.y0) : TilePixels::of(color, r.x0, r.y0);
  };
  const auto drawTile = [&](int worker, int tile, const TileRect& r) {
    if (background) {
      const TilePixels pixels = pixelsOf(worker, r);
      for (int py = r.y0; py <= r.y1; ++py) {
        if (!environment) std::fill(&pixels.at(r.x0, py), &pixels.at(r.x1, py) + 1, oneColour);
        else
          for (int px = r.x0; px <= r.x1; ++px) pixels.at(px, py) = backgroundPixel(frame, px, py);
      }
    }
    if (trianglesInTile(buffers.workers, tile) == 0 && buffers.lines.empty()) return;
    if (fragmentCounts) {  // depth complexity: every fragment, before the tests; each pixel is in one tile
      forEachTriangleInTile(buffers.workers, v, tile, r, [&](const WorkerBins&, std::uint32_t, const BinnedTriangle& t, const InterpolationVertex (&)[3], const PixelBox& box) {
        rasterizeBlocks(t.snapped, box, [&](int px, int py) {
          ++(*fragmentCounts)[static_cast<std::size_t>(py) * static_cast<std::size_t>(frame.width) + static_cast<std::size_t>(px)];
        });
      });
      return;
    }
    WorkerBins::TileScratch& scratch = buffers.workers[static_cast<std::size_t>(worker)].tile;
    std::fill(std::begin(scratch.depth), std::end(scratch.depth), 1.0f);
    std::fill(std::begin(scratch.id), std::end(scratch.id), kNoTriangle);
    scratch.triangles.clear();  // keeps its capacity: no allocation once the sizes settle
    scratch.blended.clear();
    if (scanline) {
      gatherVisible(buffers.workers, *numbering, v, buffers.visible, frame.width, r, scratch);
      if (blending)  // the blended triangles, in their order, against the kept polygons' depths
        forEachTriangleInTile(buffers.workers, v, tile, r,
                              [&](const WorkerBins& bins, std::uint32_t index, const BinnedTriangle& t, const InterpolationVertex (&vertices)[3],
                                  const PixelBox& box) {
                                if (!frame.materials[static_cast<std::size_t>(frame.instances[t.instance].material)].blended) return;
                                scratch.blended.push_back({static_cast<std::uint32_t>(scratch.triangles.size()), box});
                                scratch.triangles.emplace_back(vertices, &bins, index);
                              });
    } else forEachTriangleInTile(buffers.workers, v, tile, r,
                          [&](const WorkerBins& bins, std::uint32_t index, const BinnedTriangle& t, const InterpolationVertex (&vertices)[3],
                              const PixelBox& box) {
                            // Set up once: the z-buffer reads its depth, shading its weights if it wins a pixel.
                            const auto id = static_cast<std::uint32_t>(scratch.triangles.size());
                            scratch.triangles.emplace_back(vertices, &bins, index);
                            Interpolation& interpolation = scratch.triangles.back().interpolation;
                            const FrameInstance& instance = frame.instances[t.instance];
                            const CourseMaterial& material = frame.materials[static_cast<std::size_t>(instance.material)];
                            if (material.blended) {  // drawn after the opaque surfaces and lines, in this order (blendTile)
                              scratch.blended.push_back({id, box});
                              return;
                            }
                            if (!material.masked && !painter) {
                              rasterizeBlocks(
                                  t.snapped, box,
                                  [&](int px, int py) {
                                    const float z = interpolation.depthAt(px, py);
                                    const int k = (py - r.y0) * kTileSize + (px - r.x0);
                                    if (!(z < scratch.depth[k])) return;  // LESS
                                    scratch.depth[k] = z;
                                    scratch.id[k] = id;
                                  },
                                  [&](int x0, int x1, int py) {
                                    const int k = (py - r.y0) * kTileSize + (x0 - r.x0);
                                    lessRowOnLanes(buffers.lanes, interpolation.depthPlane(), x0, x1, py, &scratch.depth[k], &scratch.id[k], id);
                                  },
                                  [&](int bx, unsigned covered, int py) {  // bx .. bx+7 lie in the tile's row: tiles are whole blocks
                                    const int k = (py - r.y0) * kTileSize + (bx - r.x0);
                                    lessCovered(interpolation.depthPlane(), bx, covered, py, &scratch.depth[k], &scratch.id[k], id);
                                  });
                              return;
                            }
                            // Alpha mask: the fragment's alpha decides before it writes depth (alpha_mask.h).
                            // The painter's algorithm has no depth: the last triangle drawn over a pixel keeps it.
                            const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
                            const Texture* texture = material.masked ? baseColorTextureOf(scene, frame, material, mesh) : nullptr;
                            const bool colored = !mesh.colors.empty();
                            if (material.masked) interpolation.setUpVaryings(draws[t.instance].used);
                            rasterizeBlocks(t.snapped, box, [&](int px, int py) {
                              const int k = (py - r.y0) * kTileSize + (px - r.x0);
                              const float z = painter ? 0.0f : interpolation.depthAt(px, py);
                              if (!painter && !(z < scratch.depth[k])) return;  // LESS
                              if (material.masked && !keepsFragment(material, texture, colored, layout, interpolation, px, py)) return;
                              if (!painter) scratch.depth[k] = z;
                              scratch.id[k] = id;
                            });
                          });
    if (triangleIds) {  // which triangle each pixel keeps, instead of its colour
      for (int py = r.y0; py <= r.y1; ++py)
        for (int px = r.x0; px <= r.x1; ++px) {
          const std::uint32_t id = scratch.id[(py - r.y0) * kTileSize + (px - r.x0)];
          (*triangleIds)[static_cast<std::size_t>(py) * static_cast<std::size_t>(frame.width) + static_cast<std::size_t>(px)] =
              id == kNoTriangle ? 0u : 1u + scratch.triangles[id].bins->triangles[scratch.triangles[id].index].triangle;
        }
      return;
    }
    const TilePixels pixels = pixelsOf(worker, r);
    shadeIn(frame, buffers.draws.data(), maps, scratch, scratch.id, r, r, pixels, buffers.lanes, normals);
    drawLines(frame, buffers.lines, r, painter ? nullptr : scratch.depth, kTileSize, pixels);  // the painter has no depth to test
    if (!scratch.blended.empty() && !normals) blendTile(frame, buffers.draws.data(), maps, layout, scratch, r, pixels, buffers.lanes);
    if (keepDepth)
      for (int py = r.y0; py <= r.y1; ++py)
        std::copy_n(scratch.depth + (py - r.y0) * kTileSize, r.x1 - r.x0 + 1,
                    buffers.depth.begin() + static_cast<std::ptrdiff_t>(py) * frame.width + r.x0);
  };
  forEachTile(pool, grid, [&](int worker, int tile, const TileRect& r) {
    drawTile(worker, tile, r);
    if (image) {  // the drawn tile resolved while it is in the cache
      const TilePixels pixels = pixelsOf(worker, r);
      for (int py = r.y0; py <= r.y1; ++py)
        resolveRow(&pixels.at(r.x0, py), &image->at(r.x0, py), static_cast<std::size_t>(r.x1 - r.x0 + 1), frame.blending, 1, buffers.lanes);
    }
  });
}

}  // namespace facet::cpu
