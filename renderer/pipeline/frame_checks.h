#pragma once
// What both backends may take for granted about a scene and a frame,
// checked in shared code before either backend draws: each backend's
// FrameCheck runs checkScene once per scene content (Scene::identity) and
// checkFrame on every frame it is given, so that a hand-made FrameInputs or
// Scene cannot make either backend read past an array; buildFrameInputs
// runs checkFrame on what it builds. A failure throws facet::Error naming
// the mesh, instance, material or setting.
#include <memory>

#include "pipeline/frame_inputs.h"
#include "scene/scene.h"
#include "settings/render_settings.h"

namespace facet {

// What the settings alone say is wrong, whatever the scene, checked as they
// are read (a settings file, each command line) rather than when a frame
// is drawn: volume.transfer parses, a manual camera's eye, reference and up
// define a view, and each particles.N emitter passes checkEmitter. Throws
// facet::Error naming the settings key.
void checkSettings(const RenderSettings& settings);

// The camera's eye, reference and up define a view (eye matrix, course
// formula: up not zero nor along the view direction, eye not at the
// reference), or facet::Error naming settings key 'camera'.
void checkEyeFrame(const CameraSettings& camera);

// Every instance names a mesh that exists; every mesh has one normal per
// position, no texture coordinates or one pair per position, only indices
// below its position count, and its material and texture exist.
void checkScene(const Scene& scene);

// The frame against its scene: an image size in [1, kMaxImageSide], the
// instances' meshes and materials exist, at most kMaxLights lights, the
// shadow-map size, PCF radius and layer count within their limits, no
// more than kMaxFrameVertices vertices over the instances, and the memory
// the frame works in (the instances' vertex and triangle buffers, the
// shadow maps) within kFrameMemoryBudget, priced before a backend
// allocates any of it.
void checkFrame(const Scene& scene, const FrameInputs& frame);

// What a backend calls first with each frame: checkScene when the scene's
// content is not the one it checked last, then checkFrame.
class FrameCheck {
 public:
  void operator()(const Scene& scene, const FrameInputs& frame);

 private:
  std::weak_ptr<const char> checked_;  // the last scene checkScene passed
};

}  // namespace facet
