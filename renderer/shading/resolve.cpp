#include "shading/resolve.h"

#include "shading/blending.h"
#include "shading/srgb_table.h"
#include "image/srgb.h"

namespace facet {

void resolveRow(const glm::vec4* in, Rgba8* out, std::size_t n, Blending holding, int samples, int lanes) {
#if defined(FACET_AVX512_LANES)
  if (lanes == 16) return resolveSixteenLanes(in, out, n, holding == Blending::Premultiplied, samples);
#else
  (void)lanes;
#endif
  const SrgbTables& tables = srgbTables();
  if (samples == 1 && holding != Blending::Premultiplied) {  // the opaque frame's case: the colour as held
    for (std::size_t i = 0; i < n; ++i) out[i] = encodePixel4(tables, &in[i].r);
    return;
  }
  const auto count = static_cast<float>(samples);
  for (std::size_t i = 0; i < n; ++i) {
    const glm::vec4 linear = unstored(samples == 1 ? in[i] : in[i] / count, holding);
    out[i] = encodePixel4(tables, &linear.r);
  }
}

void resolve(ThreadPool& pool, const ColorBuffer& buffer, Blending holding, int samples, int lanes, Image& image) {
  image.resize(buffer.width(), buffer.height());  // its storage kept where it fits: every pixel is written below
  const auto width = static_cast<std::size_t>(buffer.width());
  forEachRange(pool, static_cast<std::size_t>(buffer.height()), [&](std::size_t begin, std::size_t end, int) {
    resolveRow(buffer.data() + begin * width, image.data() + begin * width, (end - begin) * width, holding, samples, lanes);
  });
}

void accumulate(ThreadPool& pool, const ColorBuffer& sample, Blending blending, ColorBuffer& sum, bool first) {
  if (first) sum.resize(sample.width(), sample.height());
  const auto width = static_cast<std::size_t>(sample.width());
  forEachRange(pool, static_cast<std::size_t>(sample.height()), [&](std::size_t begin, std::size_t end, int) {
    const glm::vec4* const in = sample.data();
    glm::vec4* const out = sum.data();
    for (std::size_t i = begin * width; i < end * width; ++i) {
      out[i] = (first ? glm::vec4(0.0f) : out[i]) + premultipliedOf(in[i], blending);  // 0 + p, as a sum cleared to 0 (-0 + 0 is +0)
    }
  });
}

}  // namespace facet
