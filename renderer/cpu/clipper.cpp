#include "cpu/clipper.h"

#include <algorithm>
#include <cmath>

#include "cpu/window_transform.h"

namespace facet::cpu {
namespace {

// Plane i keeps dot(p, kPlanes[i]) ≥ 0: w - x, w + x, w - y, w + y, z, w - z.
constexpr float kPlanes[6][4] = {{-1, 0, 0, 1}, {1, 0, 0, 1}, {0, -1, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 0}, {0, 0, -1, 1}};

// Evaluated left to right with separate roundings, as draw's dot4.
float planeDistance(const glm::vec4& p, const float* plane) {
  return p.x * plane[0] + p.y * plane[1] + p.z * plane[2] + p.w * plane[3];
}

// LINTERP(t, out, in) = out + t·(in - out) on every component.
ClipVertex interpolate(float t, const ClipVertex& out, const ClipVertex& in, int varyingCount) {
  ClipVertex v;
  for (int k = 0; k < 4; ++k) v.clip[k] = out.clip[k] + t * (in.clip[k] - out.clip[k]);
  for (int k = 0; k < varyingCount; ++k) {
    const auto i = static_cast<std::size_t>(k);
    v.varyings[i] = out.varyings[i] + t * (in.varyings[i] - out.varyings[i]);
  }
  return v;
}

// A window vertex with window_transform.h's arithmetic for its origin.
WindowVertex windowVertex(const ClipVertex& v, float halfWidth, float halfHeight, int varyingCount, bool madeByClipper) {
  WindowVertex w;
  const WindowPosition p = windowPosition(v.clip, halfWidth, halfHeight, madeByClipper);
  w.x = p.x, w.y = p.y, w.z = p.z, w.invW = p.invW;
  for (int k = 0; k < varyingCount; ++k) w.varyings[static_cast<std::size_t>(k)] = v.varyings[static_cast<std::size_t>(k)];
  return w;
}

}  // namespace

WindowVertex toWindow(const ClipVertex& v, float halfWidth, float halfHeight, int varyingCount) {
  return windowVertex(v, halfWidth, halfHeight, varyingCount, false);
}

void clipTriangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, const WindowVertex& windowA,
                  const WindowVertex& windowB, const WindowVertex& windowC, float halfWidth, float halfHeight, int varyingCount,
                  std::vector<WindowVertex>& out) {
  // A NaN or infinite coordinate has no place in clip space: the triangle is dropped.
  const auto finite = [](const glm::vec4& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w); };
  if (!finite(a.clip) || !finite(b.clip) || !finite(c.clip)) return;
  const unsigned ma = clipMask(a.clip), mb = clipMask(b.clip), mc = clipMask(c.clip);
  if ((ma | mb | mc) == 0) {
    out.insert(out.end(), {windowA, windowB, windowC});
    return;
  }
  if (ma & mb & mc) return;  // all three outside one plane

  // Sutherland-Hodgman over the planes the triangle crosses, lowest bit first.
  // `store` holds every vertex; the lists hold indices; window vertices are
  // kept for the original three so unclipped corners keep their fma coordinates.
  std::array<ClipVertex, 3 + 6 * 2> store{a, b, c};
  std::array<bool, store.size()> original{true, true, true};
  std::size_t stored = 3;
  std::array<int, 9> list{0, 1, 2}, next{};
  std::size_t count = 3;
  unsigned mask = ma | mb | mc;
  while (mask && count >= 3) {
    const int plane = __builtin_ctz(mask);
    mask &= mask - 1;
    std::size_t nextCount = 0;
    int previous = list[0];
    float dpPrevious = planeDistance(store[static_cast<std::size_t>(previous)].clip, kPlanes[plane]);
    for (std::size_t i = 1; i <= count; ++i) {
      const int current = list[i % count];
      const float dp = planeDistance(store[static_cast<std::size_t>(current)].clip, kPlanes[plane]);
      bool crosses;
      if (dpPrevious >= 0.0f) {
        next[nextCount++] = previous;
        crosses = dp < 0.0f;
      } else {
        crosses = !(dp < 0.0f);
      }
      if (crosses && stored < store.size() && nextCount < next.size()) {
        // Interpolate from the vertex outside toward the one inside, with t from the nearer end (draw's choice).
        const float denom = dp - dpPrevious;
        const ClipVertex& prev = store[static_cast<std::size_t>(previous)];
        const ClipVertex& cur = store[static_cast<std::size_t>(current)];
        ClipVertex made;
        if (dp < 0.0f) {
          made = -dp < dpPrevious ? interpolate(dp / denom, cur, prev, varyingCount) : interpolate(-dpPrevious / denom, prev, cur, varyingCount);
        } else {
          made = -dpPrevious < dp ? interpolate(-dpPrevious / denom, prev, cur, varyingCount) : interpolate(dp / denom, cur, prev, varyingCount);
        }
        store[stored] = made;
        original[stored] = false;
        next[nextCount++] = static_cast<int>(stored++);
      }
      previous = current;
      dpPrevious = dp;
    }
    list = next;
    count = nextCount;
  }
  if (count < 3) return;

  const WindowVertex* originals[3] = {&windowA, &windowB, &windowC};
  const auto window = [&](int index) {
    const auto i = static_cast<std::size_t>(index);
    return original[i] ? *originals[i] : windowVertex(store[i], halfWidth, halfHeight, varyingCount, true);
  };
  const WindowVertex first = window(list[0]);
  WindowVertex previous = window(list[1]);
  for (std::size_t i = 2; i < count; ++i) {
    const WindowVertex current = window(list[i]);
    out.insert(out.end(), {previous, current, first});
    previous = current;
  }
}

bool clipSegment(const ClipVertex& a, const ClipVertex& b, const WindowVertex& windowA, const WindowVertex& windowB, float halfWidth,
                 float halfHeight, int varyingCount, WindowVertex& outA, WindowVertex& outB) {
  const unsigned ma = clipMask(a.clip), mb = clipMask(b.clip);
  if ((ma | mb) == 0) {
    outA = windowA, outB = windowB;
    return true;
  }
  if (ma & mb) return false;  // both outside one plane
  float t0 = 0.0f, t1 = 0.0f;
  for (unsigned mask = ma | mb; mask; mask &= mask - 1) {
    const int plane = __builtin_ctz(mask);
    const float dp0 = planeDistance(a.clip, kPlanes[plane]), dp1 = planeDistance(b.clip, kPlanes[plane]);
    if (!std::isfinite(dp0) || !std::isfinite(dp1)) return false;
    if (dp1 < 0.0f) t1 = std::max(t1, dp1 / (dp1 - dp0));
    if (dp0 < 0.0f) t0 = std::max(t0, dp0 / (dp0 - dp1));
    if (t0 + t1 >= 1.0f) return false;
  }
  outA = ma ? windowVertex(interpolate(t0, a, b, varyingCount), halfWidth, halfHeight, varyingCount, true) : windowA;
  outB = mb ? windowVertex(interpolate(t1, b, a, varyingCount), halfWidth, halfHeight, varyingCount, true) : windowB;
  return true;
}

}  // namespace facet::cpu
