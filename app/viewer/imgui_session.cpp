#include "viewer/imgui_session.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "common/error.h"

namespace facet::viewer {

ImGuiSession::ImGuiSession(GLFWwindow* window) : window_(window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini in whatever folder facet runs in
  ImGui::StyleColorsDark();
  // Callbacks installed: ImGui chains to the window's own (the drop callback is not one ImGui takes).
  if (!ImGui_ImplGlfw_InitForOpenGL(window, true)) {
    ImGui::DestroyContext();
    throw Error("view: Dear ImGui's GLFW backend did not start");
  }
  if (!ImGui_ImplOpenGL3_Init("#version 450 core")) {
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    throw Error("view: Dear ImGui's OpenGL 3 backend did not start");
  }
}

ImGuiSession::~ImGuiSession() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void ImGuiSession::newFrame(const std::vector<KeyPress>& presses) {
  ImGuiIO& io = ImGui::GetIO();
  const auto inRange = [&](int key) { return key >= 0 && key < static_cast<int>(IM_ARRAYSIZE(io.KeysDown)); };
  for (int key : heldTaps_) io.KeysDown[key] = glfwGetKey(window_, key) == GLFW_PRESS;
  heldTaps_.clear();
  for (const KeyPress& press : presses) {
    if (!inRange(press.key) || io.KeysDown[press.key]) continue;  // still down: ImGui sees it anyway
    io.KeysDown[press.key] = true;
    heldTaps_.push_back(press.key);
  }
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void ImGuiSession::render() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace facet::viewer
