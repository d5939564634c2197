// Matrix times point in one fixed order, never fused into multiply-adds:
//   M·(x, y, z, 1) = ((M[0]·x + M[1]·y) + M[2]·z) + M[3]
// Mirror: renderer/shading/transform.h. With `precise`, llvmpipe computes the
// same roundings as the CPU backend, so clip coordinates agree bit for bit
// and both backends snap vertices to the same sub-pixel positions.
vec4 transformPoint(mat4 m, vec3 p) {
  precise vec4 r = ((m[0] * p.x + m[1] * p.y) + m[2] * p.z) + m[3];
  return r;
}

vec3 transformDirection(mat3 m, vec3 d) {
  precise vec3 r = (m[0] * d.x + m[1] * d.y) + m[2] * d.z;
  return r;
}
