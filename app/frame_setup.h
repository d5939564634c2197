#pragma once
// What `facet render` and `facet batch` do between a loaded scene and a drawn
// frame, in one place: the settings' additions to the scene, the frame's
// inputs, and the backend chosen by name.
#include <memory>
#include <string>

#include "pipeline/frame_inputs.h"
#include "pipeline/scene_additions.h"
#include "ray/ray_renderer.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "settings/render_settings.h"

namespace facet {

struct PreparedFrame {
  RenderSettings settings;  // as the frame is built with (addVolumeAndParticles may resolve the camera and lights)
  SceneAdditions added;
  FrameInputs frame;
};

// The displacement, the bump map and the environment that `asked` names,
// added to `scene`. Throws facet::Error naming the key.
void addMaterialMaps(Scene& scene, const RenderSettings& asked);

// addMaterialMaps, then the volume and particles added to `scene` as `asked`
// says, then the frame's inputs. Throws facet::Error naming the key.
PreparedFrame prepareFrame(Scene& scene, const RenderSettings& asked, int threads);

// The renderer `backend` names (gl, cpu, reference, ray, or auto: gl when a
// driver loads, cpu otherwise); `context` is gl's (auto: EGL, else OSMesa;
// egl; osmesa), `threads` the CPU backend's and ray tracer's (0: one per
// core). Throws facet::Error for gl when no driver loads or the build has
// none.
std::unique_ptr<Renderer> makeBackend(const std::string& backend, const std::string& context, int threads, RenderProgress progress = {});

}  // namespace facet
