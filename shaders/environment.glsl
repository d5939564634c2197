// Environment mapping (renderer/PIPELINE.md, "Textures"): the cube map's
// linear RGB in a direction, for the reflection k_r·I_r and the background.
// Mirror: renderer/shading/environment.h. Needs shading_math.glsl and texture.glsl before it.

layout(binding = 2) uniform usampler2D environmentMap;  // six square faces side by side, +x -x +y -y +z -z (GL_RGBA8UI), and their mips

// env(D) at mip level k: the face of D's largest component (cubeFace),
// OpenGL's (sc, tc, ma) for it, LINEAR within the face, clamped to its edges.
// The level's face size is level 0's halved (texture.glsl's sampleLevel says why).
vec3 environmentAt(vec3 D, int level) {
  int face = cubeFace(D);
  float sc, tc, ma;
  if (face == 0) { sc = -D.z; tc = -D.y; ma = D.x; }
  else if (face == 1) { sc = D.z; tc = -D.y; ma = -D.x; }
  else if (face == 2) { sc = D.x; tc = D.z; ma = D.y; }
  else if (face == 3) { sc = D.x; tc = -D.z; ma = -D.y; }
  else if (face == 4) { sc = D.x; tc = -D.y; ma = D.z; }
  else { sc = -D.x; tc = -D.y; ma = -D.z; }
  precise float s = (sc / ma + 1.0) * 0.5, t = (tc / ma + 1.0) * 0.5;
  int n = max(1, textureSize(environmentMap, 0).y >> level);
  return sampleRegion(environmentMap, true, level, ivec2(face * n, 0), ivec2(n, n), true, kWrapClampToEdge, kWrapClampToEdge, vec2(s, t)).rgb;
}

// The linear colour of the empty pixel whose centre is `fragCoord`: env(D)
// where the frame shows its map, else the background colour.
vec3 backgroundAt(vec2 fragCoord, vec2 size) {
  if (!(frame.environment.z > 0.0)) return frame.background.rgb;
  precise float x = (2.0 * fragCoord.x) / size.x - 1.0;
  precise float y = (2.0 * fragCoord.y) / size.y - 1.0;
  precise vec3 D = (frame.backgroundForward.xyz + x * frame.backgroundRight.xyz) + y * frame.backgroundUp.xyz;
  return environmentAt(D, 0);
}
