// glTF node animations (scene/animation.h): a channel's value between and
// beyond its keys by each interpolation, a node tree placed at a time, and
// the loader reading what it can of a file's animations and saying what not.
#include <cmath>
#include <string>

#include <doctest/doctest.h>
#include <glm/gtc/quaternion.hpp>

#include "pipeline/frame_inputs.h"
#include "scene/animation.h"
#include "scene/load_scene.h"

using namespace facet;

namespace {

AnimationChannel channel(AnimatedPath path, KeyInterpolation interpolation, std::vector<float> times, std::vector<glm::vec4> values) {
  AnimationChannel c;
  c.path = path;
  c.interpolation = interpolation;
  c.times = std::move(times);
  c.values = std::move(values);
  return c;
}

glm::vec4 rotationAbout(glm::vec3 axis, float degrees) {
  const glm::quat q = glm::angleAxis(glm::radians(degrees), axis);
  return {q.x, q.y, q.z, q.w};
}

}  // namespace

TEST_CASE("animation: LINEAR, STEP and CUBICSPLINE keys, slerp by the shorter arc, clamped before the first and after the last key") {
  const AnimationChannel linear = channel(AnimatedPath::Translation, KeyInterpolation::Linear, {1.0f, 3.0f}, {{0, 0, 0, 0}, {4, -2, 8, 0}});
  CHECK(channelValue(linear, 2.0f) == glm::vec4(2, -1, 4, 0));
  CHECK(channelValue(linear, 0.0f) == glm::vec4(0.0f));             // before: the first value
  CHECK(channelValue(linear, 9.0f) == glm::vec4(4, -2, 8, 0));      // after: the last
  CHECK(channelValue(linear, std::nanf("")) == glm::vec4(0.0f));    // a NaN time: the first

  const AnimationChannel step = channel(AnimatedPath::Translation, KeyInterpolation::Step, {0.0f, 1.0f, 2.0f}, {{1, 0, 0, 0}, {2, 0, 0, 0}, {3, 0, 0, 0}});
  CHECK(channelValue(step, 0.99f).x == 1.0f);
  CHECK(channelValue(step, 1.0f).x == 2.0f);
  CHECK(channelValue(step, 1.5f).x == 2.0f);

  // 0° to 90° about y: half way is 45°; 0° to 270° goes the shorter way, through -45°.
  const AnimationChannel turn =
      channel(AnimatedPath::Rotation, KeyInterpolation::Linear, {0.0f, 1.0f}, {rotationAbout({0, 1, 0}, 0), rotationAbout({0, 1, 0}, 90)});
  const glm::vec4 half = channelValue(turn, 0.5f), expected = rotationAbout({0, 1, 0}, 45);
  for (int k = 0; k < 4; ++k) CHECK(half[k] == doctest::Approx(expected[k]).epsilon(1e-5));
  const AnimationChannel around =
      channel(AnimatedPath::Rotation, KeyInterpolation::Linear, {0.0f, 1.0f}, {rotationAbout({0, 1, 0}, 0), rotationAbout({0, 1, 0}, 270)});
  const glm::vec4 shorter = channelValue(around, 0.5f), back = rotationAbout({0, 1, 0}, -45);
  CHECK(std::abs(shorter.x * back.x + shorter.y * back.y + shorter.z * back.z + shorter.w * back.w) == doctest::Approx(1.0f).epsilon(1e-5));

  // Hermite (glTF Appendix C) with key times 0 and 2: p(s) = (2s³ - 3s² + 1)v0 + 2(s³ - 2s² + s)b0 + (-2s³ + 3s²)v1 + 2(s³ - s²)a1.
  const AnimationChannel spline =
      channel(AnimatedPath::Scale, KeyInterpolation::CubicSpline, {0.0f, 2.0f}, {{9, 9, 9, 0}, {1, 0, 0, 0}, {2, 0, 0, 0}, {-1, 0, 0, 0}, {3, 0, 0, 0}, {9, 9, 9, 0}});
  const float s = 0.25f, s2 = s * s, s3 = s2 * s;
  const float p = (2 * s3 - 3 * s2 + 1) * 1 + 2 * (s3 - 2 * s2 + s) * 2 + (-2 * s3 + 3 * s2) * 3 + 2 * (s3 - s2) * -1;
  CHECK(channelValue(spline, 0.5f).x == doctest::Approx(p));
  CHECK(channelValue(spline, 0.0f).x == 1.0f);  // the value, not the in-tangent
  CHECK(channelValue(spline, 5.0f).x == 3.0f);
}

TEST_CASE("animation: a node tree placed at a time, parents first, and an unmoved node's instance exactly where the loader put it") {
  SceneAnimation animation;
  AnimatedNode root, child;
  root.local = glm::mat4(1.0f);
  child.parent = 0;
  child.translation = {1.0f, 0.0f, 0.0f};
  child.local = glm::translate(glm::mat4(1.0f), child.translation);
  animation.nodes = {root, child};
  animation.instanceNodes = {1};
  // The root turns 90° about z over one second: the child, one unit along x, swings to +y.
  animation.channels.push_back(
      channel(AnimatedPath::Rotation, KeyInterpolation::Linear, {0.0f, 1.0f}, {rotationAbout({0, 0, 1}, 0), rotationAbout({0, 0, 1}, 90)}));
  const std::vector<glm::mat4> rest = {glm::mat4(2.0f)};
  const glm::vec4 at1 = instanceTransformsAt(animation, rest, 1.0f)[0] * glm::vec4(0, 0, 0, 1);
  CHECK(at1.x == doctest::Approx(0.0f).epsilon(1e-6));
  CHECK(at1.y == doctest::Approx(1.0f));
  animation.channels.clear();
  CHECK(instanceTransformsAt(animation, rest, 1.0f)[0] == child.local);  // unmoved: the rest matrices' product
  animation.instanceNodes = {};
  CHECK(instanceTransformsAt(animation, rest, 1.0f)[0] == rest[0]);      // no node for the instance: its own transform
}

TEST_CASE("animation: assets/motion_blur.gltf loads its four channels and a frame places the instances at settings.time") {
  const Scene scene = loadScene(std::string(FACET_ASSETS) + "/motion_blur.gltf");
  CHECK(scene.animation.channels.size() == 4);
  CHECK(scene.animation.duration() == 1.0f);
  CHECK(scene.warnings.empty());
  RenderSettings s;
  s.width = 64, s.height = 48;
  s.time = 0.5f;
  const FrameInputs frame = buildFrameInputs(scene, s);
  // The ball (instance 0) from x = -2 to 2 over a second; the cube's STEP keys at 0.3 s (y 0.85) and 0.6 s (0.5).
  CHECK(frame.instances[0].worldFromModel[3].x == doctest::Approx(0.0f).epsilon(1e-6));
  const std::size_t cube = frame.instances.size() - 2;  // then the floor
  CHECK(frame.instances[cube].worldFromModel[3].y == doctest::Approx(0.85f));
  CHECK(glm::length(glm::vec3(frame.instances[cube].worldFromModel[1])) == doctest::Approx(1.75f));  // the spline's stretch half way
  s.time = 0.65f;
  CHECK(buildFrameInputs(scene, s).instances[cube].worldFromModel[3].y == doctest::Approx(0.5f));
}

TEST_CASE("animation: what cannot be read is skipped naming the channel, the file still loads") {
  // AnimatedMorphCube animates morph weights, which move nothing facet draws.
  const Scene morph = loadScene(std::string(FACET_ASSIMP_MODELS) + "/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf");
  CHECK(morph.animation.channels.empty());
  bool said = false;
  for (const std::string& w : morph.warnings) said = said || w.find("animations[0].channels[0]: target path 'weights'") != std::string::npos;
  CHECK(said);
}
