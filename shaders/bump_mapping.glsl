// Bump mapping (renderer/PIPELINE.md, "Bump mapping"): the
// course's perturbed normal from a height map's partial derivatives and the
// surface's. Mirror: renderer/shading/bump_mapping.h. Needs shading_math.glsl,
// texture.glsl and normal_mapping.glsl (tangentFrame) before it.

layout(binding = 7) uniform usampler2D bumpMap;  // grey bytes, read as data at level 0

// h at st: level 0, LINEAR, REPEAT, grey / 255.
float bumpHeight(vec2 st) {
  ivec2 size = textureSize(bumpMap, 0);
  return sampleRegion(bumpMap, false, 0, ivec2(0, 0), size, true, 0, 0, st).r;
}

// N' = N + B_u·(N × P_t) - B_v·(N × P_s) before it is normalized (renderer/shading/bump_mapping.h says how).
vec3 bumped(vec3 N, vec4 tangent, vec2 st) {
  ivec2 size = textureSize(bumpMap, 0);
  precise float ds = 1.0 / float(size.x), dt = 1.0 / float(size.y);
  float k = frame.ambient.z;
  precise float Bu = k * ((bumpHeight(vec2(st.x + ds, st.y)) - bumpHeight(vec2(st.x - ds, st.y))) / (2.0 * ds));
  precise float Bv = k * ((bumpHeight(vec2(st.x, st.y - dt)) - bumpHeight(vec2(st.x, st.y + dt))) / (2.0 * dt));
  TangentFrame f = tangentFrame(N, tangent);  // P_s = T, P_t = B
  precise vec3 bent = (N + Bu * cross3(N, f.B)) - Bv * cross3(N, f.T);
  return bent;
}
