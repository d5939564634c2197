// Renderer::render in the manner of AOVs (tests/render_outputs.h) on the CPU
// rasterizer, its readable reference and the ray tracer; a backend refuses
// an output it does not draw by its stage's name and its own, before it
// draws anything. The OpenGL backend: tests/gl/test_render_outputs.cpp.
#include <memory>
#include <string>

#include <doctest/doctest.h>

#include "common/error.h"
#include "cpu/cpu_renderer.h"
#include "cpu/reference/reference_renderer.h"
#include "ray/ray_renderer.h"
#include "render_outputs.h"
#include "scene/default_scene.h"

using namespace facet;

TEST_CASE("outputs: the CPU rasterizer gives every output asked, and only those") {
  test::checkOutputs(*makeCpuRenderer(2), {FrameOutput::Image, FrameOutput::TriangleIds, FrameOutput::FragmentCounts, FrameOutput::Depth,
                                           FrameOutput::ShadowMaps, FrameOutput::Normals});
}

TEST_CASE("outputs: the readable reference and the ray tracer give the image, triangle ids and fragment counts asked, and only those") {
  const FrameOutputs drawn = {FrameOutput::Image, FrameOutput::TriangleIds, FrameOutput::FragmentCounts};
  test::checkOutputs(*makeReferenceRenderer(), drawn);
  test::checkOutputs(*makeRayRenderer(2), drawn);
}

TEST_CASE("outputs: an output a backend does not draw is refused by its stage's name and the backend's, before anything is drawn") {
  const Scene scene = makeDefaultScene();
  const FrameInputs frame = test::smallFrame(scene);
  int progressed = 0;
  const auto ray = makeRayRenderer(1, [&](double) { ++progressed; });
  const auto reference = makeReferenceRenderer();
  for (Renderer* renderer : {ray.get(), reference.get()}) {
    CAPTURE(renderer->description());
    CHECK_THROWS_WITH_AS(renderer->render(scene, frame, {FrameOutput::Depth}), ("the depth stage is not drawn by " + renderer->description()).c_str(), Error);
    CHECK_THROWS_WITH_AS(renderer->render(scene, frame, {FrameOutput::ShadowMaps}),
                         ("the shadow-map stage is not drawn by " + renderer->description()).c_str(), Error);
    CHECK_THROWS_WITH_AS(renderer->render(scene, frame, {FrameOutput::Image, FrameOutput::Normals}),
                         ("the normals stage is not drawn by " + renderer->description()).c_str(), Error);
  }
  CHECK(progressed == 0);  // the ray tracer refused before it traced the image asked beside the normals
  ray->render(scene, frame);
  CHECK(progressed > 0);  // what the count above would have seen
}
