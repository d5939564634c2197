// The resolve's rule for one pixel (renderer/PIPELINE.md, "The
// colour buffer and the resolve"): what the colour buffer holds there,
// averaged over the samples first, taken to its straight colour and
// encoded as the image's levels. Mirror: cpu::resolveRow.
#include "srgb.glsl"
#include "blending.glsl"

vec4 resolved(vec4 held, bool premultiplied) {
  return encodeSrgb(unstored(held, premultiplied));
}
