#include "scene/animation.h"

#include <algorithm>
#include <cmath>

#include "math/transforms.h"

namespace facet {
namespace {

glm::vec4 quatVec(const glm::quat& q) { return {q.x, q.y, q.z, q.w}; }
glm::quat vecQuat(const glm::vec4& v) { return glm::quat(v.w, v.x, v.y, v.z); }

// Normalized, or the identity where it has no length (a broken key turns nothing).
glm::vec4 unitRotation(glm::vec4 q) {
  const float length = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  return length > 0.0f && std::isfinite(length) ? q / length : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
}

}  // namespace

float SceneAnimation::duration() const {
  float last = 0.0f;
  for (const AnimationChannel& c : channels)
    if (!c.times.empty()) last = std::max(last, c.times.back());
  return last;
}

glm::vec4 channelValue(const AnimationChannel& c, float time) {
  const std::size_t keys = c.times.size();
  const bool cubic = c.interpolation == KeyInterpolation::CubicSpline;
  const auto value = [&](std::size_t k) { return c.values[cubic ? 3 * k + 1 : k]; };
  const bool rotation = c.path == AnimatedPath::Rotation;
  if (keys == 0) return rotation ? glm::vec4(0.0f, 0.0f, 0.0f, 1.0f) : glm::vec4(0.0f);
  if (!(time > c.times.front())) return rotation ? unitRotation(value(0)) : value(0);  // before the first key, and NaN
  if (time >= c.times.back()) return rotation ? unitRotation(value(keys - 1)) : value(keys - 1);
  // The key k with times[k] <= time < times[k + 1].
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(c.times.begin(), c.times.end(), time) - c.times.begin()) - 1;
  const float t0 = c.times[k], t1 = c.times[k + 1];
  const float s = (time - t0) / (t1 - t0);
  glm::vec4 v;
  switch (c.interpolation) {
    case KeyInterpolation::Step:
      v = value(k);
      break;
    case KeyInterpolation::CubicSpline: {
      // glTF 2.0, Appendix C: p(s) = (2s³ - 3s² + 1)·v_k + td·(s³ - 2s² + s)·b_k + (-2s³ + 3s²)·v_k+1 + td·(s³ - s²)·a_k+1.
      const float td = t1 - t0, s2 = s * s, s3 = s2 * s;
      const glm::vec4 b = c.values[3 * k + 2], a = c.values[3 * (k + 1)];
      v = (2.0f * s3 - 3.0f * s2 + 1.0f) * value(k) + (td * (s3 - 2.0f * s2 + s)) * b + (-2.0f * s3 + 3.0f * s2) * value(k + 1) +
          (td * (s3 - s2)) * a;
      break;
    }
    case KeyInterpolation::Linear:
      v = rotation ? quatVec(glm::slerp(vecQuat(unitRotation(value(k))), vecQuat(unitRotation(value(k + 1))), s))
                   : value(k) + s * (value(k + 1) - value(k));
      break;
  }
  return rotation ? unitRotation(v) : v;
}

std::vector<glm::mat4> instanceTransformsAt(const SceneAnimation& animation, const std::vector<glm::mat4>& rest, float time) {
  std::vector<AnimatedNode> nodes = animation.nodes;
  std::vector<char> moved(nodes.size(), 0);
  for (const AnimationChannel& c : animation.channels) {
    if (c.node < 0 || static_cast<std::size_t>(c.node) >= nodes.size()) continue;
    AnimatedNode& n = nodes[static_cast<std::size_t>(c.node)];
    if (n.hasMatrix) continue;
    moved[static_cast<std::size_t>(c.node)] = 1;
    const glm::vec4 v = channelValue(c, time);
    if (c.path == AnimatedPath::Translation) n.translation = glm::vec3(v);
    else if (c.path == AnimatedPath::Scale) n.scale = glm::vec3(v);
    else n.rotation = vecQuat(v);
  }
  // World transforms, parents first: a node's parent has a smaller index (the loader adds them walking down).
  // T·R·S as the loader composes it (math/transforms.h), so that an unmoved node's product is the loader's.
  std::vector<glm::mat4> world(nodes.size(), glm::mat4(1.0f));
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const AnimatedNode& n = nodes[i];
    const glm::mat4 local = moved[i] ? translation(n.translation) * glm::mat4_cast(n.rotation) * scaling(n.scale) : n.local;
    world[i] = n.parent >= 0 && static_cast<std::size_t>(n.parent) < i ? world[static_cast<std::size_t>(n.parent)] * local : local;
  }
  std::vector<glm::mat4> out = rest;
  for (std::size_t i = 0; i < out.size() && i < animation.instanceNodes.size(); ++i) {
    const int node = animation.instanceNodes[i];
    if (node >= 0 && static_cast<std::size_t>(node) < world.size()) out[i] = world[static_cast<std::size_t>(node)];
  }
  return out;
}

}  // namespace facet
