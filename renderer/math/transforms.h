#pragma once
// The course's elementary 3D transformations, as 4x4 homogeneous matrices
// acting on column vectors (P' = M·P). Angles are in radians.
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace facet {

glm::mat4 translation(glm::vec3 t);                // T(tx, ty, tz)
glm::mat4 scaling(glm::vec3 s);                    // S(sx, sy, sz)
glm::mat4 rotationX(float angle);                  // Rx(α): y toward z
glm::mat4 rotationY(float angle);                  // Ry(α): z toward x
glm::mat4 rotationZ(float angle);                  // Rz(α): x toward y

// Shear: x' = x + hxy·y + hxz·z, y' = y + hyx·x + hyz·z, z' = z + hzx·x + hzy·y.
struct ShearFactors {
  float hxy = 0, hxz = 0, hyx = 0, hyz = 0, hzx = 0, hzy = 0;
};
glm::mat4 shear(const ShearFactors& h);

// General rotation matrix GRM: its rows are the orthonormal vectors i, j, k,
// so it maps i to the x axis, j to y and k to z.
glm::mat4 generalRotation(glm::vec3 i, glm::vec3 j, glm::vec3 k);

// Rotation by `angle` about the axis through `point` with direction `axis`
// (course construction): T(P)·GRM^-1·Rz(α)·GRM·T(-P), with GRM's k = axis.
glm::mat4 rotationAboutAxis(glm::vec3 point, glm::vec3 axis, float angle);

// Inverses by the course's rules (no general matrix inversion).
glm::mat4 inverseTranslation(glm::vec3 t);          // T(-t)
glm::mat4 inverseScaling(glm::vec3 s);              // S(1/s); s must have no zero
glm::mat4 inverseRotation(const glm::mat4& rotation);  // R^-1 = R^T for a pure rotation

}  // namespace facet
