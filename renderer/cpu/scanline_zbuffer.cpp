#include "cpu/scanline_zbuffer.h"

#include <algorithm>
#include <cmath>

#include "cpu/alpha_mask.h"
#include "shading/draw_uniforms.h"
#include "cpu/interpolation.h"
#include "cpu/passes.h"
#include "shading/texture.h"
#include "shading/lit_varyings.h"

namespace facet::cpu {
namespace {

std::int64_t floorDiv(std::int64_t n, std::int64_t d) {  // d > 0
  const std::int64_t q = n / d;
  return q * d > n ? q - 1 : q;
}

// floor(N / D) of an N that changes by a constant from row to row, as a
// quotient and a remainder: the incremental x-intercept, without rounding.
struct Intercept {
  std::int64_t q = 0, r = 0, d = 1, dq = 0, dr = 0;

  void start(std::int64_t n, std::int64_t divisor, std::int64_t step) {
    d = divisor;
    q = floorDiv(n, d);
    r = n - q * d;
    dq = floorDiv(step, d);
    dr = step - dq * d;
  }
  void next() {
    q += dq;
    r += dr;
    if (r >= d) ++q, r -= d;
  }
};

// One edge's limit on the span of a row. The rasterizer's test at pixel
// (px, py) is e = c + s_x·px + s_y·py > 0 (tile_raster.h); on row py with
// n = c + s_y·py it is px > -n/s_x (s_x > 0: a left edge), px < -n/s_x
// (s_x < 0: a right edge), or n > 0 whatever px (s_x = 0).
struct EdgeLimit {
  enum Kind { Left, Right, Level } kind = Level;
  Intercept x;          // floor(-n / |s_x|)
  std::int64_t n = 0, sy = 0;  // Level: n on the current row, and its step

  void start(std::int64_t c, std::int64_t sx, std::int64_t syStep, int py) {
    sy = syStep;
    n = c + sy * py;
    kind = sx > 0 ? Left : sx < 0 ? Right : Level;
    if (kind != Level) x.start(-n, sx > 0 ? sx : -sx, -sy);
  }
  void next() {
    n += sy;
    if (kind != Level) x.next();
  }
  // Narrows [x0, x1] to the pixels inside this edge.
  void limit(std::int64_t& x0, std::int64_t& x1) const {
    if (kind == Left) x0 = std::max(x0, x.q + 1);
    else if (kind == Right) x1 = std::min(x1, -x.q - 1);
    else if (n <= 0) x1 = x0 - 1;
  }
};

// What a polygon needs to be drawn into a row: its edges, its depth plane and its alpha mask.
struct ActivePolygon {
  std::uint32_t polygon = 0;
  int maxY = 0, minX = 0, maxX = 0;
  EdgeLimit edges[3];
  std::uint32_t setUp = 0;  // index into the worker's PolygonSetUp list
};

struct PolygonSetUp {
  Interpolation planes;
  double a0 = 0, dadx = 0, dady = 0;  // the depth plane (A, B, C of the course: dz/dx = -A/C)
  const CourseMaterial* material = nullptr;
  const Texture* texture = nullptr;   // a masked polygon's base colour texture
  bool colored = false, masked = false;
};

// A pixel of the row: the kept polygon's stepped depth z and a bound on how
// far the z-buffer's float depth there can be from it.
struct RowSample {
  double z = 1.0, bound = 0.0;
  std::uint32_t polygon = kNoPolygon;
  std::uint32_t setUp = 0;
};

// The z-buffer's depth is the float plane fma(B, py, fma(A, px, a0)) clamped
// to [0, 1] (plane_equations.h): two roundings of at most 2^-24 of
// |a0| + |A px| + |B py| each. Twice that (and a subnormal's worth) bounds
// the distance to the stepped double z, so two depths further apart than
// their bounds compare as the z-buffer's floats do; closer ones are compared
// as those floats.
constexpr double kRelativeBound = 0x1p-22, kAbsoluteBound = 0x1p-100;

}  // namespace

PolygonNumbering::PolygonNumbering(const std::vector<WorkerBins>& workers) {
  first.push_back(0);
  for (const WorkerBins& bins : workers) first.push_back(first.back() + bins.triangles.size());
}

std::size_t PolygonNumbering::workerOf(std::uint32_t p) const {
  return static_cast<std::size_t>(std::upper_bound(first.begin(), first.end(), static_cast<std::size_t>(p)) - first.begin()) - 1;
}

std::size_t scanlineDepthBytes(int width, int workers) {
  return static_cast<std::size_t>(width) * static_cast<std::size_t>(workers) * sizeof(RowSample);
}

void scanlineVisibility(ThreadPool& pool, const std::vector<WorkerBins>& workers, const PassVertices& vertices, const Scene& scene,
                        const FrameInputs& frame, const PolygonNumbering& numbering, std::vector<std::uint32_t>& visible) {
  const int width = frame.width, height = frame.height;
  const VaryingLayout layout = varyingLayout(frame.shading);
  visible.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), kNoPolygon);

  // The edge table: every polygon by y_min, then in submission order.
  struct Entry {
    int minY;
    std::uint32_t polygon;
  };
  std::vector<Entry> table;
  table.reserve(numbering.count());
  for (std::size_t w = 0; w < workers.size(); ++w)
    for (std::size_t i = 0; i < workers[w].triangles.size(); ++i) {
      PixelBox box;
      const FrameInstance& instance = frame.instances[workers[w].triangles[i].instance];
      if (frame.materials[static_cast<std::size_t>(instance.material)].blended) continue;  // blended after, against what this keeps
      if (!pixelBox(workers[w].triangles[i].snapped, 0, 0, width - 1, height - 1, box)) continue;
      table.push_back({box.minY, static_cast<std::uint32_t>(numbering.first[w] + i)});
    }
  std::stable_sort(table.begin(), table.end(), [](const Entry& a, const Entry& b) { return a.minY < b.minY; });

  forEachRange(pool, static_cast<std::size_t>(height), [&](std::size_t begin, std::size_t end, int) {
    if (begin == end) return;
    std::vector<ActivePolygon> active, added;
    std::vector<PolygonSetUp> setUps;
    std::vector<RowSample> row(static_cast<std::size_t>(width));

    // A polygon entering the active list on row py.
    const auto activate = [&](std::uint32_t polygon, int py) {
      const std::size_t w = numbering.workerOf(polygon);
      const WorkerBins& bins = workers[w];
      const BinnedTriangle& t = bins.triangles[polygon - numbering.first[w]];
      PixelBox box;
      pixelBox(t.snapped, 0, 0, width - 1, height - 1, box);
      if (box.maxY < py) return;
      ActivePolygon a;
      a.polygon = polygon;
      a.maxY = box.maxY, a.minX = box.minX, a.maxX = box.maxX;
      EdgeFunction edges[3];
      edgeFunctions(t.snapped, edges);
      for (int i = 0; i < 3; ++i) a.edges[i].start(edges[i].c, -edges[i].dcdx * 256, edges[i].dcdy * 256, py);
      InterpolationVertex corner[3];
      for (int k = 0; k < 3; ++k) {
        const float* p = bins.vertex(vertices, t.vertex[k]);
        corner[k] = {p[0], p[1], p[2], p[3], p + 4};
      }
      PolygonSetUp s{Interpolation(corner[0], corner[1], corner[2])};
      const Plane& z = s.planes.depthPlane();
      s.a0 = z.a0, s.dadx = z.dadx, s.dady = z.dady;
      const FrameInstance& instance = frame.instances[t.instance];
      s.material = &frame.materials[static_cast<std::size_t>(instance.material)];
      s.masked = s.material->masked;
      if (s.masked) {
        const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
        s.texture = baseColorTextureOf(scene, frame, *s.material, mesh);
        s.colored = !mesh.colors.empty();
        s.planes.setUpVaryings(drawUniforms(scene, frame, *s.material, mesh).used);  // α's texture coordinates, COLOR_0
      }
      a.setUp = static_cast<std::uint32_t>(setUps.size());
      setUps.push_back(s);
      added.push_back(a);
    };
    const auto byPolygon = [](const ActivePolygon& a, const ActivePolygon& b) { return a.polygon < b.polygon; };

    const int y0 = static_cast<int>(begin);
    // The polygons already under way at the first row, then each row's bucket.
    std::size_t next = 0;
    for (; next < table.size() && table[next].minY <= y0; ++next) activate(table[next].polygon, y0);
    for (int py = y0; py < static_cast<int>(end); ++py) {
      if (py > y0) {
        active.erase(std::remove_if(active.begin(), active.end(), [&](const ActivePolygon& a) { return a.maxY < py; }), active.end());
        for (ActivePolygon& a : active)
          for (EdgeLimit& e : a.edges) e.next();
        for (; next < table.size() && table[next].minY == py; ++next) activate(table[next].polygon, py);
      }
      if (!added.empty()) {  // kept in submission order, as the z-buffer meets them
        std::sort(added.begin(), added.end(), byPolygon);
        const auto middle = static_cast<std::ptrdiff_t>(active.size());
        active.insert(active.end(), added.begin(), added.end());
        std::inplace_merge(active.begin(), active.begin() + middle, active.end(), byPolygon);
        added.clear();
      }

      std::fill(row.begin(), row.end(), RowSample{});
      for (const ActivePolygon& a : active) {
        std::int64_t x0 = a.minX, x1 = a.maxX;
        for (const EdgeLimit& e : a.edges) e.limit(x0, x1);
        if (x0 > x1) continue;
        const PolygonSetUp& s = setUps[a.setUp];
        const double fy = py;
        // z at the span's first pixel, then z_{x+1} = z_x - A/C; the bound steps with it.
        double z = (s.a0 + s.dady * fy) + s.dadx * static_cast<double>(x0);
        double bound = kRelativeBound * (std::abs(s.a0) + std::abs(s.dady) * fy + std::abs(s.dadx) * static_cast<double>(x0)) + kAbsoluteBound;
        const double boundStep = kRelativeBound * std::abs(s.dadx);
        for (std::int64_t x = x0; x <= x1; ++x, z += s.dadx, bound += boundStep) {
          const int px = static_cast<int>(x);
          RowSample& kept = row[static_cast<std::size_t>(px)];
          const double zc = std::clamp(z, 0.0, 1.0);  // NaN stays NaN and is decided below
          bool less;
          if (zc + bound < kept.z - kept.bound) less = true;
          else if (zc - bound > kept.z + kept.bound) less = false;
          else {  // too close to call from the stepped depths: the z-buffer's own floats
            const float keptZ = kept.polygon == kNoPolygon ? 1.0f : setUps[kept.setUp].planes.depthAt(px, py);
            less = s.planes.depthAt(px, py) < keptZ;
          }
          if (!less) continue;  // LESS
          if (s.masked && !keepsFragment(*s.material, s.texture, s.colored, layout, s.planes, px, py)) continue;
          kept = {zc, bound, a.polygon, a.setUp};
        }
      }
      std::uint32_t* out = visible.data() + static_cast<std::size_t>(py) * static_cast<std::size_t>(width);
      for (int px = 0; px < width; ++px) out[px] = row[static_cast<std::size_t>(px)].polygon;
    }
  });
}

}  // namespace facet::cpu
