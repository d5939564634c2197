// v-buffer ray casting against integrals computed here.
#include <cmath>

#include <doctest/doctest.h>

#include "volume/load_volume.h"
#include "volume/volume_raycast.h"

namespace facet {
namespace {

Volume constantVolume(int n, float value) {
  Volume v;
  v.size = glm::ivec3(n);
  v.spacing = glm::vec3(1.0f);
  v.values.assign(v.sampleCount(), value);
  updateRange(v);
  return v;
}

TransferFunction flat(glm::vec3 color, float opacity) { return {{{0.0f, color, opacity}, {1.0f, color, opacity}}}; }

}  // namespace

TEST_CASE("volume ray casting: a constant medium's opacity is 1 - (1 - alpha)^(L / spacing) for every step") {
  // Along x through a 33-sample box (extent 32): the continuous answer for a
  // medium of opacity α per voxel spacing over L = 32 spacings. The samples
  // cover n·Δ of L, n = the whole steps in it, so A = 1 − (1 − α)^(n·step).
  const Volume volume = constantVolume(33, 0.5f);
  const TransferFunction transfer = flat(glm::vec3(1.0f, 0.5f, 0.25f), 0.05f);
  for (const float step : {1.0f, 0.5f, 0.25f, 0.1f}) {
    CAPTURE(step);
    const RayCastVolume cast(volume, transfer, {step, 1.0f, false});
    RayCastCounts counts;
    const glm::vec4 result = cast.cast({-5.0f, 16.0f, 16.0f}, {40.0f, 16.0f, 16.0f}, counts);
    const double expected = 1.0 - std::pow(1.0 - 0.05, 32.0);
    CHECK(counts.samples == static_cast<std::uint64_t>(std::lround(32.0f / step)));
    CHECK(result.a == doctest::Approx(expected).epsilon(2e-4));
    // Premultiplied colour: every sample has colour c, so C = c·A.
    CHECK(result.r == doctest::Approx(result.a).epsilon(1e-5));
    CHECK(result.b == doctest::Approx(0.25 * result.a).epsilon(1e-5));
  }
}

TEST_CASE("volume ray casting: front-to-back compositing of a ramp matches the emission-absorption integral") {
  // Values rise along x from 0 to 1; the transfer function maps v to colour
  // (v, 0, 0) and opacity 0.1 per spacing. The integral along the ray,
  // computed here by fine quadrature: C = ∫ c(x)·σ·T(x) dx with T = (1 − α)^x,
  // σ = −ln(1 − α) per spacing. Step 0.1 is a Riemann sum of it; its error is
  // O(Δ) of the integrand's variation, under 1% here.
  Volume volume;
  volume.size = glm::ivec3(17, 5, 5);
  volume.values.resize(volume.sampleCount());
  for (int z = 0; z < 5; ++z)
    for (int y = 0; y < 5; ++y)
      for (int x = 0; x < 17; ++x) volume.values[volume.index(x, y, z)] = static_cast<float>(x) / 16.0f;
  updateRange(volume);
  const TransferFunction transfer{{{0.0f, glm::vec3(0.0f), 0.1f}, {1.0f, glm::vec3(1.0f, 0.0f, 0.0f), 0.1f}}};
  const RayCastVolume cast(volume, transfer, {0.1f, 1.0f, false});
  RayCastCounts counts;
  const glm::vec4 result = cast.cast({-1.0f, 2.0f, 2.0f}, {20.0f, 2.0f, 2.0f}, counts);
  const double sigma = -std::log(1.0 - 0.1);
  double integral = 0.0;
  const int n = 160000;
  for (int i = 0; i < n; ++i) {
    const double x = (i + 0.5) * 16.0 / n;
    integral += (x / 16.0) * sigma * std::exp(-sigma * x) * (16.0 / n);
  }
  CHECK(result.r == doctest::Approx(integral).epsilon(0.01));
  CHECK(result.a == doctest::Approx(1.0 - std::exp(-sigma * 16.0)).epsilon(1e-3));
}

TEST_CASE("volume ray casting: empty-space skipping changes no result and early termination stops rays") {
  const Volume volume = makeMarschnerLobb(48);
  // Transparent below 0.6: the skipping has cells to skip.
  const TransferFunction transfer{{{0.0f, glm::vec3(0.0f), 0.0f}, {0.6f, glm::vec3(0.0f), 0.0f}, {1.0f, glm::vec3(1.0f, 0.8f, 0.6f), 0.4f}}};
  const RayCastVolume plain(volume, transfer, {0.5f, 1.0f, false});
  const RayCastVolume skipping(volume, transfer, {0.5f, 1.0f, true});
  const RayCastVolume stopping(volume, transfer, {0.5f, 0.9f, false});
  RayCastCounts a, b, c;
  int differing = 0, stoppedDiffers = 0;
  const glm::vec3 extent = volume.extent();
  for (int j = 0; j < 40; ++j)
    for (int i = 0; i < 40; ++i) {
      const glm::vec3 from(-0.3f * extent.x, (static_cast<float>(i) + 0.5f) / 40.0f * extent.y, (static_cast<float>(j) + 0.5f) / 40.0f * extent.z);
      const glm::vec3 to(1.3f * extent.x, extent.y - from.y, from.z * 0.7f);
      const glm::vec4 p = plain.cast(from, to, a), s = skipping.cast(from, to, b), e = stopping.cast(from, to, c);
      differing += p != s;
      // Stopped at A ≥ 0.9: the rest could add at most (1 − A) of the light.
      stoppedDiffers += std::abs(p.a - e.a) > 0.1f + 1e-6f;
    }
  CHECK(differing == 0);
  CHECK(b.skippedEmpty > 0);
  CHECK(b.samples + b.skippedEmpty == a.samples);
  CHECK(c.savedByTermination > 0);
  CHECK(c.samples + c.savedByTermination == a.samples);
  CHECK(stoppedDiffers == 0);
}

}  // namespace facet
