#pragma once
#include <glm/mat4x4.hpp>

namespace facet {

// The course's normalized perspective matrix. theta is the half-angle of view
// measured horizontally (radians), aspect = W/H, 0 < near < far:
//   [ 1  0    0       0     ]
//   [ 0  A_R  0       0     ]    A = F/(F-N), B = -N·F/(F-N)
//   [ 0  0    A·tanθ  B·tanθ]
//   [ 0  0    tanθ    0     ]
// After the divide: x' = x/(z tanθ), y' = A_R·y/(z tanθ), z' = A + B/z,
// so z' = 0 at the near plane and 1 at the far plane.
glm::mat4 perspective(float theta, float aspect, float near, float far);

// The course's parallel normalization matrix for a box of width W and height H
// between the planes z = N and z = F (eye space):
//   [ 2/W  0    0        0       ]
//   [ 0    2/H  0        0       ]
//   [ 0    0    1/(F-N)  -N/(F-N)]
//   [ 0    0    0        1       ]
glm::mat4 parallel(float width, float height, float near, float far);

}  // namespace facet
