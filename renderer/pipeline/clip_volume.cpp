#include "pipeline/clip_volume.h"

#include <cmath>

namespace facet {

Bounds meshBounds(const Mesh& mesh) {
  Bounds box;
  for (const glm::vec3& p : mesh.positions) box.include(p);
  return box;
}

bool clipVolumeMisses(const glm::mat4& clipFromModel, const Bounds& box) {
  if (box.empty) return true;
  // Bit k of `beyond`: every corner so far is past plane k. The planes are
  // linear in the homogeneous point, so a box with all corners past one has
  // every point of its hull past it too, whatever the signs of w.
  unsigned beyond = 0x3f;
  for (int corner = 0; corner < 8 && beyond; ++corner) {
    const glm::vec3 p{(corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y, (corner & 4) ? box.max.z : box.min.z};
    const glm::vec4 c = clipFromModel * glm::vec4(p, 1.0f);
    if (!(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && std::isfinite(c.w))) return false;  // no claim: draw it
    const auto past = [&](float lhs, float rhs, float v) { return lhs > rhs + kClipMissMargin * (std::fabs(v) + std::fabs(c.w)); };
    unsigned now = 0;
    if (past(-c.w, c.x, c.x)) now |= 1u;   // x < -w
    if (past(c.x, c.w, c.x)) now |= 2u;    // x > w
    if (past(-c.w, c.y, c.y)) now |= 4u;   // y < -w
    if (past(c.y, c.w, c.y)) now |= 8u;    // y > w
    if (past(0.0f, c.z, c.z)) now |= 16u;  // z < 0
    if (past(c.z, c.w, c.z)) now |= 32u;   // z > w
    beyond &= now;
  }
  return beyond != 0;
}

}  // namespace facet
