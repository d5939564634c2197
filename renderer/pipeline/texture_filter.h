#pragma once
// textures.filter applied to a texture's glTF sampler (renderer/PIPELINE.md, "Textures").
#include "scene/scene.h"
#include "settings/render_settings.h"

namespace facet {

// auto keeps the sampler; nearest, bilinear and trilinear replace both of its
// filters (NEAREST / NEAREST, LINEAR / LINEAR, LINEAR / LINEAR_MIPMAP_LINEAR)
// and keep its wraps.
Sampler filteredSampler(Sampler sampler, TextureFilter filter);

}  // namespace facet
