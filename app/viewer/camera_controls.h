#pragma once
// The orbit camera's moves, on the course's camera (P_eye, P_ref, v_up):
// orbit the eye around the reference point, pan both across the view, zoom
// toward the reference point. They take a manual camera (the viewer
// materializes an auto one first, so a move starts from what auto chose) and
// mouse distances in window coordinates (x right, y down).
#include <glm/vec2.hpp>

#include "pipeline/view_setup.h"
#include "settings/render_settings.h"

namespace facet::viewer {

// Turns the eye around P_ref: pixels.x about v_up (turntable), pixels.y
// over the top or under. A drag across the whole window height turns by
// 180°; the eye stops 1° short of v_up, where the eye matrix is undefined.
void orbit(CameraSettings& camera, glm::vec2 pixels, float windowHeight);

// Moves P_eye and P_ref together so that the point at P_ref's depth follows
// the cursor.
void pan(CameraSettings& camera, glm::vec2 pixels, float windowWidth);

// steps > 0 (wheel up) comes closer: each step takes 10% off the distance
// to P_ref (perspective) or off the width W (parallel). The eye stays at
// least minDistance from P_ref.
void zoom(CameraSettings& camera, float steps, float minDistance);

// Perspective <-> parallel, keeping the width of view at P_ref: W = 2 d tan θ
// (going to perspective moves the eye to the distance d that gives W, and N
// and F with it, as moveDepthRange does).
void toggleProjection(CameraSettings& camera, const Sphere& sphere);

// Moves N and F with the eye: when a move changes the distance from the eye
// to the scene's centre (along the line of sight) by Δ, N and F change by Δ
// too, so the scene keeps its place between them. A zoom never clips the
// scene that was whole, and a near plane set into the scene on purpose
// still cuts it at the same depth. N stays above F/1000.
void moveDepthRange(CameraSettings& camera, const CameraSettings& before, const Sphere& sphere);

}  // namespace facet::viewer
