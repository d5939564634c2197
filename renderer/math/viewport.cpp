#include "math/viewport.h"

#include "math/transforms.h"

namespace facet {

glm::mat4 windowToViewport(const Rect& w, const Rect& v) {
  const glm::vec3 scale{(v.right - v.left) / (w.right - w.left), (v.top - v.bottom) / (w.top - w.bottom), 1.0f};
  return translation({v.left, v.bottom, 0.0f}) * scaling(scale) * translation({-w.left, -w.bottom, 0.0f});
}

glm::mat4 viewportMatrix(int width, int height) {
  return windowToViewport({-1, 1, -1, 1}, {0, static_cast<float>(width), 0, static_cast<float>(height)});
}

}  // namespace facet
