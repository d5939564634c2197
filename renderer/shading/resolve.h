#pragma once
// The last step of a CPU frame (renderer/PIPELINE.md, "The colour
// buffer and the resolve"): each pixel of the linear colour buffer clamped,
// its colour (a premultiplied buffer's divided by its alpha first) encoded to
// sRGB levels and its alpha to a linear level.
// Mirror: shaders/resolve.frag, shaders/accumulate.frag.
#include "common/thread_pool.h"
#include "image/color_buffer.h"
#include "image/image.h"
#include "settings/render_settings.h"

namespace facet {

// `image` takes the buffer's size (its storage kept where it fits,
// Image::resize); rows are split across the pool. The buffer holds colours
// as `holding` says, summed over `samples` passes (divided by that count
// first: anti-aliasing's box filter). `lanes` is the
// renderer's width (lane_width.h): at 16 the pixels go four at a time
// (resolve_avx512.cpp), else one at a time, each channel's clamp and bucket
// four lanes at a time (srgb_table.h). An eight-lane encode with gathers
// measured slower than the one-pixel rule: gathers are slow, which the
// sixteen-lane path's estimate avoids.
void resolve(ThreadPool& pool, const ColorBuffer& buffer, Blending holding, int samples, int lanes, Image& image);
// That rule for n pixels in a row: out[i] from in[i].
void resolveRow(const glm::vec4* in, Rgba8* out, std::size_t n, Blending holding, int samples, int lanes);
#if defined(FACET_AVX512_LANES)
// resolveRow at sixteen lanes (AVX-512F; only where widestLanes() says so).
void resolveSixteenLanes(const glm::vec4* in, Rgba8* out, std::size_t n, bool premultiplied, int samples);
#endif

// Anti-aliasing: one sample's colour buffer, held as `blending` says, added
// premultiplied into `sum` (pixel by pixel, in the order the samples are
// drawn; the first sample sets `sum`'s size and adds itself to 0).
void accumulate(ThreadPool& pool, const ColorBuffer& sample, Blending blending, ColorBuffer& sum, bool first);

}  // namespace facet
