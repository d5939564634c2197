// v-buffer ray casting of a volume, front to back.
#include "volume/volume_raycast.h"

#include <algorithm>
#include <cmath>

namespace facet {

float largestOpacity(const TransferFunction& transfer, float lo, float hi) {
  float most = std::max(transfer(lo).a, transfer(hi).a);
  for (const TransferPoint& p : transfer.points)
    if (p.value > lo && p.value < hi) most = std::max(most, p.opacity);
  return most;
}

RayCastVolume::RayCastVolume(const Volume& volume, const TransferFunction& transfer, RayCastOptions options)
    : volume_(volume), transfer_(transfer), options_(options) {
  delta_ = options.step * std::min({volume.spacing.x, volume.spacing.y, volume.spacing.z});
  if (!options.emptySpaceSkipping) return;
  // A cell spans samples [8i, 8i + 8] on each axis: every sample a trilinear lookup inside it reads.
  cells_ = (volume.size - 2) / kMacroCellSide + 1;
  empty_.assign(static_cast<std::size_t>(cells_.x) * static_cast<std::size_t>(cells_.y) * static_cast<std::size_t>(cells_.z), 0);
  for (int cz = 0; cz < cells_.z; ++cz)
    for (int cy = 0; cy < cells_.y; ++cy)
      for (int cx = 0; cx < cells_.x; ++cx) {
        float lo = INFINITY, hi = -INFINITY;
        bool finite = true;
        for (int z = cz * kMacroCellSide; z <= std::min((cz + 1) * kMacroCellSide, volume.size.z - 1); ++z)
          for (int y = cy * kMacroCellSide; y <= std::min((cy + 1) * kMacroCellSide, volume.size.y - 1); ++y)
            for (int x = cx * kMacroCellSide; x <= std::min((cx + 1) * kMacroCellSide, volume.size.x - 1); ++x) {
              const float v = volume.at(x, y, z);
              finite = finite && std::isfinite(v);
              lo = std::min(lo, v), hi = std::max(hi, v);
            }
        empty_[(static_cast<std::size_t>(cz) * static_cast<std::size_t>(cells_.y) + static_cast<std::size_t>(cy)) * static_cast<std::size_t>(cells_.x) +
               static_cast<std::size_t>(cx)] = finite && !(largestOpacity(transfer, lo, hi) > 0.0f) ? 1 : 0;
      }
}

bool RayCastVolume::transparentCell(glm::ivec3 c) const {
  if (empty_.empty() || c.x < 0 || c.y < 0 || c.z < 0 || c.x >= cells_.x || c.y >= cells_.y || c.z >= cells_.z) return false;
  return empty_[(static_cast<std::size_t>(c.z) * static_cast<std::size_t>(cells_.y) + static_cast<std::size_t>(c.y)) * static_cast<std::size_t>(cells_.x) +
                static_cast<std::size_t>(c.x)] != 0;
}

namespace {

// The parameter range [t0, t1] of o + t·d inside the box [lo, hi] (slabs), empty when t0 > t1.
void slabs(glm::vec3 o, glm::vec3 d, glm::vec3 lo, glm::vec3 hi, float& t0, float& t1) {
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0f) {
      if (o[a] < lo[a] || o[a] > hi[a]) t0 = INFINITY, t1 = -INFINITY;
      continue;
    }
    float n = (lo[a] - o[a]) / d[a], f = (hi[a] - o[a]) / d[a];
    if (n > f) std::swap(n, f);
    t0 = std::max(t0, n), t1 = std::min(t1, f);
  }
}

}  // namespace

glm::vec4 RayCastVolume::cast(glm::vec3 from, glm::vec3 to, RayCastCounts& counts) const {
  const glm::vec3 d = to - from;
  const float length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  if (!(length > 0.0f)) return glm::vec4(0.0f);
  float t0 = 0.0f, t1 = 1.0f;
  slabs(from, d, glm::vec3(0.0f), volume_.extent(), t0, t1);
  if (!(t0 < t1)) return glm::vec4(0.0f);
  const float dt = delta_ / length;  // Δ as a share of the segment
  const auto first = static_cast<std::int64_t>(std::ceil(t0 / dt - 0.5f));
  const auto last = static_cast<std::int64_t>(std::floor(t1 / dt - 0.5f));  // samples k with t0 ≤ t_k ≤ t1
  glm::vec3 C(0.0f);
  float A = 0.0f;
  const glm::vec3 cellSize = static_cast<float>(kMacroCellSide) * volume_.spacing;
  for (std::int64_t k = std::max<std::int64_t>(first, 0); k <= last;) {
    const float t = (static_cast<float>(k) + 0.5f) * dt;
    const glm::vec3 p = from + t * d;
    if (options_.emptySpaceSkipping) {
      const glm::ivec3 cell = glm::ivec3(glm::floor(p / cellSize));
      if (transparentCell(cell)) {
        // On to the first sample past the cell: every sample inside it has opacity 0 and adds nothing.
        float c0 = -INFINITY, c1 = INFINITY;
        slabs(from, d, glm::vec3(cell) * cellSize, glm::vec3(cell + 1) * cellSize, c0, c1);
        const auto next = std::max(k + 1, static_cast<std::int64_t>(std::ceil(c1 / dt - 0.5f)));
        counts.skippedEmpty += static_cast<std::uint64_t>(std::min(next, last + 1) - k);
        k = next;
        continue;
      }
    }
    ++counts.samples;
    const glm::vec4 c = transfer_(trilinear(volume_, p));
    const float alpha = 1.0f - std::pow(1.0f - std::clamp(c.a, 0.0f, 1.0f), options_.step);
    const float weight = (1.0f - A) * alpha;
    C = C + weight * glm::vec3(c);
    A = A + weight;
    ++k;
    if (options_.earlyTermination < 1.0f && A >= options_.earlyTermination) {
      counts.savedByTermination += static_cast<std::uint64_t>(std::max<std::int64_t>(last + 1 - k, 0));
      break;
    }
  }
  return glm::vec4(C, A);
}

}  // namespace facet
