// FrameBlock, the C++ mirror of the std140 block Frame: its offsets are the
// driver's, and it carries FrameInputs' values.
#include <cstddef>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "common/error.h"
#include "gl/frame_block.h"
#include "gl/shader_program.h"
#include "gl/shader_variant.h"
#include "pipeline/frame_inputs.h"
#include "cpu/cpu_renderer.h"
#include "gl_test_support.h"
#include "scene/default_scene.h"

using namespace facet;
using namespace facet::gl;

namespace {

struct Member {
  std::string name;     // as the driver names it: "Frame.lights[3].shadowFromWorld[0]"
  std::size_t offset;   // in FrameBlock
};

std::vector<Member> frameBlockMembers() {
  std::vector<Member> members = {
      {"Frame.eyePosition", offsetof(FrameBlock, eyePosition)},   {"Frame.towardEye", offsetof(FrameBlock, towardEye)},
      {"Frame.ambient", offsetof(FrameBlock, ambient)},           {"Frame.shadowParams", offsetof(FrameBlock, shadowParams)},
      {"Frame.background", offsetof(FrameBlock, background)},
      {"Frame.environment", offsetof(FrameBlock, environment)},     {"Frame.backgroundForward", offsetof(FrameBlock, backgroundForward)},
      {"Frame.backgroundRight", offsetof(FrameBlock, backgroundRight)}, {"Frame.backgroundUp", offsetof(FrameBlock, backgroundUp)},
      {"Frame.fog", offsetof(FrameBlock, fog)}, {"Frame.fogColor", offsetof(FrameBlock, fogColor)}, {"Frame.fogRange", offsetof(FrameBlock, fogRange)},
  };
  for (std::size_t i = 0; i < facet::kMaxLights; ++i) {
    const std::string light = "Frame.lights[" + std::to_string(i) + "].";
    const std::size_t base = offsetof(FrameBlock, lights) + i * sizeof(LightBlock);
    members.push_back({light + "position", base + offsetof(LightBlock, position)});
    members.push_back({light + "directionCosCutoff", base + offsetof(LightBlock, directionCosCutoff)});
    members.push_back({light + "intensity", base + offsetof(LightBlock, intensity)});
    members.push_back({light + "attenuation", base + offsetof(LightBlock, attenuation)});
    members.push_back({light + "shadow", base + offsetof(LightBlock, shadow)});
    members.push_back({light + "shadowFromWorld[0]", base + offsetof(LightBlock, shadowFromWorld)});
  }
  return members;
}

}  // namespace

TEST_CASE("the driver lays the Frame block out as FrameBlock: every offset, the array and matrix strides, the size") {
  test::GlHarness harness;
  const GlFunctions& gl = harness.gl;
  // The program that reads the most of the block; std140 keeps every member active anyway.
  const ShaderProgram program = buildProgram(gl, {"lit_phong.vert", "lit_phong.frag"}, litShaderDefines(buildFrameInputs(makeDefaultScene(), RenderSettings{}), {}));
  const GLuint block = gl.GetUniformBlockIndex(program.id(), "Frame");
  REQUIRE(block != GL_INVALID_INDEX);
  GLint size = 0;
  gl.GetActiveUniformBlockiv(program.id(), block, GL_UNIFORM_BLOCK_DATA_SIZE, &size);
  CHECK(size == static_cast<GLint>(sizeof(FrameBlock)));

  const std::vector<Member> members = frameBlockMembers();
  std::vector<const char*> names;
  for (const Member& m : members) names.push_back(m.name.c_str());
  std::vector<GLuint> indices(members.size(), GL_INVALID_INDEX);
  gl.GetUniformIndices(program.id(), static_cast<GLsizei>(names.size()), names.data(), indices.data());
  for (std::size_t i = 0; i < members.size(); ++i) {
    INFO(members[i].name);
    REQUIRE(indices[i] != GL_INVALID_INDEX);
    GLint offset = -1, blockIndex = -1;
    gl.GetActiveUniformsiv(program.id(), 1, &indices[i], GL_UNIFORM_OFFSET, &offset);
    gl.GetActiveUniformsiv(program.id(), 1, &indices[i], GL_UNIFORM_BLOCK_INDEX, &blockIndex);
    CHECK(blockIndex == static_cast<GLint>(block));
    CHECK(offset == static_cast<GLint>(members[i].offset));
  }

  // shadowFromWorld: six column-major mat4, 64 bytes apart, columns 16 apart (std::array<glm::mat4, 6>).
  GLint arrayStride = 0, matrixStride = 0, rowMajor = 1;
  const GLuint matrices = indices.back();
  gl.GetActiveUniformsiv(program.id(), 1, &matrices, GL_UNIFORM_ARRAY_STRIDE, &arrayStride);
  gl.GetActiveUniformsiv(program.id(), 1, &matrices, GL_UNIFORM_MATRIX_STRIDE, &matrixStride);
  gl.GetActiveUniformsiv(program.id(), 1, &matrices, GL_UNIFORM_IS_ROW_MAJOR, &rowMajor);
  CHECK(arrayStride == static_cast<GLint>(sizeof(glm::mat4)));
  CHECK(matrixStride == static_cast<GLint>(sizeof(glm::vec4)));
  CHECK(rowMajor == 0);
}

TEST_CASE("makeFrameBlock copies FrameInputs into the block's slots") {
  const Scene scene = makeDefaultScene();
  const FrameInputs frame = buildFrameInputs(scene, test::smallSettings(ShadingMode::Gouraud));
  const FrameBlock block = makeFrameBlock(frame);
  CHECK(block.eyePosition == glm::vec4(frame.eyePosition, 1.0f));  // w = 1: perspective
  CHECK(block.ambient == glm::vec4(frame.ambient, frame.proceduralScale, 0.0f, 0.0f));
  CHECK(block.shadowParams == glm::vec4(frame.shadows.biasSlope, frame.shadows.biasMin, 512.0f, 0.0f));
  const FrameLight& light = frame.lights[0];
  CHECK(block.lights[0].position == glm::vec4(light.light.position, 1.0f));
  CHECK(block.lights[0].intensity == glm::vec4(light.intensity, 0.0f));
  CHECK(block.lights[0].attenuation == glm::vec4(light.light.attenuation, 0.0f));
  CHECK(block.lights[0].shadow == glm::ivec4(0, 0, 0, 0));  // its faces start at layer 0
  for (std::size_t face = 0; face < 6; ++face) CHECK(block.lights[0].shadowFromWorld[face] == light.shadowFromWorld[face]);
  CHECK(block.lights[1].intensity == glm::vec4(0.0f));  // unused slots stay zero
}

TEST_CASE("a frame with more lights than the block holds is refused by both backends alike, before drawing") {
  const Scene scene = makeDefaultScene();
  FrameInputs frame = buildFrameInputs(scene, test::smallSettings(ShadingMode::Phong, false));
  frame.lights.resize(facet::kMaxLights + 1, frame.lights[0]);
  const char* expected = "9 lights: a frame shades at most 8";
  CHECK_THROWS_WITH_AS(makeGlRenderer(GlContextKind::OsMesa)->render(scene, frame), expected, Error);
  CHECK_THROWS_WITH_AS(makeCpuRenderer(1)->render(scene, frame), expected, Error);
}
