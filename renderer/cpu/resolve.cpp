#include "cpu/resolve.h"

#include "cpu/blending.h"
#include "cpu/passes.h"
#include "cpu/srgb_table.h"
#include "image/srgb.h"

namespace facet::cpu {

void resolve(ThreadPool& pool, const ColorBuffer& buffer, Blending holding, int samples, Image& image) {
  image = Image(buffer.width(), buffer.height());
  const auto width = static_cast<std::size_t>(buffer.width());
  const auto count = static_cast<float>(samples);
  forEachRange(pool, static_cast<std::size_t>(buffer.height()), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t i = begin * width; i < end * width; ++i) {
      const glm::vec4 linear = unstored(samples == 1 ? buffer.data()[i] : buffer.data()[i] / count, holding);
      Rgba8& out = image.data()[i];
      std::uint8_t levels[4];
      encodeLevels4(&linear.r, levels);  // four at a time; the fourth, alpha, is not light
      out = {levels[0], levels[1], levels[2], alphaLevel(linear.a)};
    }
  });
}

void accumulate(ThreadPool& pool, const ColorBuffer& sample, Blending blending, ColorBuffer& sum) {
  const auto width = static_cast<std::size_t>(sample.width());
  forEachRange(pool, static_cast<std::size_t>(sample.height()), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t i = begin * width; i < end * width; ++i) sum.data()[i] = sum.data()[i] + premultipliedOf(sample.data()[i], blending);
  });
}

}  // namespace facet::cpu
