#include "pipeline/texture_filter.h"

namespace facet {

Sampler filteredSampler(Sampler sampler, TextureFilter filter) {
  switch (filter) {
    case TextureFilter::Nearest: sampler.mag = MagFilter::Nearest, sampler.min = MinFilter::Nearest; break;
    case TextureFilter::Bilinear: sampler.mag = MagFilter::Linear, sampler.min = MinFilter::Linear; break;
    case TextureFilter::Trilinear: sampler.mag = MagFilter::Linear, sampler.min = MinFilter::LinearMipmapLinear; break;
    case TextureFilter::Auto:
    case TextureFilter::Count: break;
  }
  return sampler;
}

}  // namespace facet
