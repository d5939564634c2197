#include "pipeline/split_sum.h"

#include <cmath>
#include <cstdint>
#include <numbers>

#include "pipeline/microfacet.h"

namespace facet {
namespace {

constexpr int kSamples = 1024;

// The van der Corput radical inverse of i in base 2: the second coordinate of Hammersley's points.
double radicalInverse(std::uint32_t i) {
  i = (i << 16) | (i >> 16);
  i = ((i & 0x55555555u) << 1) | ((i & 0xAAAAAAAAu) >> 1);
  i = ((i & 0x33333333u) << 2) | ((i & 0xCCCCCCCCu) >> 2);
  i = ((i & 0x0F0F0F0Fu) << 4) | ((i & 0xF0F0F0F0u) >> 4);
  i = ((i & 0x00FF00FFu) << 8) | ((i & 0xFF00FF00u) >> 8);
  return static_cast<double>(i) * (1.0 / 4294967296.0);
}

// (A, B) for one roughness and N·V: H drawn with density D·(N·H), so L = 2(V·H)H - V has
// density D·(N·H)/(4·V·H) and each sample weighs Vis·(N·L)·4·(V·H)/(N·H).
glm::vec2 integrate(double roughness, double NdotV) {
  const double r2 = roughness * roughness, alpha = r2 > kMinAlpha ? r2 : double(kMinAlpha), alpha2 = alpha * alpha;
  const double vx = std::sqrt(1.0 - NdotV * NdotV), vz = NdotV;  // V in the x-z plane, N = +z
  double A = 0.0, B = 0.0;
  for (int s = 0; s < kSamples; ++s) {
    const double u = (s + 0.5) / kSamples, w = radicalInverse(static_cast<std::uint32_t>(s));
    const double phi = 2.0 * std::numbers::pi * u;
    const double cosTheta = std::sqrt((1.0 - w) / (1.0 + (alpha2 - 1.0) * w)), sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
    const double hx = sinTheta * std::cos(phi), hz = cosTheta;
    const double VdotH = vx * hx + vz * hz;
    const double NdotL = 2.0 * VdotH * hz - vz;
    if (!(NdotL > 0.0) || !(VdotH > 0.0)) continue;
    const double weight = smithVisibility(NdotL, NdotV, alpha2) * NdotL * 4.0 * VdotH / hz;
    const double x5 = schlickWeight(VdotH);
    A += (1.0 - x5) * weight;
    B += x5 * weight;
  }
  return {static_cast<float>(A / kSamples), static_cast<float>(B / kSamples)};
}

SplitSumTable build() {
  SplitSumTable t{};
  for (int row = 0; row < kSplitSumSize; ++row)
    for (int column = 0; column < kSplitSumSize; ++column)
      t.ab[static_cast<std::size_t>(row * kSplitSumSize + column)] = integrate(static_cast<double>(row) / (kSplitSumSize - 1), static_cast<double>(column) / (kSplitSumSize - 1));
  return t;
}

}  // namespace

const SplitSumTable& splitSumTable() {
  static const SplitSumTable table = build();
  return table;
}

}  // namespace facet
