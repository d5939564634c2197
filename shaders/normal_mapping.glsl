// glTF normal textures (renderer/PIPELINE.md, "Normal textures"):
// the tangent-space normal of the texture turned into world space by the
// pixel's tangent frame. Mirror: renderer/shading/normal_mapping.h.
// Needs shading_math.glsl, texture.glsl and draw_uniforms.glsl before it.

// The pixel's unit tangent frame: T = normalize3(t - N·(N·t)), B = (w < 0 ? -1 : 1)·(N × T).
// Normal textures and bump mapping share it.
struct TangentFrame {
  vec3 T;
  vec3 B;
};
TangentFrame tangentFrame(vec3 N, vec4 tangent) {
  vec3 t = tangent.xyz;
  precise vec3 T = normalize3(t - N * dot3(N, t));
  precise vec3 B = (tangent.w < 0.0 ? -1.0 : 1.0) * cross3(N, T);
  return TangentFrame(T, B);
}

// N' before it is normalized: n = (2·texel - 1) with x, y times the scale,
// T = normalize3(t - N·(N·t)), B = ±(N × T) by the tangent's w, N' = (T·n.x + B·n.y) + N·n.z.
vec3 normalMapped(vec3 N, vec4 tangent, Texcoords t) {
  vec4 texel = sampleTexture(normalMap, mapsSrgb.w != 0, normalMapSampler, setOf(t, mapSets.w), derivativesOf(t, mapSets.w));
  precise float x = (2.0 * texel.r - 1.0) * normalScale, y = (2.0 * texel.g - 1.0) * normalScale;
  precise float z = 2.0 * texel.b - 1.0;
  TangentFrame f = tangentFrame(N, tangent);
  precise vec3 bent = (f.T * x + f.B * y) + N * z;
  return bent;
}
