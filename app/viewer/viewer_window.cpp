#include "viewer/viewer_window.h"

#include <algorithm>
#include <utility>

#include <GLFW/glfw3.h>

#include "common/error.h"

namespace facet::viewer {
namespace {

// GLFW's description of its last error, e.g. "X11: The DISPLAY environment variable is missing".
std::string lastGlfwError() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown GLFW error";
}

}  // namespace

GlfwLibrary::GlfwLibrary() {
  if (!glfwInit()) throw Error("view: cannot open a window: " + lastGlfwError() + " (without a display, run it under xvfb-run -a)");
}

GlfwLibrary::~GlfwLibrary() { glfwTerminate(); }

ViewerWindow::ViewerWindow(int width, int height, int besideWidth) : appliedBeside_(besideWidth) {
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  window_ = glfwCreateWindow(width + besideWidth, height, "facet view", nullptr, nullptr);
  if (!window_) throw Error("view: cannot create a window with an OpenGL 4.5 core context: " + lastGlfwError());
  glfwMakeContextCurrent(window_);
  glfwSetWindowUserPointer(window_, this);
  glfwSetDropCallback(window_, [](GLFWwindow* window, int count, const char** paths) {
    auto* self = static_cast<ViewerWindow*>(glfwGetWindowUserPointer(window));
    for (int i = 0; i < count; ++i) self->dropped_.emplace_back(paths[i]);
  });
  glfwSetKeyCallback(window_, [](GLFWwindow* window, int key, int, int action, int mods) {
    if (action == GLFW_PRESS) static_cast<ViewerWindow*>(glfwGetWindowUserPointer(window))->pressed_.push_back({key, mods});
  });
  // Ask for exactly width × height of framebuffer, where the window system scales.
  int framebufferWidth = 0, framebufferHeight = 0;
  framebufferSize(framebufferWidth, framebufferHeight);
  if (framebufferWidth != width + besideWidth || framebufferHeight != height) {
    appliedWidth_ = appliedHeight_ = -1;  // syncImageSize resizes on its first call
  } else {
    appliedWidth_ = width;
    appliedHeight_ = height;
  }
}

ViewerWindow::~ViewerWindow() { glfwDestroyWindow(window_); }

std::vector<std::string> ViewerWindow::takeDroppedPaths() { return std::exchange(dropped_, {}); }

std::vector<KeyPress> ViewerWindow::takePressedKeys() { return std::exchange(pressed_, {}); }

void ViewerWindow::setTitle(const std::string& title) {
  if (title == title_) return;
  glfwSetWindowTitle(window_, title.c_str());
  title_ = title;
}

void ViewerWindow::framebufferSize(int& width, int& height) const { glfwGetFramebufferSize(window_, &width, &height); }

void ViewerWindow::setMinimumSize(int width, int height) {
  minimumWidth_ = width;
  minimumHeight_ = height;
  glfwSetWindowSizeLimits(window_, width, height, GLFW_DONT_CARE, GLFW_DONT_CARE);  // for a window manager's resizes
}

void ViewerWindow::syncImageSize(int& width, int& height, int besideWidth, bool editing) {
  int framebufferWidth = 0, framebufferHeight = 0;
  framebufferSize(framebufferWidth, framebufferHeight);
  if (framebufferWidth == 0 || framebufferHeight == 0) return;  // minimized: keep the size for when it comes back
  const int left = std::max(1, framebufferWidth - besideWidth);  // what the window leaves the image
  if (besideWidth != appliedBeside_ && appliedWidth_ >= 0) {
    appliedBeside_ = besideWidth;
    width = appliedWidth_ = left;
    height = appliedHeight_ = framebufferHeight;
  } else if (width != appliedWidth_ || height != appliedHeight_) {
    if (editing) return;
    // Window sizes are in screen coordinates; the image is in framebuffer pixels.
    int windowWidth = 0, windowHeight = 0;
    glfwGetWindowSize(window_, &windowWidth, &windowHeight);
    const double scaleX = static_cast<double>(framebufferWidth) / windowWidth;
    const double scaleY = static_cast<double>(framebufferHeight) / windowHeight;
    // Clamped here too: without a window manager, X applies any size asked for.
    glfwSetWindowSize(window_, std::max(static_cast<int>((width + besideWidth) / scaleX + 0.5), minimumWidth_),
                      std::max(static_cast<int>(height / scaleY + 0.5), minimumHeight_));
    appliedWidth_ = width;
    appliedHeight_ = height;
    appliedBeside_ = besideWidth;
  } else if (left != width || framebufferHeight != height) {
    width = appliedWidth_ = left;
    height = appliedHeight_ = framebufferHeight;
  }
}

}  // namespace facet::viewer
