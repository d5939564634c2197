#include "render/renderer.h"

namespace facet {

FrameOutputs::FrameOutputs(std::initializer_list<FrameOutput> outputs) {
  for (const FrameOutput output : outputs) set_.set(static_cast<std::size_t>(output));
}

void Renderer::refuseUndrawn(const FrameOutputs& asked, const FrameOutputs& drawn) const {
  for (std::size_t k = 0; k < kFrameOutputNames.size(); ++k) {
    const auto output = static_cast<FrameOutput>(k);
    if (asked.has(output) && !drawn.has(output))
      throw Error("the " + std::string(kFrameOutputNames[k]) + " stage is not drawn by " + description());
  }
}

}  // namespace facet
