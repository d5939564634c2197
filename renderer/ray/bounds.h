#pragma once
// An axis-aligned box, world space. Empty until grown: lower = +inf,
// upper = -inf, so the union with anything is that thing. Unions are min
// and max, exact in floating point, so a box built in any order is the
// same box.
#include <algorithm>
#include <limits>

#include <glm/vec3.hpp>

namespace facet::ray {

struct Bounds {
  glm::vec3 lower{std::numeric_limits<float>::infinity()};
  glm::vec3 upper{-std::numeric_limits<float>::infinity()};

  bool empty() const { return !(lower.x <= upper.x && lower.y <= upper.y && lower.z <= upper.z); }

  void grow(const glm::vec3& p) {
    lower = glm::vec3(std::min(lower.x, p.x), std::min(lower.y, p.y), std::min(lower.z, p.z));
    upper = glm::vec3(std::max(upper.x, p.x), std::max(upper.y, p.y), std::max(upper.z, p.z));
  }
  void grow(const Bounds& b) {  // lower with lower, upper with upper: an empty b changes nothing
    lower = glm::vec3(std::min(lower.x, b.lower.x), std::min(lower.y, b.lower.y), std::min(lower.z, b.lower.z));
    upper = glm::vec3(std::max(upper.x, b.upper.x), std::max(upper.y, b.upper.y), std::max(upper.z, b.upper.z));
  }

  // Half the surface area, in double: the extents of a box of finite floats
  // cannot overflow there. 0 for an empty box. The SAH needs only ratios.
  double halfArea() const {
    if (empty()) return 0.0;
    const double x = static_cast<double>(upper.x) - lower.x;
    const double y = static_cast<double>(upper.y) - lower.y;
    const double z = static_cast<double>(upper.z) - lower.z;
    return x * y + y * z + z * x;
  }

  // The axis (0, 1, 2) of the largest extent, the first on a tie.
  int largestAxis() const {
    const double x = static_cast<double>(upper.x) - lower.x;
    const double y = static_cast<double>(upper.y) - lower.y;
    const double z = static_cast<double>(upper.z) - lower.z;
    return (x >= y && x >= z) ? 0 : (y >= z ? 1 : 2);
  }
};

}  // namespace facet::ray
