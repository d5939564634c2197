// Coverage: which pixels a triangle covers, checkable by hand against the
// rules in renderer/PIPELINE.md, "Rasterization" (llvmpipe's). The renderer's path
// (snapTriangle, then rasterizeBlocks over the 64x64 tiles of the bounding
// box) is what the hand-checked cases run; a last case holds its block-first
// walk equal to the plain per-pixel walk of rasterize.h on random triangles.
#include <algorithm>
#include <array>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include <doctest/doctest.h>

#include "cpu/clipper.h"
#include "cpu/rasterize.h"
#include "cpu/tile_raster.h"
#include "cpu/triangle_setup.h"

using namespace facet::cpu;
using Pixels = std::set<std::pair<int, int>>;

namespace {

WindowVertex at(float x, float y) {
  WindowVertex v;
  v.x = x;
  v.y = y;
  return v;
}

// Snaps a, b, c and gives the pixel box on a width × height target; false when dropped.
bool snap(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c, int width, int height, SnappedTriangle& t, PixelBox& box) {
  return snapTriangle({a.x, b.x, c.x}, {a.y, b.y, c.y}, t) && pixelBox(t, 0, 0, width - 1, height - 1, box);
}

// The renderer's coverage: snap, bin by bounding box, 8x8 blocks per tile.
// fragment(x, y) once per covered pixel; false when the triangle is dropped.
template <class Fragment>
bool coverTiles(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c, int width, int height, Fragment&& fragment,
                bool* frontFacing = nullptr) {
  SnappedTriangle t{};
  PixelBox box;
  if (!snap(a, b, c, width, height, t, box)) return false;
  if (frontFacing) *frontFacing = t.frontFacing;
  for (int ty = box.minY >> kTileShift; ty <= box.maxY >> kTileShift; ++ty)
    for (int tx = box.minX >> kTileShift; tx <= box.maxX >> kTileShift; ++tx) {
      const int x0 = tx * kTileSize, y0 = ty * kTileSize;
      const int x1 = std::min(x0 + kTileSize, width) - 1, y1 = std::min(y0 + kTileSize, height) - 1;
      PixelBox inTile;
      if (pixelBox(t, x0, y0, x1, y1, inTile)) rasterizeBlocks(t, inTile, fragment);
    }
  return true;
}

Pixels cover(WindowVertex a, WindowVertex b, WindowVertex c, int size = 16) {
  Pixels pixels;
  coverTiles(a, b, c, size, size, [&](int x, int y) { CHECK(pixels.insert({x, y}).second); });
  return pixels;
}

Pixels block(int x0, int x1, int y0, int y1) {
  Pixels p;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) p.insert({x, y});
  return p;
}

}  // namespace

TEST_CASE("snapping: 1/256 pixel grid centred on pixel centres, ties to even") {
  CHECK(snapToGrid(2.5f) == 512);
  CHECK(snapToGrid(2.5f + 1.0f / 256) == 513);
  CHECK(snapToGrid(2.5f + 1.0f / 512) == 512);  // 512.5 -> 512 (even)
  CHECK(snapToGrid(2.5f + 3.0f / 512) == 514);  // 513.5 -> 514 (even)
  CHECK(snapToGrid(0.5f) == 0);
  CHECK(snapToGrid(0.0f) == -128);
}

TEST_CASE("right triangle with vertices on pixel centres: left and bottom edges in, hypotenuse (right edge) out") {
  // (2.5,2.5), (8.5,2.5), (2.5,8.5): the hypotenuse is x_w + y_w = 11, so pixel
  // (x, y) with centre (x+0.5, y+0.5) is in when x >= 2, y >= 2 and x + y < 10.
  Pixels expected;
  for (int y = 2; y <= 7; ++y)
    for (int x = 2; x + y < 10; ++x) expected.insert({x, y});
  CHECK(cover(at(2.5f, 2.5f), at(8.5f, 2.5f), at(2.5f, 8.5f)) == expected);
  CHECK(cover(at(2.5f, 2.5f), at(2.5f, 8.5f), at(8.5f, 2.5f)) == expected);  // winding does not matter
}

TEST_CASE("the other half of the square takes the hypotenuse but not its top and right edges") {
  // (8.5,8.5), (2.5,8.5), (8.5,2.5): pixels with x + y >= 10 (centre on or past the
  // hypotenuse, a left edge here), x <= 7 and y <= 7 (x_w = 8.5, y_w = 8.5 are right and top edges).
  Pixels expected;
  for (int y = 2; y <= 7; ++y)
    for (int x = 2; x <= 7; ++x)
      if (x + y >= 10) expected.insert({x, y});
  CHECK(cover(at(8.5f, 8.5f), at(2.5f, 8.5f), at(8.5f, 2.5f)) == expected);
}

TEST_CASE("two triangles tiling a square cover its 6x6 pixels once: left/bottom in, right/top out") {
  const Pixels lower = cover(at(2.5f, 2.5f), at(8.5f, 2.5f), at(2.5f, 8.5f));
  const Pixels upper = cover(at(8.5f, 8.5f), at(2.5f, 8.5f), at(8.5f, 2.5f));
  Pixels both = lower;
  for (const auto& p : upper) CHECK(both.insert(p).second);  // no pixel twice
  CHECK(both == block(2, 7, 2, 7));
}

TEST_CASE("edges between pixel centres: a square from 2.0 to 6.0 covers centres 2.5..5.5") {
  const Pixels a = cover(at(2.0f, 2.0f), at(6.0f, 2.0f), at(6.0f, 6.0f));
  const Pixels b = cover(at(2.0f, 2.0f), at(6.0f, 6.0f), at(2.0f, 6.0f));
  Pixels both = a;
  both.insert(b.begin(), b.end());
  CHECK(a.size() + b.size() == 16);
  CHECK(both == block(2, 5, 2, 5));
}

TEST_CASE("sub-pixel shifts: 1/256 moves an edge across a centre, 1/512 does not") {
  const auto square = [](float d) {
    Pixels p = cover(at(2.5f + d, 2.5f + d), at(10.5f + d, 2.5f + d), at(10.5f + d, 10.5f + d));
    const Pixels q = cover(at(2.5f + d, 2.5f + d), at(10.5f + d, 10.5f + d), at(2.5f + d, 10.5f + d));
    p.insert(q.begin(), q.end());
    return p;
  };
  CHECK(square(0.0f) == block(2, 9, 2, 9));
  CHECK(square(1.0f / 256) == block(3, 10, 3, 10));
  CHECK(square(-1.0f / 256) == block(2, 9, 2, 9));
  CHECK(square(1.0f / 512) == block(2, 9, 2, 9));
  CHECK(square(3.0f / 512) == block(3, 10, 3, 10));
}

TEST_CASE("zero-area and sub-grid slivers cover nothing and front-facing is counter-clockwise") {
  CHECK(cover(at(1.5f, 1.5f), at(5.5f, 5.5f), at(9.5f, 9.5f)).empty());
  CHECK(cover(at(1.5f, 1.5f), at(9.5f, 1.5f), at(5.5f, 1.5f + 1.0f / 1024)).empty());  // snaps to zero area
  bool front = false;
  REQUIRE(coverTiles(at(1, 1), at(9, 1), at(1, 9), 16, 16, [](int, int) {}, &front));
  CHECK(front);
  REQUIRE(coverTiles(at(1, 1), at(1, 9), at(9, 1), 16, 16, [](int, int) {}, &front));
  CHECK_FALSE(front);
}

TEST_CASE("a fan of many small triangles tiling a rectangle covers each pixel exactly once") {
  // 40x30 rectangle [3.3, 43.3] x [2.7, 32.7] cut by an irregular grid, every cell split in two.
  constexpr int W = 48, H = 36;
  std::vector<int> count(W * H, 0);
  const float xs[] = {3.3f, 7.0f, 11.25f, 15.6f, 20.0f, 24.1f, 29.77f, 33.0f, 38.5f, 43.3f};
  const float ys[] = {2.7f, 6.1f, 10.0f, 14.45f, 19.3f, 23.0f, 27.9f, 32.7f};
  std::size_t triangles = 0;
  for (int j = 0; j + 1 < 8; ++j)
    for (int i = 0; i + 1 < 10; ++i) {
      // Perturb interior grid points so edges are not axis-aligned.
      const auto p = [&](int a, int b) {
        const bool interior = a > 0 && a < 9 && b > 0 && b < 7;
        return at(xs[a] + (interior ? 0.37f * static_cast<float>((a * 7 + b * 3) % 5 - 2) : 0.0f),
                  ys[b] + (interior ? 0.29f * static_cast<float>((a * 5 + b * 11) % 5 - 2) : 0.0f));
      };
      for (const auto& tri : {std::array{p(i, j), p(i + 1, j), p(i + 1, j + 1)}, std::array{p(i, j), p(i + 1, j + 1), p(i, j + 1)}}) {
        ++triangles;
        coverTiles(tri[0], tri[1], tri[2], W, H, [&](int x, int y) { ++count[y * W + x]; });
      }
    }
  CHECK(triangles == 9 * 7 * 2);
  int twice = 0, missing = 0, outside = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const float cx = static_cast<float>(x) + 0.5f, cy = static_cast<float>(y) + 0.5f;
      const bool inside = cx > 3.3f && cx < 43.3f && cy > 2.7f && cy < 32.7f;
      const int c = count[y * W + x];
      if (c > 1) ++twice;
      if (inside && c == 0) ++missing;
      if (!inside && c != 0) ++outside;
    }
  CHECK(twice == 0);
  CHECK(missing == 0);
  CHECK(outside == 0);
}

TEST_CASE("the renderer's tiled, block-first coverage equals the per-pixel walk on 20000 random triangles") {
  // Sizes from a fraction of a pixel to larger than the target, anywhere on and
  // off a 300x200 target of 5x4 tiles, both orientations, sub-pixel positions.
  constexpr int W = 300, H = 200;
  std::mt19937 random(7);
  std::uniform_real_distribution<float> centre(-40.0f, 340.0f), unit(-1.0f, 1.0f);
  long differing = 0, dropped = 0, drawn = 0;
  for (int n = 0; n < 20000; ++n) {
    const float scale = std::pow(2.0f, static_cast<float>(n % 11) - 2.0f);  // 0.25 .. 256 px
    const float cx = centre(random), cy = centre(random) * 2.0f / 3.0f;
    const WindowVertex a = at(cx + scale * unit(random), cy + scale * unit(random));
    const WindowVertex b = at(cx + scale * unit(random), cy + scale * unit(random));
    const WindowVertex c = at(cx + scale * unit(random), cy + scale * unit(random));
    Pixels reference, tiled;
    SnappedTriangle t;
    PixelBox box;
    const bool set = snap(a, b, c, W, H, t, box);
    if (set) rasterize(t, box, [&](int x, int y) { reference.insert({x, y}); });
    long repeats = 0;
    const bool binned = coverTiles(a, b, c, W, H, [&](int x, int y) { repeats += tiled.insert({x, y}).second ? 0 : 1; });
    differing += (set != binned || reference != tiled || repeats != 0) ? 1 : 0;
    dropped += set ? 0 : 1;
    drawn += static_cast<long>(reference.size());
  }
  CHECK(differing == 0);
  // The comparison means something: many triangles drawn, some dropped, many pixels.
  CHECK(dropped > 100);
  CHECK(drawn > 1000000);
}

TEST_CASE("coverage equals the per-pixel walk where a block's edge values leave 32 bits, and where they fit") {
  // Vertices up to 2^20 pixels away: edges whose step over a block reaches
  // 2^31 take the 64-bit walk of each pixel, the others the eight-lane rows.
  constexpr int W = 96, H = 64;
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  long differing = 0, wide = 0, narrow = 0, drawn = 0;
  for (int n = 0; n < 300; ++n) {
    const float reach = std::pow(2.0f, static_cast<float>(n % 21));  // 1 .. 2^20 px
    const auto vertex = [&] { return at(48.0f + reach * unit(random), 32.0f + reach * unit(random)); };
    const WindowVertex a = vertex(), b = vertex(), c = vertex();
    Pixels reference, tiled;
    SnappedTriangle t;
    PixelBox box;
    if (!snap(a, b, c, W, H, t, box)) continue;
    rasterize(t, box, [&](int x, int y) { reference.insert({x, y}); });
    coverTiles(a, b, c, W, H, [&](int x, int y) { tiled.insert({x, y}); });
    differing += reference != tiled ? 1 : 0;
    drawn += static_cast<long>(reference.size());
    EdgeFunction edges[3];
    edgeFunctions(t, edges);
    bool fits = true;
    for (const EdgeFunction& e : edges) fits = fits && blockReach(-e.dcdx * 256, e.dcdy * 256) < (std::int64_t{1} << 31);
    (fits ? narrow : wide) += reference.empty() ? 0 : 1;
  }
  CHECK(differing == 0);
  CHECK(wide > 20);  // both walks ran, on triangles that cover pixels
  CHECK(narrow > 20);
  CHECK(drawn > 100000);
}
