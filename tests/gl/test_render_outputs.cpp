// Renderer::render in the manner of AOVs (tests/render_outputs.h) on the
// OpenGL backend: every output asked, and only those; the scene upload timed
// with the image it is drawn for.
#include <memory>

#include <doctest/doctest.h>

#include "gl/gl_renderer.h"
#include "../render_outputs.h"
#include "scene/default_scene.h"

using namespace facet;

TEST_CASE("outputs: the OpenGL backend gives every output asked, and only those") {
  const std::unique_ptr<Renderer> gl = makeGlRenderer(GlContextKind::OsMesa);
  test::checkOutputs(*gl, {FrameOutput::Image, FrameOutput::TriangleIds, FrameOutput::FragmentCounts, FrameOutput::Depth, FrameOutput::ShadowMaps,
                           FrameOutput::Normals});
  // A scene first uploaded for another output: the image's timings do not count that upload.
  const Scene scene = makeDefaultScene();
  const FrameInputs frame = test::smallFrame(scene);
  const RenderResult ids = gl->render(scene, frame, {FrameOutput::TriangleIds});
  CHECK(ids.timings.empty());
  for (const PassTiming& t : gl->render(scene, frame).timings) CHECK(t.pass != kSceneUploadPass);
}
