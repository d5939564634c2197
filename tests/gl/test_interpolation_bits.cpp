// Depth and attribute interpolation (renderer/PIPELINE.md, "Rasterization") and
// the derivatives textures take their level of detail from (PIPELINE.md, "Textures"): the
// CPU's plane equations (renderer/cpu/plane_equations.h) and quad
// differences (cpu::Interpolation::quadDerivatives) against what llvmpipe
// writes, bit for bit, on random triangles.
#include <cmath>
#include <cstring>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "cpu/clipper.h"
#include "cpu/interpolation.h"
#include "cpu/plane_equations.h"
#include "cpu/rasterize.h"
#include "cpu/triangle_setup.h"
#include "gl/gl_object.h"
#include "gl/shader_program.h"
#include "gl_test_support.h"

using namespace facet;

namespace {

constexpr int kWidth = 61, kHeight = 47;
constexpr float kUnwritten = -12345.0f;

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("llvmpipe's depth, perspective-correct attributes and dFdx/dFdy equal the CPU's plane equations and quad differences bit for bit") {
  test::GlHarness harness;
  const gl::GlFunctions& gl = harness.gl;
  const std::string vert = "#version 450 core\nlayout(location = 0) in vec4 clipPosition;\nlayout(location = 1) in vec4 vertexValue;\n"
                           "out vec4 value;\nvoid main() { gl_Position = clipPosition; value = vertexValue; }\n";
  const std::string frag =
      "#version 450 core\nin vec4 value;\nlayout(location = 0) out vec4 color;\nlayout(location = 1) out vec4 derivatives;\n"
      "void main() { color = value; derivatives = vec4(dFdx(value.xy), dFdy(value.xy)); }\n";
  const gl::ShaderProgram program = gl::buildProgram(gl, {"probe.vert", "probe.frag"}, "", [&](std::string_view name) {
    if (name == "probe.vert") return std::optional<std::string_view>(vert);
    if (name == "probe.frag") return std::optional<std::string_view>(frag);
    return gl::findEmbeddedShaderFile(name);
  });

  const gl::GlObject color = gl::createRenderbuffer(gl);
  gl.NamedRenderbufferStorage(color.id(), GL_RGBA32F, kWidth, kHeight);
  const gl::GlObject derivative = gl::createRenderbuffer(gl);
  gl.NamedRenderbufferStorage(derivative.id(), GL_RGBA32F, kWidth, kHeight);
  const gl::GlObject depth = gl::createRenderbuffer(gl);
  gl.NamedRenderbufferStorage(depth.id(), GL_DEPTH_COMPONENT32F, kWidth, kHeight);
  const gl::GlObject framebuffer = gl::createFramebuffer(gl);
  gl.NamedFramebufferRenderbuffer(framebuffer.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color.id());
  gl.NamedFramebufferRenderbuffer(framebuffer.id(), GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER, derivative.id());
  gl.NamedFramebufferRenderbuffer(framebuffer.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth.id());
  const GLenum drawBuffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  gl.NamedFramebufferDrawBuffers(framebuffer.id(), 2, drawBuffers);
  const gl::GlObject buffer = gl::createBuffer(gl);
  gl.NamedBufferStorage(buffer.id(), 3 * 8 * sizeof(float), nullptr, GL_DYNAMIC_STORAGE_BIT);
  const gl::GlObject vertexArray = gl::createVertexArray(gl);
  gl.VertexArrayVertexBuffer(vertexArray.id(), 0, buffer.id(), 0, 8 * sizeof(float));
  for (GLuint a = 0; a < 2; ++a) {
    gl.EnableVertexArrayAttrib(vertexArray.id(), a);
    gl.VertexArrayAttribFormat(vertexArray.id(), a, 4, GL_FLOAT, GL_FALSE, a * 4 * sizeof(float));
    gl.VertexArrayAttribBinding(vertexArray.id(), a, 0);
  }
  gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
  gl.Viewport(0, 0, kWidth, kHeight);
  gl.ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  gl.Disable(GL_CULL_FACE);
  gl.UseProgram(program.id());
  gl.BindVertexArray(vertexArray.id());

  std::mt19937 random(174);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f), wRange(0.3f, 4.0f), values(-100.0f, 100.0f);
  std::vector<float> colors(4 * kWidth * kHeight), derivatives(4 * kWidth * kHeight), depths(kWidth * kHeight);
  long pixels = 0, depthMismatches = 0, attributeMismatches = 0, derivativeMismatches = 0, coverageMismatches = 0;
  std::string firstMismatch;
  const float halfWidth = 0.5f * kWidth, halfHeight = 0.5f * kHeight;
  for (int t = 0; t < 600; ++t) {
    float vertices[3][8];
    for (auto& v : vertices) {
      const float w = wRange(random);
      // A quarter of the triangles reach outside the view volume and are clipped.
      const float reach = t % 4 == 3 ? 2.0f : 1.0f;
      v[0] = reach * unit(random) * w, v[1] = reach * unit(random) * w, v[2] = 0.5f * (reach * unit(random) + 1.0f) * w, v[3] = w;
      for (int k = 4; k < 8; ++k) v[k] = values(random);
    }
    gl.NamedBufferSubData(buffer.id(), 0, sizeof vertices, vertices);
    const float clear[4] = {kUnwritten, kUnwritten, kUnwritten, kUnwritten};
    gl.ClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, clear);
    const float one = 1.0f;
    gl.ClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &one);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
    gl.NamedFramebufferReadBuffer(framebuffer.id(), GL_COLOR_ATTACHMENT0);
    gl.ReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_FLOAT, colors.data());
    gl.NamedFramebufferReadBuffer(framebuffer.id(), GL_COLOR_ATTACHMENT1);
    gl.ReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_FLOAT, derivatives.data());
    gl.ReadPixels(0, 0, kWidth, kHeight, GL_DEPTH_COMPONENT, GL_FLOAT, depths.data());
    REQUIRE(gl.GetError() == GL_NO_ERROR);

    // The CPU's window vertices (clipped where a vertex is outside), coverage and planes.
    cpu::ClipVertex clip[3];
    cpu::WindowVertex window[3];
    for (int i = 0; i < 3; ++i) {
      clip[i].clip = {vertices[i][0], vertices[i][1], vertices[i][2], vertices[i][3]};
      for (int k = 0; k < 4; ++k) clip[i].varyings[static_cast<std::size_t>(k)] = vertices[i][4 + k];
      window[i] = cpu::toWindow(clip[i], halfWidth, halfHeight, 4);
    }
    std::vector<cpu::WindowVertex> fan;
    cpu::clipTriangle(clip[0], clip[1], clip[2], window[0], window[1], window[2], halfWidth, halfHeight, 4, fan);
    // Per pixel: the planes of the fan triangle that covers it (one at most: a fan covers each pixel once).
    struct Planes {
      cpu::Plane z, oneOverW, attribute[4];
      cpu::Interpolation interpolation;  // the renderer's own, for the derivatives
    };
    std::vector<Planes> fanPlanes;
    std::vector<int> coveredBy(kWidth * kHeight, -1);
    for (std::size_t f = 0; f + 2 < fan.size(); f += 3) {
      cpu::SnappedTriangle snapped;
      cpu::PixelBox box;
      if (!cpu::snapTriangle({fan[f].x, fan[f + 1].x, fan[f + 2].x}, {fan[f].y, fan[f + 1].y, fan[f + 2].y}, snapped) ||
          !cpu::pixelBox(snapped, 0, 0, kWidth - 1, kHeight - 1, box))
        continue;
      const cpu::WindowVertex* v[3] = {&fan[f], &fan[f + 1], &fan[f + 2]};
      cpu::toSetUpOrder(snapped, v);
      const cpu::WindowVertex &a = *v[0], &b = *v[1], &c = *v[2];
      const cpu::PlaneSetup s = cpu::setUpPlanes(a.x, a.y, b.x, b.y, c.x, c.y);
      Planes p;
      p.z = cpu::planeOf(s, a.z, b.z, c.z);
      p.oneOverW = cpu::planeOf(s, a.invW, b.invW, c.invW);
      for (std::size_t k = 0; k < 4; ++k)
        p.attribute[k] = cpu::planeOf(s, a.varyings[k] * a.invW, b.varyings[k] * b.invW, c.varyings[k] * c.invW);
      const cpu::InterpolationVertex corners[3] = {{a.x, a.y, a.z, a.invW, a.varyings.data()},
                                                   {b.x, b.y, b.z, b.invW, b.varyings.data()},
                                                   {c.x, c.y, c.z, c.invW, c.varyings.data()}};
      p.interpolation = cpu::Interpolation(corners[0], corners[1], corners[2]);
      p.interpolation.setUpVaryings(4);
      const int index = static_cast<int>(fanPlanes.size());
      fanPlanes.push_back(p);
      cpu::rasterize(snapped, box, [&](int px, int py) { coveredBy[static_cast<std::size_t>(py * kWidth + px)] = index; });
    }

    for (int py = 0; py < kHeight; ++py)
      for (int px = 0; px < kWidth; ++px) {
        const std::size_t i = static_cast<std::size_t>(py * kWidth + px);
        const bool written = colors[4 * i] != kUnwritten;
        const Planes* p = coveredBy[i] >= 0 ? &fanPlanes[static_cast<std::size_t>(coveredBy[i])] : nullptr;
        const float expectedDepth = p ? cpu::depthAt(p->z, px, py) : 1.0f;
        const bool expectWritten = p && expectedDepth < 1.0f;
        if (written != expectWritten) {
          ++coverageMismatches;
          continue;
        }
        if (!written) continue;
        ++pixels;
        if (!sameBits(depths[i], expectedDepth)) {
          if (firstMismatch.empty())
            firstMismatch = "triangle " + std::to_string(t) + " pixel " + std::to_string(px) + "," + std::to_string(py) + ": depth " +
                            std::to_string(depths[i]) + " vs " + std::to_string(expectedDepth);
          ++depthMismatches;
        }
        const float w = 1.0f / p->oneOverW.at(px, py);
        for (int k = 0; k < 4; ++k) {
          const float expected = p->attribute[k].at(px, py) * w;
          if (!sameBits(colors[4 * i + static_cast<std::size_t>(k)], expected)) {
            if (firstMismatch.empty())
              firstMismatch = "triangle " + std::to_string(t) + " pixel " + std::to_string(px) + "," + std::to_string(py) + ": attribute " +
                              std::to_string(colors[4 * i + static_cast<std::size_t>(k)]) + " vs " + std::to_string(expected);
            ++attributeMismatches;
          }
        }
        const glm::vec4 expectedDerivatives = p->interpolation.quadDerivatives(0, px, py);
        for (int k = 0; k < 4; ++k)
          if (!sameBits(derivatives[4 * i + static_cast<std::size_t>(k)], expectedDerivatives[k])) {
            if (firstMismatch.empty())
              firstMismatch = "triangle " + std::to_string(t) + " pixel " + std::to_string(px) + "," + std::to_string(py) + ": derivative " +
                              std::to_string(derivatives[4 * i + static_cast<std::size_t>(k)]) + " vs " + std::to_string(expectedDerivatives[k]);
            ++derivativeMismatches;
          }
      }
  }
  CAPTURE(firstMismatch);
  MESSAGE(pixels << " pixels: " << depthMismatches << " depth, " << attributeMismatches << " attribute and " << derivativeMismatches
                 << " derivative mismatches");
  CHECK(pixels > 100000);
  CHECK(coverageMismatches == 0);
  CHECK(depthMismatches == 0);
  CHECK(attributeMismatches == 0);
  CHECK(derivativeMismatches == 0);
}
