// Marschner and Lobb's test signal (1994), the volume renderers' built-in data.
#include <cmath>
#include <numbers>
#include <string>

#include "common/error.h"
#include "scene/memory_budget.h"
#include "settings/render_settings.h"
#include "volume/load_volume.h"

namespace facet {
namespace {

constexpr double kFrequency = 6.0;  // f_M
constexpr double kAlpha = 0.25;     // α

// ρ in double, so that the stored float is the formula's value rounded once.
double density(double x, double y, double z) {
  constexpr double pi = std::numbers::pi;
  const double r = std::sqrt(x * x + y * y);
  const double radial = std::cos(2.0 * pi * kFrequency * std::cos(pi * r / 2.0));
  return (1.0 - std::sin(pi * z / 2.0) + kAlpha * (1.0 + radial)) / (2.0 * (1.0 + kAlpha));
}

}  // namespace

float marschnerLobb(float x, float y, float z) { return static_cast<float>(density(x, y, z)); }

Volume makeMarschnerLobb(int resolution) {
  if (resolution < kMinMarschnerLobbResolution || resolution > kMaxMarschnerLobbResolution)
    throw Error("volume.resolution: " + std::to_string(resolution) + " is out of range [" + std::to_string(kMinMarschnerLobbResolution) +
                ", " + std::to_string(kMaxMarschnerLobbResolution) + "]");
  Volume volume;
  volume.source = "builtin:marschner-lobb";
  volume.size = glm::ivec3(resolution);
  const double step = 2.0 / (resolution - 1);
  volume.spacing = glm::vec3(static_cast<float>(step));
  MemoryBudget budget(kSceneMemoryBudget, "scene budget");
  const std::string n = std::to_string(resolution);
  budget.charge(volume.sampleCount() * sizeof(float), volume.source + ": " + n + "x" + n + "x" + n + " samples");
  volume.values.resize(volume.sampleCount());
  // Coordinates from the index, not by accumulating the step, so that the
  // last sample sits exactly on 1.
  const auto coordinate = [&](int i) { return -1.0 + 2.0 * i / (resolution - 1); };
  for (int k = 0; k < resolution; ++k)
    for (int j = 0; j < resolution; ++j)
      for (int i = 0; i < resolution; ++i)
        volume.values[volume.index(i, j, k)] = static_cast<float>(density(coordinate(i), coordinate(j), coordinate(k)));
  updateRange(volume);
  return volume;
}

}  // namespace facet
