#pragma once
// `facet view --bench-orbit N`: the camera turns once around P_ref in N
// window frames, as a steady drag would turn it, and each whole window frame
// (input, panel, 3D frame, swap) is timed. Beside it, in the same run, the
// same scene, settings and size rendered headless by `facet render` in a
// child process: the ratio says what the viewer saves over drawing every
// frame from scratch.
#include <string>
#include <vector>

#include "settings/render_settings.h"
#include "viewer/viewer_state.h"

namespace facet::viewer {

// Turns the camera 360/frames degrees about v_up: a drag of 2 H / frames pixels (camera_controls.h).
void orbitBenchStep(ViewerState& state, int frames, float windowHeight);

// A headless frame: the median over `runs` processes of the sum of the
// frame's passes `facet render --backend B` prints (shadow, lit, resolve,
// read-back: not the process start, the scene upload or the shader compile).
// Throws facet::Error when the child fails.
double headlessFrameMilliseconds(const std::string& scenePath, const RenderSettings& settings, const std::string& backend, int runs);

// The figures: the window frames' median and spread, and the ratio to each headless frame.
// shown: which backend drew the view; dragPreview: the preview's divisor (ViewerState).
void printOrbitReport(const std::vector<double>& windowMilliseconds, const std::string& shown, int dragPreview, const std::string& scenePath,
                      const RenderSettings& settings);

}  // namespace facet::viewer
