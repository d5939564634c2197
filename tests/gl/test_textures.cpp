// Base colour textures (renderer/PIPELINE.md, "Textures"): the texel values
// texelFetch gives the shaders, and a textured glTF model.
#include <cstring>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "gl/frame_block.h"
#include "gl/gl_object.h"
#include "gl/shader_program.h"
#include "gl_test_support.h"
#include "image/srgb.h"
#include "scene/load_scene.h"

using namespace facet;

TEST_CASE("a base colour texel reaches the shader as its byte and decodes to the shared table's value, for every byte") {
  test::GlHarness harness;
  const gl::GlFunctions& gl = harness.gl;
  // Every byte value in red, its complement in green, uploaded as scene_buffers.cpp uploads textures.
  constexpr int kWidth = 256;
  std::vector<Rgba8> texels(kWidth);
  for (int c = 0; c < kWidth; ++c) texels[static_cast<std::size_t>(c)] = {static_cast<std::uint8_t>(c), static_cast<std::uint8_t>(255 - c), 0, 255};
  const gl::GlObject texture = gl::createTexture(gl, GL_TEXTURE_2D);
  gl.TextureStorage2D(texture.id(), 1, GL_RGBA8UI, kWidth, 1);
  gl.TextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl.TextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl.TextureSubImage2D(texture.id(), 0, 0, 0, kWidth, 1, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE, texels.data());
  const gl::SrgbBlock srgb = gl::makeSrgbBlock();
  const gl::GlObject tables = gl::createBuffer(gl);
  gl.NamedBufferStorage(tables.id(), sizeof srgb, &srgb, 0);

  const gl::GlObject color = gl::createRenderbuffer(gl);
  gl.NamedRenderbufferStorage(color.id(), GL_RGBA32F, kWidth, 1);
  const gl::GlObject framebuffer = gl::createFramebuffer(gl);
  gl.NamedFramebufferRenderbuffer(framebuffer.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color.id());
  const gl::GlObject vertexArray = gl::createVertexArray(gl);

  // texel() of shaders/texture.glsl: the bytes, decoded by the SrgbTables block.
  const std::string probe = "#version 450 core\n#include \"shading_math.glsl\"\n#include \"srgb.glsl\"\n#include \"texture.glsl\"\nlayout(binding = 1) uniform usampler2D image;\n"
                            "out vec4 value;\nvoid main() { value = texel(image, 0, int(gl_FragCoord.x), 0, true); }\n";
  const gl::ShaderProgram program = gl::buildProgram(gl, {"viewport_triangle.vert", "probe.frag"}, "", [&](std::string_view name) {
    return name == "probe.frag" ? std::optional<std::string_view>(probe) : gl::findEmbeddedShaderFile(name);
  });
  gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
  gl.Viewport(0, 0, kWidth, 1);
  gl.UseProgram(program.id());
  gl.BindTextureUnit(1, texture.id());
  gl.BindBufferBase(GL_UNIFORM_BUFFER, 1, tables.id());
  gl.BindVertexArray(vertexArray.id());
  gl.DrawArrays(GL_TRIANGLES, 0, 3);
  std::vector<float> values(4 * kWidth);
  gl.ReadPixels(0, 0, kWidth, 1, GL_RGBA, GL_FLOAT, values.data());
  REQUIRE(gl.GetError() == GL_NO_ERROR);

  // renderer/shading/texture.cpp reads the same table: compared bit for bit.
  const SrgbTables& expected = srgbTables();
  int mismatches = 0, firstMismatch = -1;
  for (int c = 0; c < kWidth; ++c) {
    const float red = values[static_cast<std::size_t>(4 * c)], green = values[static_cast<std::size_t>(4 * c + 1)];
    const float expectedRed = expected.decoded[static_cast<std::size_t>(c)], expectedGreen = expected.decoded[static_cast<std::size_t>(255 - c)];
    if (std::memcmp(&red, &expectedRed, sizeof red) == 0 && std::memcmp(&green, &expectedGreen, sizeof green) == 0) continue;
    if (firstMismatch < 0) firstMismatch = c;
    ++mismatches;
  }
  CAPTURE(firstMismatch);
  CHECK(mismatches == 0);
  CHECK(values[4 * 200] > values[4 * 100]);  // decoded, increasing: not the bytes themselves, not zeros
  CHECK(values[4 * 255] == 1.0f);
}

TEST_CASE("a textured glTF box shows its texture: many colours, a blue and a green part of the logo") {
  const Scene scene = loadScene(std::string(FACET_ASSIMP_MODELS) + "/BoxTextured-glTF/BoxTextured.gltf");
  REQUIRE(scene.textures.size() == 1);
  for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong}) {
    const std::string name(kShadingModeNames[static_cast<std::size_t>(mode)]);
    CAPTURE(name);
    RenderSettings settings = test::smallSettings(mode, true);
    settings.width = 320;
    settings.height = 240;
    const FrameInputs frame = buildFrameInputs(scene, settings);
    const Image image = test::renderHeadless("box_textured_" + name, scene, frame);
    std::set<std::uint32_t> colours;
    int bluish = 0, greenish = 0;
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) {
        const Rgba8 p = image.at(x, y);
        colours.insert(static_cast<std::uint32_t>(p.r) << 16 | static_cast<std::uint32_t>(p.g) << 8 | p.b);
        bluish += p.b > p.r + 40 && p.b > p.g + 10;
        greenish += p.g > p.r + 20 && p.g > p.b + 20;
      }
    CHECK(colours.size() > 500);
    CHECK(bluish > 1000);
    CHECK(greenish > 1000);
  }
}
