#pragma once
// The last step of a CPU frame (renderer/PIPELINE.md, section 7, "The colour
// buffer and the resolve"): each pixel of the linear colour buffer clamped,
// its colour (a premultiplied buffer's divided by its alpha first) encoded to
// sRGB levels and its alpha to a linear level.
// Mirror: shaders/resolve.frag.
#include "cpu/thread_pool.h"
#include "image/color_buffer.h"
#include "image/image.h"
#include "settings/render_settings.h"

namespace facet::cpu {

// `image` takes the buffer's size; rows are split across the pool.
void resolve(ThreadPool& pool, const ColorBuffer& buffer, Blending blending, Image& image);

}  // namespace facet::cpu
