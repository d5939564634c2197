#pragma once
// Shared by the OpenGL backend's tests: headless renders of a scene, the PNG
// every render leaves in the build folder, world points to pixels, and a
// current context with its function table for tests that call GL directly.
#include <memory>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "gl/gl_functions.h"
#include "gl/gl_renderer.h"
#include "gl/headless_context.h"
#include "image/image.h"
#include "pipeline/frame_inputs.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "settings/render_settings.h"

namespace facet::test {

// 160x120 keeps llvmpipe fast; a 512² shadow map still resolves the default scene's shadows.
RenderSettings smallSettings(ShadingMode shading = ShadingMode::Phong, bool shadows = true, bool cullBackFaces = true);

// Renders with a fresh renderer of `kind` and writes images/<name>.png.
Image renderHeadless(const std::string& name, const Scene& scene, const FrameInputs& frame, GlContextKind kind = GlContextKind::OsMesa);

// Writes images/<name>.png in the test build folder.
void writeTestImage(const std::string& name, const Image& image);

// The pixel (x, y from the bottom row) whose centre is nearest to where `world` projects.
glm::ivec2 pixelOf(const FrameInputs& frame, glm::vec3 world);
// Window coordinates of `world`, in pixels (x right, y up).
glm::vec2 windowOf(const FrameInputs& frame, glm::vec3 world);

// Rec. 709 luma of an 8-bit pixel, for "brighter than" checks.
double luma(Rgba8 pixel);

// An 8-bit sRGB-encoded channel of a linear value, by the contract's formula in double precision.
int encodedByte(double linear);
Rgba8 encodedPixel(glm::vec3 linear);

// "(r, g, b, a)" for failure messages.
std::string describe(Rgba8 pixel);

// A world-space sphere around one mesh instance's vertices.
struct BoundingSphere {
  glm::vec3 center{0.0f};
  float radius = 0.0f;
};
BoundingSphere boundingSphere(const Scene& scene, const FrameInputs& frame, std::size_t instance);

// The instance whose material is named `material` (the default scene names each object's material).
std::size_t instanceWithMaterial(const Scene& scene, const FrameInputs& frame, const std::string& material);

// A current OSMesa context and its function table, for tests that talk to OpenGL directly.
// GL objects a test makes must go before it does: declare them after it.
struct GlHarness {
  std::unique_ptr<gl::HeadlessContext> context = gl::makeHeadlessContext(GlContextKind::OsMesa);
  gl::GlFunctions gl = gl::loadGlFunctions([this](const char* name) { return context->getProcAddress(name); });
};

}  // namespace facet::test
