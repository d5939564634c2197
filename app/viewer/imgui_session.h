#pragma once
// Dear ImGui for one GLFW window: the context and the GLFW and OpenGL 3
// backends, set up in the constructor and shut down in reverse in the
// destructor, with the window's context current.
#include <vector>

#include "viewer/viewer_window.h"

struct GLFWwindow;

namespace facet::viewer {

class ImGuiSession {
 public:
  explicit ImGuiSession(GLFWwindow* window);  // throws facet::Error when a backend cannot start
  ~ImGuiSession();
  ImGuiSession(const ImGuiSession&) = delete;
  ImGuiSession& operator=(const ImGuiSession&) = delete;

  // Starts an ImGui frame (both backends, then ImGui::NewFrame). presses:
  // the keys pressed since the last frame. Dear ImGui 1.86 reads whether a
  // key is down once a frame, so a key pressed and released within one slow
  // frame (llvmpipe can take half a second) would never be seen: Enter would
  // not end a text field. Such a tap is held down for one frame.
  void newFrame(const std::vector<KeyPress>& presses);
  // ImGui::Render, then draws its lists into the bound framebuffer.
  void render();

 private:
  GLFWwindow* window_;
  std::vector<int> heldTaps_;  // keys held down for ImGui in the last frame
};

}  // namespace facet::viewer
