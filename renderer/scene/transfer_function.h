#pragma once
// The transfer function of volume rendering: a sample's scalar to colour
// and opacity, piecewise linear between control points
// (renderer/PIPELINE.md, "Transfer functions").
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace facet {

struct TransferPoint {
  float value = 0.0f;        // the scalar, in the data's units
  glm::vec3 color{1.0f};     // linear RGB
  float opacity = 0.0f;      // α per reference step (one voxel spacing), [0, 1]
};

struct TransferFunction {
  std::vector<TransferPoint> points;  // by increasing value, at least one

  // Colour and opacity at `value`: linear between the two points around it,
  // the first point's below the first, the last's above the last.
  glm::vec4 operator()(float value) const;
};

// `text` is a preset name, or control points "value r g b a" separated by
// commas, values increasing ("0 0 0 0 0, 80 1 0.8 0.6 0.05, 255 1 1 1 0.9").
// A preset spans the data range [minValue, maxValue]. Throws facet::Error
// naming volume.transfer and the point at fault (unordered values, a
// number missing, a colour or opacity outside [0, 1]).
TransferFunction parseTransferFunction(std::string_view text, float minValue, float maxValue);
std::vector<std::string_view> transferPresetNames();

}  // namespace facet
