#pragma once
// glTF node animations (glTF 2.0, 3.11): the node tree a file places its
// meshes with, and the channels that move its nodes' translation, rotation
// and scale over time, so that a frame can place every mesh instance at
// `time` (renderer/PIPELINE.md, "Scene") and the ray tracer at the times
// of its shutter ("Ray tracing", motion blur). Morph weights and skins do not
// move anything here.
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace facet {

// A node as the file places it below its parent: its T, R and S, and the
// local matrix the loader made of them (or the file's `matrix`), which a
// node no channel moves keeps, so that its instances' TMs are the loader's.
struct AnimatedNode {
  int parent = -1;  // index into SceneAnimation::nodes; -1 for a root
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 scale{1.0f};
  bool hasMatrix = false;        // given by `matrix`: not animated (glTF forbids it)
  glm::mat4 local{1.0f};         // the rest pose's local matrix
};

enum class AnimatedPath { Translation, Rotation, Scale };
enum class KeyInterpolation { Linear, Step, CubicSpline };

// One channel: a node's translation, rotation or scale at increasing key
// times. Values are xyz (translation, scale) or xyzw (rotation); a cubic
// spline holds three per key: in-tangent, value, out-tangent.
struct AnimationChannel {
  int node = 0;
  AnimatedPath path = AnimatedPath::Translation;
  KeyInterpolation interpolation = KeyInterpolation::Linear;
  std::vector<float> times;       // seconds, strictly increasing
  std::vector<glm::vec4> values;
};

struct SceneAnimation {
  std::vector<AnimatedNode> nodes;
  std::vector<AnimationChannel> channels;
  std::vector<int> instanceNodes;  // per Scene::instances entry: the node that places it

  bool empty() const { return channels.empty(); }
  float duration() const;  // the last key time of any channel (0: none)
};

// A channel's value at `time`: before its first key the first value, after
// its last the last; between keys by its interpolation (LINEAR: lerp, or
// slerp by the shorter arc for a rotation; STEP: the key at or before;
// CUBICSPLINE: the Hermite spline of glTF's Appendix C); a rotation normalized.
glm::vec4 channelValue(const AnimationChannel& channel, float time);

// Every instance's TM at `time`: each node's T·R·S with its channels'
// values, times its parent's, parents first. `rest` (Scene::instances'
// transforms) is returned unchanged where the animation has no node for an
// instance.
std::vector<glm::mat4> instanceTransformsAt(const SceneAnimation& animation, const std::vector<glm::mat4>& rest, float time);

}  // namespace facet
