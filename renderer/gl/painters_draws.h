#pragma once
// Triangles drawn in an order of their own on the OpenGL side: hsr = painter
// (renderer/PIPELINE.md, "Hidden-surface removal"), the frame's
// triangles in FrameInputs::paintersOrder, and transparency ("Transparency"), the
// blended ones in FrameInputs::transparentOrder. The order is cut into runs of
// one instance each. Their indices are copied in that order
// into one index buffer, so that a run is one draw and GL's primitive order is
// the painter's; the triangles' indices in the frame go into a storage buffer
// for the triangle-id pass.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "gl/gl_object.h"
#include "pipeline/frame_inputs.h"
#include "scene/scene.h"

namespace facet::gl {

struct PainterRun {
  std::size_t instance = 0;       // index into FrameInputs::instances
  GLsizei first = 0, count = 0;   // positions in the order, in triangles
  GLuint indices = 0;             // the index buffer they are drawn from (PaintersDraws::indices)
};

class PaintersDraws {
 public:
  // Once per frame, before its draws: `order` holds indices into the frame's triangle list.
  void prepare(const GlFunctions& gl, const Scene& scene, const FrameInputs& frame, const std::vector<std::uint32_t>& order);

  const std::vector<PainterRun>& runs() const { return runs_; }
  GLuint indices() const { return indices_.id(); }      // three mesh-local vertex indices per position
  GLuint triangles() const { return triangles_.id(); }  // each position's index in the frame's triangle list

 private:
  std::vector<PainterRun> runs_;
  GlObject indices_, triangles_;
};

}  // namespace facet::gl
