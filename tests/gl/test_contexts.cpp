// Headless contexts and the errors a frame can end with: limits of the
// driver, incomplete framebuffers. (A missing library or a context the
// driver refuses is tested through the command line, tests/gl/CMakeLists.txt.)
#include <string>

#include <doctest/doctest.h>

#include "common/error.h"
#include "gl/gl_object.h"
#include "gl/render_target.h"
#include "gl_test_support.h"
#include "scene/default_scene.h"

using namespace facet;

TEST_CASE("both headless contexts give OpenGL 4.5 core on llvmpipe, and a renderer names it") {
  for (GlContextKind kind : {GlContextKind::OsMesa, GlContextKind::Egl}) {
    const std::unique_ptr<gl::HeadlessContext> context = gl::makeHeadlessContext(kind);
    const gl::GlFunctions gl = gl::loadGlFunctions([&](const char* name) { return context->getProcAddress(name); });
    CHECK(gl::getInteger(gl, GL_MAJOR_VERSION) * 10 + gl::getInteger(gl, GL_MINOR_VERSION) >= 45);
    CHECK((gl::getInteger(gl, GL_CONTEXT_PROFILE_MASK) & GL_CONTEXT_CORE_PROFILE_BIT) != 0);
    CHECK(gl::rendererAndVersion(gl).find("4.5 (Core Profile)") != std::string::npos);
  }
  const std::string description = makeGlRenderer(GlContextKind::Egl)->description();
  CHECK(description.find("gl: ") == 0);
  CHECK(description.find(" via egl") == description.size() - 8);
}

TEST_CASE("an image beyond the frame's limit: facet::Error from the shared frame check, before anything is drawn") {
  const Scene scene = makeDefaultScene();
  FrameInputs frame = buildFrameInputs(scene, test::smallSettings());
  frame.width = 40000;  // beyond kMaxImageSide, and beyond what --size accepts
  CHECK_THROWS_WITH_AS(makeGlRenderer(GlContextKind::OsMesa)->render(scene, frame),
                       doctest::Contains("image size 40000x120: each side must be in [1, 16384]"), Error);
  frame.width = 160;
  frame.shadows.mapSize = 32768;
  CHECK_THROWS_WITH_AS(makeGlRenderer(GlContextKind::OsMesa)->render(scene, frame),
                       doctest::Contains("settings key 'shadows.mapSize': 32768 is not in [1, 8192]"), Error);
}

TEST_CASE("a target larger than the driver's renderbuffers or textures: facet::Error naming the driver's limit") {
  // A driver below facet's own limits (a GPU with 8192) refuses what the frame check lets through; llvmpipe's
  // limits are facet's, so the targets are asked for directly.
  test::GlHarness harness;
  gl::RenderTarget target(GL_RGBA32F);
  CHECK_THROWS_WITH_AS(target.resize(harness.gl, 40000, 120),
                       doctest::Contains("image size 40000x120: larger than this OpenGL allows (GL_MAX_TEXTURE_SIZE 16384)"), Error);
  gl::ShadowMapArray maps;
  CHECK_THROWS_WITH_AS(maps.resize(harness.gl, 32768, 1),
                       doctest::Contains("settings key 'shadows.mapSize': 32768: larger than this OpenGL allows (GL_MAX_TEXTURE_SIZE"), Error);
}

TEST_CASE("an incomplete framebuffer: facet::Error naming it and its status") {
  test::GlHarness harness;
  const gl::GlObject framebuffer = gl::createFramebuffer(harness.gl);  // no attachment at all
  CHECK_THROWS_WITH_AS(gl::checkFramebufferComplete(harness.gl, framebuffer.id(), "test"),
                       "OpenGL: the test framebuffer is incomplete (GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT)", Error);
}

TEST_CASE("a frame that draws a mesh the uploaded scene lacks: facet::Error, not a crash") {
  const Scene scene = makeDefaultScene();
  FrameInputs frame = buildFrameInputs(scene, test::smallSettings());
  frame.instances[0].mesh = 99;
  CHECK_THROWS_WITH_AS(makeGlRenderer(GlContextKind::OsMesa)->render(scene, frame), doctest::Contains("mesh 99"), Error);
}
