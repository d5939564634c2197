// The shaders' arithmetic (shaders/shading_math.glsl, lighting.glsl,
// srgb.glsl, blending.glsl) against its C++ mirror (renderer/shading/shading_math.h,
// lighting.h, blending.h, image/srgb.h) on llvmpipe, bit for bit, over random inputs and
// the edge cases each function decides: a fragment shader evaluates one
// GLSL expression per pixel from two input textures and writes the floats.
#include <cmath>
#include <cstring>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "shading/blending.h"
#include "shading/lighting.h"
#include "shading/physically_based.h"
#include "shading/shading_math.h"
#include "gl/frame_block.h"
#include "gl/gl_object.h"
#include "gl/shader_program.h"
#include "gl/shader_variant.h"
#include "gl_test_support.h"
#include "image/srgb.h"
#include "pipeline/frame_inputs.h"
#include "scene/default_scene.h"

using namespace facet;

namespace {

constexpr int kWidth = 4096;

// Runs `expression` (GLSL, of vec4 a and b, giving a vec4) for each pair of inputs; returns the outputs.
std::vector<glm::vec4> evaluate(const std::string& expression, const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
  test::GlHarness harness;
  const gl::GlFunctions& gl = harness.gl;
  const auto texture = [&](const std::vector<glm::vec4>& values) {
    gl::GlObject t = gl::createTexture(gl, GL_TEXTURE_2D);
    gl.TextureStorage2D(t.id(), 1, GL_RGBA32F, kWidth, 1);
    gl.TextureSubImage2D(t.id(), 0, 0, 0, kWidth, 1, GL_RGBA, GL_FLOAT, values.data());
    return t;
  };
  const gl::GlObject textureA = texture(a), textureB = texture(b);
  const gl::SrgbBlock srgb = gl::makeSrgbBlock();
  const gl::GlObject tables = gl::createBuffer(gl);
  gl.NamedBufferStorage(tables.id(), sizeof srgb, &srgb, 0);
  const gl::SplitSumBlock splitSum = gl::makeSplitSumBlock();
  const gl::GlObject splitSumTable = gl::createBuffer(gl);
  gl.NamedBufferStorage(splitSumTable.id(), sizeof splitSum, &splitSum, 0);
  const gl::GlObject color = gl::createRenderbuffer(gl);
  gl.NamedRenderbufferStorage(color.id(), GL_RGBA32F, kWidth, 1);
  const gl::GlObject framebuffer = gl::createFramebuffer(gl);
  gl.NamedFramebufferRenderbuffer(framebuffer.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color.id());
  const gl::GlObject vertexArray = gl::createVertexArray(gl);

  const std::string probe = "#version 450 core\n#include \"frame_block.glsl\"\n#include \"transform.glsl\"\n#include \"shading_math.glsl\"\n"
                            "#include \"srgb.glsl\"\n#include \"texture.glsl\"\n#include \"procedural.glsl\"\n#include \"draw_uniforms.glsl\"\n"
                            "#include \"environment.glsl\"\n#include \"lighting.glsl\"\n#include \"physically_based.glsl\"\n#include \"blending.glsl\"\n"
                            "layout(binding = 14) uniform sampler2D inputA;\nlayout(binding = 15) uniform sampler2D inputB;\nout vec4 value;\n"
                            "void main() {\n  vec4 a = texelFetch(inputA, ivec2(gl_FragCoord.xy), 0), b = texelFetch(inputB, ivec2(gl_FragCoord.xy), 0);\n"
                            "  value = " + expression + ";\n}\n";
  const FrameInputs frame = buildFrameInputs(makeDefaultScene(), RenderSettings{});
  const gl::ShaderProgram program = gl::buildProgram(gl, {"viewport_triangle.vert", "probe.frag"}, gl::litShaderDefines(frame, {}), [&](std::string_view name) {
    return name == "probe.frag" ? std::optional<std::string_view>(probe) : gl::findEmbeddedShaderFile(name);
  });
  gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
  gl.Viewport(0, 0, kWidth, 1);
  gl.UseProgram(program.id());
  gl.BindTextureUnit(14, textureA.id());
  gl.BindTextureUnit(15, textureB.id());
  gl.BindBufferBase(GL_UNIFORM_BUFFER, 1, tables.id());
  gl.BindBufferBase(GL_UNIFORM_BUFFER, 2, splitSumTable.id());
  gl.BindVertexArray(vertexArray.id());
  gl.DrawArrays(GL_TRIANGLES, 0, 3);
  std::vector<glm::vec4> out(kWidth);
  gl.ReadPixels(0, 0, kWidth, 1, GL_RGBA, GL_FLOAT, out.data());
  REQUIRE(gl.GetError() == GL_NO_ERROR);
  return out;
}

bool sameBits(const glm::vec4& x, const glm::vec4& y) { return std::memcmp(&x, &y, sizeof x) == 0; }

// Pixels whose shader output differs from `expected` in any bit.
int mismatches(const std::string& expression, const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b,
               const std::function<glm::vec4(const glm::vec4&, const glm::vec4&)>& expected) {
  const std::vector<glm::vec4> out = evaluate(expression, a, b);
  int count = 0;
  for (std::size_t i = 0; i < out.size(); ++i) count += sameBits(out[i], expected(a[i], b[i])) ? 0 : 1;
  return count;
}

std::vector<glm::vec4> random(std::mt19937& rng, float lo, float hi) {
  std::uniform_real_distribution<float> d(lo, hi);
  std::vector<glm::vec4> v(kWidth);
  for (glm::vec4& x : v) x = {d(rng), d(rng), d(rng), d(rng)};
  return v;
}

}  // namespace

TEST_CASE("shader arithmetic: dot3, cross3, length3 and normalize3 give the CPU's bits") {
  std::mt19937 rng(1);
  const auto a = random(rng, -10.0f, 10.0f), b = random(rng, -10.0f, 10.0f);
  CHECK(mismatches("vec4(dot3(a.xyz, b.xyz), length3(a.xyz), 0.0, 0.0)", a, b, [](const glm::vec4& x, const glm::vec4& y) {
          return glm::vec4(dot3(glm::vec3(x), glm::vec3(y)), length3(glm::vec3(x)), 0.0f, 0.0f);
        }) == 0);
  CHECK(mismatches("vec4(normalize3(a.xyz), 0.0)", a, b, [](const glm::vec4& x, const glm::vec4&) {
          return glm::vec4(normalize3(glm::vec3(x)), 0.0f);
        }) == 0);
  CHECK(mismatches("vec4(cross3(a.xyz, b.xyz), 0.0)", a, b, [](const glm::vec4& x, const glm::vec4& y) {
          return glm::vec4(cross3(glm::vec3(x), glm::vec3(y)), 0.0f);
        }) == 0);
}

TEST_CASE("shader arithmetic: power, the specular exponent, gives the CPU's bits, also at 0, 1, NaN and tiny results") {
  std::mt19937 rng(2);
  auto base = random(rng, 0.0f, 1.0f), exponent = random(rng, 1.0f, 1024.0f);
  const float specials[] = {0.0f, 1.0f, -0.5f, 1e-30f, 0.999999f, std::nanf(""), 2.0f, 1e30f};
  for (std::size_t i = 0; i < 64; ++i) base[i].x = specials[i % 8];
  for (std::size_t i = 64; i < 128; ++i) exponent[i].x = 1.0f / 2.4f;
  CHECK(mismatches("vec4(power(a.x, b.x), power(a.y, b.y), power(a.z, 2.4), power(a.w, 1.0))", base, exponent,
                   [](const glm::vec4& x, const glm::vec4& y) {
                     return glm::vec4(power(x.x, y.x), power(x.y, y.y), power(x.z, 2.4f), power(x.w, 1.0f));
                   }) == 0);
}

TEST_CASE("shader arithmetic: the cube face of a point light, ties to x then y then z, as the CPU picks it") {
  std::mt19937 rng(3);
  std::vector<glm::vec4> d = random(rng, -5.0f, 5.0f);
  // Ties between components, of both signs: the rule decides these.
  const glm::vec4 ties[] = {{1, 1, 0, 0}, {-1, 1, 0, 0}, {1, -1, 1, 0}, {0, 2, 2, 0}, {0, -2, -2, 0}, {3, 0, -3, 0}, {-3, 3, 3, 0}, {0, 0, 0, 0}};
  for (std::size_t i = 0; i < 256; ++i) d[i] = ties[i % 8] * static_cast<float>(1 + i / 8);
  CHECK(mismatches("vec4(float(cubeFace(a.xyz)), 0.0, 0.0, 0.0)", d, d, [](const glm::vec4& x, const glm::vec4&) {
          return glm::vec4(static_cast<float>(cubeFace(glm::vec3(x))), 0.0f, 0.0f, 0.0f);
        }) == 0);
}

TEST_CASE("shader arithmetic: the sRGB level of a linear value, at every threshold and the float below it, as the CPU's") {
  std::mt19937 rng(4);
  std::vector<glm::vec4> c = random(rng, -0.1f, 1.1f);
  const SrgbTables& t = srgbTables();
  for (int k = 1; k < 256; ++k) {
    c[static_cast<std::size_t>(k)].x = t.thresholds[static_cast<std::size_t>(k)];
    c[static_cast<std::size_t>(k)].y = std::nextafter(t.thresholds[static_cast<std::size_t>(k)], 0.0f);
  }
  c[0] = {std::nanf(""), -0.0f, 1.0f, 1e9f};
  CHECK(mismatches("vec4(float(encodeLevel(a.x)), float(encodeLevel(a.y)), float(encodeLevel(a.z)), float(encodeLevel(a.w)))", c, c,
                   [](const glm::vec4& x, const glm::vec4&) {
                     return glm::vec4(encodeLevel(x.x), encodeLevel(x.y), encodeLevel(x.z), encodeLevel(x.w));
                   }) == 0);
}

TEST_CASE("shader arithmetic: the resolve's alpha level, at every level's boundary and the floats beside it, as the CPU's") {
  std::mt19937 rng(14);
  std::vector<glm::vec4> a = random(rng, -0.1f, 1.1f);
  for (int k = 0; k < 256; ++k) {  // (k - 0.5)/255, where floor(255·a + 0.5) steps, and its neighbours
    const float edge = (static_cast<float>(k) - 0.5f) / 255.0f;
    a[static_cast<std::size_t>(k)] = {edge, std::nextafter(edge, -1.0f), std::nextafter(edge, 2.0f), static_cast<float>(k) / 255.0f};
  }
  a[256] = {std::nanf(""), -0.0f, 1.0f, 1e9f};
  CHECK(mismatches("vec4(float(alphaLevel(a.x)), float(alphaLevel(a.y)), float(alphaLevel(a.z)), float(alphaLevel(a.w)))", a, a,
                   [](const glm::vec4& x, const glm::vec4&) {
                     return glm::vec4(alphaLevel(x.x), alphaLevel(x.y), alphaLevel(x.z), alphaLevel(x.w));
                   }) == 0);
}

TEST_CASE("shader arithmetic: attenuation and the selects of max, min and their NaN results, as the CPU's") {
  std::mt19937 rng(5);
  std::vector<glm::vec4> x = random(rng, -2.0f, 2.0f), c = random(rng, 0.0f, 1.0f);
  x[0] = {std::nanf(""), -0.0f, 0.0f, 1.0f};
  CHECK(mismatches("vec4(maxZero(a.x), minOne(a.y), attenuation(b.xyz, abs(a.z) * 10.0), maxZero(a.w))", x, c,
                   [](const glm::vec4& v, const glm::vec4& k) {
                     return glm::vec4(maxZero(v.x), minOne(v.y), attenuation(glm::vec3(k), std::fabs(v.z) * 10.0f), maxZero(v.w));
                   }) == 0);
}

TEST_CASE("shader arithmetic: exp2Of and shading=pbr's Fresnel, GGX, Smith visibility and split-sum table give the CPU's bits") {
  std::mt19937 rng(6);
  std::vector<glm::vec4> x = random(rng, 0.0f, 1.0f), y = random(rng, 0.0f, 1.0f);
  // The ends each function decides: 0 and 1 cosines, a mirror's α² floor, exponents beyond the series' range.
  const glm::vec4 ends[] = {{0, 0, 0, 0}, {1, 1, 1, 1}, {1, 0, 1e-6f, 0}, {0, 1, 1e-6f, 1}, {0.5f, 0.5f, 1.0f, 0.5f}};
  for (std::size_t i = 0; i < 5; ++i) x[i] = ends[i], y[i] = ends[4 - i];
  CHECK(mismatches("vec4(schlickFresnel(a.xyz, b.x), ggxDistribution(a.w, b.y))", x, y, [](const glm::vec4& a, const glm::vec4& b) {
          return glm::vec4(schlickFresnel(glm::vec3(a), b.x), ggxDistribution(a.w, b.y));
        }) == 0);
  CHECK(mismatches("vec4(smithVisibility(a.x, a.y, b.z), environmentBrdf(a.z, b.w), exp2Of(-200.0 * a.w + 60.0))", x, y,
                   [](const glm::vec4& a, const glm::vec4& b) {
                     const glm::vec2 ab = environmentBrdf(a.z, b.w);
                     return glm::vec4(smithVisibility(a.x, a.y, b.z), ab.x, ab.y, exp2Of(-200.0f * a.w + 60.0f));
                   }) == 0);
}

TEST_CASE("shader arithmetic: both blending equations (over and additive), the premultiplied buffer's store and resolve and the samples' sum give the CPU's bits") {
  std::mt19937 rng(7);
  std::vector<glm::vec4> held = random(rng, 0.0f, 1.0f), fragment = random(rng, -0.5f, 1.5f);  // alpha beyond [0, 1] is clamped
  // What each equation decides: alpha NaN, 0, 1, below 0; nothing under a clear fragment (α_o = 0); colours above 1.
  const glm::vec4 edgesHeld[] = {{0.2f, 0.4f, 0.6f, 0.0f}, {0.2f, 0.4f, 0.6f, 1.0f}, {0.5f, 0.5f, 0.5f, 0.3f}, {3.0f, 0.0f, 1.0f, 0.5f}, {0, 0, 0, 0}};
  const glm::vec4 edgesFragment[] = {{1, 0, 0, 0.0f}, {1, 0, 0, std::nanf("")}, {0.1f, 0.9f, 0.3f, 1.0f}, {0.7f, 0.2f, 0.1f, -2.0f}, {4.0f, 1.0f, 0.0f, 0.25f}};
  for (std::size_t i = 0; i < 5; ++i) held[i] = edgesHeld[i], fragment[i] = edgesFragment[i];
  for (const bool premultiplied : {false, true}) {
    const Blending blending = premultiplied ? Blending::Premultiplied : Blending::Straight;
    const std::string p = premultiplied ? "true" : "false";
    CAPTURE(p);
    for (const bool additive : {false, true}) {
      const std::string add = additive ? "true" : "false";
      CAPTURE(add);
      CHECK(mismatches("blend(a, b.xyz, b.w, " + p + ", " + add + ")", held, fragment, [&](const glm::vec4& a, const glm::vec4& b) {
              return blend(a, glm::vec3(b), b.w, blending, additive);
            }) == 0);
    }
    CHECK(mismatches("vec4(stored(a.xyz, a.w, " + p + ").xyz, unstored(b, " + p + ").x)", held, fragment, [&](const glm::vec4& a, const glm::vec4& b) {
            return glm::vec4(glm::vec3(stored(glm::vec3(a), a.w, blending)), unstored(b, blending).x);
          }) == 0);
    CHECK(mismatches("premultipliedOf(b, " + p + ") + a", held, fragment, [&](const glm::vec4& a, const glm::vec4& b) {
            return a + premultipliedOf(b, blending);  // anti-aliasing's sum (shaders/accumulate.frag)
          }) == 0);
  }
}
