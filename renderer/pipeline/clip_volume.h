#pragma once
// Whole-instance culling against a clip volume (renderer/PIPELINE.md,
// "Faces draw what they can reach"): a pass skips an instance
// whose model-space box lies beyond one plane of the volume, because none of
// its triangles could leave a fragment there. The box is the mesh's
// positions' (used by a triangle or not), so the test errs toward drawing.
#include <glm/mat4x4.hpp>

#include "scene/scene.h"

namespace facet {

// The box of every position of `mesh`; empty when it has none.
Bounds meshBounds(const Mesh& mesh);

// Whether all eight corners of `box` are beyond the same plane of the clip
// volume -w ≤ x ≤ w, -w ≤ y ≤ w, 0 ≤ z ≤ w of clipFromModel, each by more
// than kClipMissMargin·(|coordinate| + |w|): a margin far above the rounding
// between this product and a pass's own vertex transform. An empty box misses.
bool clipVolumeMisses(const glm::mat4& clipFromModel, const Bounds& box);

inline constexpr float kClipMissMargin = 1e-4f;

}  // namespace facet
