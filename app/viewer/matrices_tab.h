#pragma once
// The panel's Matrices tab: the matrices of the frame on screen with their
// numbers, as the course names them: the selected object's TM, the eye
// matrix EM, the projection PM, the viewport (window) matrix, PM·EM·TM, and
// each shadow-casting light's PM·EM for pass 1 and its shadow matrix for
// pass 2. They follow every slider, since they are the frame's own.
#include "scene/scene.h"
#include "viewer/view_frame.h"

namespace facet::viewer {

struct MatrixSelection {
  int instance = 0;  // into FrameInputs::instances (a picked pixel selects its triangle's)
  int light = 0;     // into FrameInputs::lights
  int face = 0;      // a point light's cube face, 0..5
};

void drawMatricesTab(const DrawnFrame& drawn, MatrixSelection& selection);

}  // namespace facet::viewer
