#pragma once
// Lit-pass programs specialized per frame: what the shaders would otherwise
// decide per pixel from uniforms (light count and kinds, which lights have
// shadow maps, the specular model, the PCF radius, whether the draw is
// textured, has vertex colours or is alpha-masked) becomes #defines compiled in. llvmpipe evaluates both sides of
// every `if` with per-pixel masks, so a texture path or a shadow lookup that
// a uniform turns off still costs its full price on every pixel; compiled
// out, it costs nothing. Only dead branches go: the arithmetic of the path
// taken is unchanged, and the images are bit-identical.
#include <string>

#include "pipeline/frame_inputs.h"

namespace facet::gl {

// What one draw of the lit pass reads besides the base colour factor.
struct DrawVariant {
  bool textured = false;  // a base colour texture, and the mesh has its texture coordinate set
  bool colored = false;   // COLOR_0
  bool masked = false;    // alphaMode MASK: fragments below the cutoff are discarded
  // Maps, each where the mesh has its set: shading=pbr's metallic-roughness and occlusion; every mode's emissive.
  bool metallicRoughnessMap = false, occlusionMap = false, emissiveMap = false;
  bool normalMap = false;  // a normal texture and tangents (Phong and pbr)
  bool bumped = false;     // the frame's bump map and the mesh's tangents (Phong and pbr)
  bool blended = false;    // transparency: the fragment blends into the colour buffer (lit pass only)
  static constexpr int kCount = 512;
  int index() const {
    return (textured ? 1 : 0) + (colored ? 2 : 0) + (masked ? 4 : 0) + (metallicRoughnessMap ? 8 : 0) + (occlusionMap ? 16 : 0) + (emissiveMap ? 32 : 0) +
           (normalMap ? 64 : 0) + (bumped ? 128 : 0) + (blended ? 256 : 0);
  }
  static DrawVariant of(int index) {
    return {(index & 1) != 0,  (index & 2) != 0,  (index & 4) != 0,  (index & 8) != 0,
            (index & 16) != 0, (index & 32) != 0, (index & 64) != 0, (index & 128) != 0, (index & 256) != 0};
  }
};

// The #define lines of a variant's draw-specific macros (FACET_TEXTURED,
// FACET_COLORED, FACET_MASKED, FACET_METALLIC_ROUGHNESS_MAP, FACET_OCCLUSION_MAP,
// FACET_EMISSIVE_MAP, FACET_NORMAL_MAP, FACET_BUMP_MAP, FACET_BLENDED): the lit
// programs' and the triangle-id pass's.
std::string drawVariantDefines(DrawVariant variant);

// "#define FACET_FOG m": the frame's fog mode (fog.glsl), for the lit and the line programs.
std::string fogDefine(const FrameInputs& frame);

// What a lit program writes: the fragment's linear colour; its colour's
// sRGB levels (FACET_LEVELS_OUTPUT: a frame nothing blends or averages,
// encoded as drawn, renderer/PIPELINE.md, "The colour buffer and
// the resolve"); or the normal it is shaded with (FACET_NORMAL_OUTPUT: the
// normals stage, "Stages"). Only Color for a blended draw.
enum class LitOutput { Color, Levels, Normal };

// The #define lines (one per macro, each ending in a newline) of the lit
// programs for `frame`, for draws of `variant`, writing `output`. Equal
// strings mean the same program, so the text is also the key of the
// renderer's program cache.
std::string litShaderDefines(const FrameInputs& frame, DrawVariant variant, LitOutput output = LitOutput::Color);

}  // namespace facet::gl
