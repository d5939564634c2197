#pragma once
#include <glm/mat4x4.hpp>

namespace facet {

// An axis-aligned rectangle: left, right, bottom, top.
struct Rect {
  float left = 0, right = 1, bottom = 0, top = 1;
};

// The course's window-to-viewport mapping
//   M = T(V_L, V_B) · S((V_R-V_L)/(W_R-W_L), (V_T-V_B)/(W_T-W_B)) · T(-W_L, -W_B)
// on x and y; z passes through unchanged (window z = NDC z in [0, 1]).
glm::mat4 windowToViewport(const Rect& window, const Rect& viewport);

// The mapping used for every frame: window [-1,1]² onto [0,W]×[0,H] pixels,
// origin at the lower left, pixel (px, py) centred at (px + 0.5, py + 0.5).
glm::mat4 viewportMatrix(int width, int height);

}  // namespace facet
