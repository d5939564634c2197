// The course's fog (renderer/PIPELINE.md, "Fog"): C = C_fog +
// f·(C - C_fog) by the pixel's eye-space depth d; FACET_FOG is the mode
// (0 none: compiled out, 1 linear, 2 exponential, 3 exponential2).
// Mirror: renderer/shading/fog.h. Needs frame_block.glsl and shading_math.glsl before it.

const float kLog2E = 1.44269502;  // log2 e as a float

// d from what the rasterizer interpolates: 1/w (perspective, w = z_eye·tan θ)
// or the window depth z (parallel, z = (z_eye - N)/(F - N)).
float eyeDepth() {
  if (frame.eyePosition.w != 0.0) {
    precise float d = (1.0 / gl_FragCoord.w) * frame.fog.w;
    return d;
  }
  precise float d = frame.fogRange.x + gl_FragCoord.z * (frame.fogRange.y - frame.fogRange.x);
  return d;
}

vec3 fogged(vec3 color) {
#if defined(FACET_FOG) && FACET_FOG
  float d = eyeDepth();
#if FACET_FOG == 1
  precise float f = (frame.fog.y - d) / (frame.fog.y - frame.fog.x);
#else
  precise float x = frame.fog.z * d;
  precise float e = FACET_FOG == 2 ? x : x * x;
  precise float f = exp2Of(-(e * kLog2E));
#endif
  f = minOne(maxZero(f));
  vec3 C = frame.fogColor.rgb;
  precise vec3 r = C + f * (color - C);
  return r;
#else
  return color;
#endif
}
