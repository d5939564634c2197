#pragma once
// The course's ray casting (renderer/PIPELINE.md, "Ray
// casting"): the ray through a pixel, with a window at unit distance, so
// that the ray parameter t is the eye depth z_eye of the point it reaches.
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>

#include "pipeline/frame_inputs.h"
#include "ray/ray.h"

namespace facet::ray {

// The primary ray of pixel (px, py) (bottom row first) at `offset` pixels
// from its centre: perspective, from the eye through
//   P_x = -tanθ + 2(i + 0.5)·tanθ/X_res,  P_y = (tanθ - (j + 0.5)·2tanθ/Y_res)/A_R,  z = 1
// with i = px + dx and j = (H - 1 - py) - dy, turned to world space by EM's
// rotation transposed; parallel, from (x·W/2, y·H/2, 0) in eye space along
// +z. t runs from N to F, the rasterizers' clipping planes.
Ray primaryRay(const FrameInputs& frame, int px, int py, glm::vec2 offset = glm::vec2(0.0f));

// primaryRay with what every ray of the frame shares worked out once: tan θ,
// A_R, EM's rotation transposed (a frame traces millions of rays).
class CameraRays {
 public:
  explicit CameraRays(const FrameInputs& frame);
  Ray at(int px, int py, glm::vec2 offset = glm::vec2(0.0f)) const;

 private:
  glm::dmat3 worldFromEye_;
  glm::dvec3 eye_;
  double width_, height_, tanTheta_, aspect_, boxWidth_, boxHeight_;
  int rows_;
  float near_, far_;
  bool perspective_;
};

// The thin lens (depth of field, `camera.aperture`): the pinhole ray moved
// to the point `disk` (of the unit disk) of a lens of that radius around its
// origin, in the image plane's directions, and turned through the point it
// reached at the eye depth in focus f. Its direction still has eye-space
// z = 1, so t stays the eye depth. The pinhole ray itself where the aperture
// or f is 0.
Ray throughLens(const FrameInputs& frame, const Ray& pinhole, glm::vec2 disk, float focus);

// The ray through the image's centre (between pixels where a side is even),
// which autofocus follows.
Ray centreRay(const FrameInputs& frame);

}  // namespace facet::ray
