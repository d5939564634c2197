#include "gl/shader_variant.h"

namespace facet::gl {
namespace {

// "((i) == 0 ? a : (i) == 1 ? b : c)": a function-like macro that folds to a
// literal once the light loop is unrolled over the constant light count.
template <class Value>
std::string perLight(const FrameInputs& frame, Value value) {
  std::string chain = "(";
  for (std::size_t i = 0; i + 1 < frame.lights.size(); ++i) {
    chain.append("(i) == ").append(std::to_string(i)).append(" ? ").append(value(frame.lights[i])).append(" : ");
  }
  chain.append(value(frame.lights.empty() ? FrameLight{} : frame.lights.back())).append(")");
  return chain;
}

}  // namespace

std::string drawVariantDefines(DrawVariant variant) {
  std::string d;
  d += "#define FACET_TEXTURED " + std::string(variant.textured ? "1" : "0") + "\n";
  d += "#define FACET_COLORED " + std::string(variant.colored ? "1" : "0") + "\n";
  d += "#define FACET_MASKED " + std::string(variant.masked ? "1" : "0") + "\n";
  d += "#define FACET_METALLIC_ROUGHNESS_MAP " + std::string(variant.metallicRoughnessMap ? "1" : "0") + "\n";
  d += "#define FACET_OCCLUSION_MAP " + std::string(variant.occlusionMap ? "1" : "0") + "\n";
  d += "#define FACET_EMISSIVE_MAP " + std::string(variant.emissiveMap ? "1" : "0") + "\n";
  d += "#define FACET_NORMAL_MAP " + std::string(variant.normalMap ? "1" : "0") + "\n";
  d += "#define FACET_BUMP_MAP " + std::string(variant.bumped ? "1" : "0") + "\n";
  d += "#define FACET_BLENDED " + std::string(variant.blended ? "1" : "0") + "\n";
  return d;
}

std::string fogDefine(const FrameInputs& frame) { return "#define FACET_FOG " + std::to_string(static_cast<int>(frame.fog.mode)) + "\n"; }

std::string litShaderDefines(const FrameInputs& frame, DrawVariant variant, LitOutput output) {
  // A blended draw reads the colour buffer in its fragment shader (lit_output.glsl); the
  // directive comes first, before any declaration, and only the fragment stage uses it.
  std::string d = variant.blended ? "#extension GL_EXT_shader_framebuffer_fetch : enable\n" : "";
  d += drawVariantDefines(variant);
  if (variant.blended) d += "#define FACET_PREMULTIPLIED " + std::string(frame.blending == Blending::Premultiplied ? "1" : "0") + "\n";
  d += "#define FACET_NORMAL_OUTPUT " + std::string(output == LitOutput::Normal ? "1" : "0") + "\n";
  d += "#define FACET_LEVELS_OUTPUT " + std::string(output == LitOutput::Levels ? "1" : "0") + "\n";
  d += "#define FACET_ENVIRONMENT " + std::string(frame.environment.map ? "1" : "0") + "\n";
  d += "#define FACET_PBR " + std::string(frame.shading == ShadingMode::Pbr ? "1" : "0") + "\n";
  d += fogDefine(frame);
  d += "#define FACET_PROCEDURAL " + std::to_string(static_cast<int>(frame.procedural)) + "\n";
  d += "#define FACET_SPECULAR_MODEL " + std::to_string(static_cast<int>(frame.specular)) + "\n";
  d += "#define FACET_PCF_RADIUS " + std::to_string(frame.shadows.pcfRadius) + "\n";
  d += "#define FACET_LIGHT_COUNT " + std::to_string(frame.lights.size()) + "\n";
  d += "#define FACET_LIGHT_KIND(i) " + perLight(frame, [](const FrameLight& l) { return std::to_string(static_cast<int>(l.light.kind)); }) + "\n";
  d += "#define FACET_LIGHT_SHADOWED(i) " + perLight(frame, [](const FrameLight& l) { return std::string(l.hasShadowMap ? "true" : "false"); }) + "\n";
  return d;
}

}  // namespace facet::gl
