#pragma once
// hsr = painter on the OpenGL side (renderer/PIPELINE.md, section 6,
// "Hidden-surface removal"): the frame's triangles in FrameInputs::paintersOrder,
// cut into runs of one instance each. Their indices are copied in that order
// into one index buffer, so that a run is one draw and GL's primitive order is
// the painter's; the triangles' indices in the frame go into a storage buffer
// for the triangle-id pass.
#include <cstddef>
#include <vector>

#include "gl/gl_object.h"
#include "pipeline/frame_inputs.h"
#include "scene/scene.h"

namespace facet::gl {

struct PainterRun {
  std::size_t instance = 0;       // index into FrameInputs::instances
  GLsizei first = 0, count = 0;   // positions in the painter's order, in triangles
};

class PaintersDraws {
 public:
  // Once per painter frame, before its draws.
  void prepare(const GlFunctions& gl, const Scene& scene, const FrameInputs& frame);

  const std::vector<PainterRun>& runs() const { return runs_; }
  GLuint indices() const { return indices_.id(); }      // three mesh-local vertex indices per position
  GLuint triangles() const { return triangles_.id(); }  // each position's index in the frame's triangle list

 private:
  std::vector<PainterRun> runs_;
  GlObject indices_, triangles_;
};

}  // namespace facet::gl
