#pragma once
// The last step of a CPU frame (renderer/PIPELINE.md, section 7, "The colour
// buffer and the resolve"): each pixel of the linear colour buffer clamped,
// its colour (a premultiplied buffer's divided by its alpha first) encoded to
// sRGB levels and its alpha to a linear level.
// Mirror: shaders/resolve.frag, shaders/accumulate.frag.
#include "cpu/thread_pool.h"
#include "image/color_buffer.h"
#include "image/image.h"
#include "settings/render_settings.h"

namespace facet::cpu {

// `image` takes the buffer's size; rows are split across the pool. The
// buffer holds colours as `holding` says, summed over `samples` passes
// (divided by that count first: anti-aliasing's box filter). Four lanes
// (srgb_table.h): an eight-lane encode with gathers measured slower (3.7
// against 3.2 ms at 1920x1080): gathers are slow, and a quarter of the pass
// is reading the float buffer from memory (resolving each tile in the cache
// instead saved no more than that; README, "Eight lanes").
void resolve(ThreadPool& pool, const ColorBuffer& buffer, Blending holding, int samples, Image& image);
// That rule for n pixels of one sample: out[i] from in[i].
void resolveRow(const glm::vec4* in, Rgba8* out, std::size_t n, Blending holding);

// Anti-aliasing: one sample's colour buffer, held as `blending` says, added
// premultiplied into `sum` (pixel by pixel, in the order the samples are
// drawn; the first sample sets `sum`'s size and adds itself to 0).
void accumulate(ThreadPool& pool, const ColorBuffer& sample, Blending blending, ColorBuffer& sum, bool first);

}  // namespace facet::cpu
