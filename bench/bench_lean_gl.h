#pragma once
// facet bench's "lean" column: llvmpipe running the simplest programs that
// draw a bench scene's picture, as a floor for what facet's own GL backend
// (renderer/gl) costs on the same driver. Bench code only, not a backend of
// the product: no course contract (no bit-exact transforms, no
// llvmpipe-mirroring resolve), no textures, fog, PBR, lines or sprites.
#include <memory>
#include <string>

#include "render/renderer.h"

namespace facet {

// Why the lean peer has no program for this frame ("textures", "unlit
// materials", "a ray-cast volume", ...), or empty when it draws it.
std::string leanUnsupported(const Scene& scene, const FrameInputs& frame);

// How the lean peer draws an anti-aliased frame (s² samples a pixel): into a
// multisampled framebuffer either way (llvmpipe's sample positions), with
// the fragment shader run for every sample (GL 4.0 sample shading at a
// minimum of 1), which is the course's supersampling: the lighting
// evaluated at each sample, as the contract's pass per sample does; or run
// once a pixel, which is plain MSAA: edges anti-aliased, shading not.
enum class LeanSampling { EverySample, OncePerPixel };

// On an OSMesa context of its own, made current at every call. Throws
// facet::Error when the context cannot be made; render() throws for a frame
// leanUnsupported refuses.
std::unique_ptr<Renderer> makeLeanGlRenderer(LeanSampling sampling = LeanSampling::EverySample);

}  // namespace facet
