#pragma once
// The course's v-buffer ray casting (renderer/PIPELINE.md, "Volume rendering",
// "Ray casting"): rays through the volume, a sample every `step` voxel
// spacings, each the trilinear interpolation of the 8 samples around it,
// through the transfer function, composited front to back with the opacity
// corrected for the step; early ray termination and empty-space skipping.
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "scene/transfer_function.h"
#include "scene/volume.h"

namespace facet {

inline constexpr int kMacroCellSide = 8;  // empty-space skipping's macro cells: 8 sample spacings a side

struct RayCastOptions {
  float step = 0.5f;              // Δ in voxel spacings (the smallest spacing)
  float earlyTermination = 0.99f; // stop once A ≥ this (1: never)
  bool emptySpaceSkipping = true;
};

struct RayCastCounts {
  std::uint64_t samples = 0;            // samples taken
  std::uint64_t skippedEmpty = 0;       // samples empty-space skipping stepped over
  std::uint64_t savedByTermination = 0; // samples left on rays early termination stopped
  RayCastCounts& operator+=(const RayCastCounts& o) {
    samples += o.samples, skippedEmpty += o.skippedEmpty, savedByTermination += o.savedByTermination;
    return *this;
  }
};

// A volume ready to be ray cast with one transfer function: the macro cells
// it makes transparent (every value between a cell's least and largest
// sample maps to opacity 0).
class RayCastVolume {
 public:
  RayCastVolume(const Volume& volume, const TransferFunction& transfer, RayCastOptions options);

  // Premultiplied colour C and opacity A along the segment from `from` to
  // `to` (model space of the volume), samples at t_k = t0 + (k + ½)·Δ of the
  // segment's part inside the box [t0, t1] (Δ in model units):
  //   α_k = 1 − (1 − α(v_k))^step   (the opacity corrected for the step),
  //   C += (1 − A)·α_k·c(v_k),  A += (1 − A)·α_k.
  glm::vec4 cast(glm::vec3 from, glm::vec3 to, RayCastCounts& counts) const;

 private:
  bool transparentCell(glm::ivec3 cell) const;

  const Volume& volume_;
  const TransferFunction& transfer_;
  RayCastOptions options_;
  float delta_ = 0;                   // Δ, model units
  glm::ivec3 cells_{0};
  std::vector<std::uint8_t> empty_;   // per macro cell, x fastest: 1 where transparent
};

// The largest opacity the transfer function gives a value in [lo, hi]:
// piecewise linear, so at an end or at a control point between.
float largestOpacity(const TransferFunction& transfer, float lo, float hi);

}  // namespace facet
