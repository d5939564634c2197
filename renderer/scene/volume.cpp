// Sampling a scalar volume: trilinear interpolation, gradients, value range.
#include "scene/volume.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string_view>

namespace facet {
namespace {

// File name extensions compare without case.
bool endsWith(std::string_view path, std::string_view suffix) {
  if (path.size() < suffix.size()) return false;
  return std::equal(suffix.begin(), suffix.end(), path.end() - static_cast<std::ptrdiff_t>(suffix.size()), [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
  });
}

// The course's lerp, a + t·(b − a): one rounding per operation (facet_fp keeps
// the compiler from fusing it), so that backends can repeat it bit for bit.
float lerp(float a, float b, float t) { return a + t * (b - a); }

// Grid coordinate along one axis clamped to [0, samples − 1] (NaN to 0), and
// split into the lower sample's index and the fraction towards the next one.
// On the far face both neighbours are the last sample with t = 0, so that
// the value there is the sample itself (a + 1·(b − a) need not be b).
struct AxisStep {
  int lower = 0, upper = 0;
  float t = 0.0f;
};

AxisStep axisStep(float coordinate, int samples) {
  const float last = static_cast<float>(samples - 1);
  float g = coordinate;
  if (!(g >= 0.0f)) g = 0.0f;
  if (g > last) g = last;
  AxisStep step;
  step.lower = std::min(static_cast<int>(std::floor(g)), samples - 1);
  step.upper = std::min(step.lower + 1, samples - 1);
  step.t = g - static_cast<float>(step.lower);
  return step;
}

// One axis of sampleGradient: central difference inside, one-sided at the
// border, divided by the distance between the two samples used.
float difference(const Volume& v, int x, int y, int z, int axis) {
  glm::ivec3 lo(x, y, z), hi(x, y, z);
  const int n = v.size[axis];
  if (n < 2) return 0.0f;
  lo[axis] = std::max(lo[axis] - 1, 0);
  hi[axis] = std::min(hi[axis] + 1, n - 1);
  const float distance = static_cast<float>(hi[axis] - lo[axis]) * v.spacing[axis];
  return (v.at(hi.x, hi.y, hi.z) - v.at(lo.x, lo.y, lo.z)) / distance;
}

}  // namespace

VolumeFormat volumeFormatOf(const std::string& path) {
  if (path == "builtin:marschner-lobb") return VolumeFormat::MarschnerLobb;
  if (endsWith(path, ".nrrd") || endsWith(path, ".nhdr")) return VolumeFormat::Nrrd;
  if (endsWith(path, ".nii") || endsWith(path, ".nii.gz")) return VolumeFormat::Nifti;
  return VolumeFormat::None;
}

float trilinear(const Volume& volume, glm::vec3 p) {
  if (volume.empty()) return 0.0f;
  const AxisStep x = axisStep(p.x / volume.spacing.x, volume.size.x);
  const AxisStep y = axisStep(p.y / volume.spacing.y, volume.size.y);
  const AxisStep z = axisStep(p.z / volume.spacing.z, volume.size.z);
  // Along x on the four edges of the cell, then y, then z.
  const float c00 = lerp(volume.at(x.lower, y.lower, z.lower), volume.at(x.upper, y.lower, z.lower), x.t);
  const float c10 = lerp(volume.at(x.lower, y.upper, z.lower), volume.at(x.upper, y.upper, z.lower), x.t);
  const float c01 = lerp(volume.at(x.lower, y.lower, z.upper), volume.at(x.upper, y.lower, z.upper), x.t);
  const float c11 = lerp(volume.at(x.lower, y.upper, z.upper), volume.at(x.upper, y.upper, z.upper), x.t);
  const float c0 = lerp(c00, c10, y.t);
  const float c1 = lerp(c01, c11, y.t);
  return lerp(c0, c1, z.t);
}

glm::vec3 sampleGradient(const Volume& volume, int x, int y, int z) {
  if (volume.empty()) return glm::vec3(0.0f);
  x = std::clamp(x, 0, volume.size.x - 1);
  y = std::clamp(y, 0, volume.size.y - 1);
  z = std::clamp(z, 0, volume.size.z - 1);
  return {difference(volume, x, y, z, 0), difference(volume, x, y, z, 1), difference(volume, x, y, z, 2)};
}

void updateRange(Volume& volume) {
  bool any = false;
  float lo = 0.0f, hi = 0.0f;
  for (const float v : volume.values) {
    if (!std::isfinite(v)) continue;
    if (!any) {
      lo = hi = v;
      any = true;
    } else {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  volume.minValue = lo;
  volume.maxValue = hi;
}

}  // namespace facet
