#include "viewer/viewer_window.h"

#include <algorithm>
#include <cstdlib>
#include <string>
#include <utility>

#include <GLFW/glfw3.h>

#include "common/error.h"
#include "common/quote.h"

namespace facet::viewer {
namespace {

constexpr const char* kNoDisplayHint = " (without a display, run it under xvfb-run -a)";

// GLFW's description of its last error, e.g. "X11: Failed to open display :5".
std::string lastGlfwError(int* code = nullptr) {
  const char* description = nullptr;
  const int error = glfwGetError(&description);
  if (code) *code = error;
  return description ? description : "unknown GLFW error";
}

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "";
}

// Whether a Wayland compositor can be asked at all: libwayland needs
// WAYLAND_SOCKET, an absolute WAYLAND_DISPLAY or an absolute
// XDG_RUNTIME_DIR, and without them prints a line of its own on stderr.
bool waylandReachable() {
  return !environment("WAYLAND_SOCKET").empty() || environment("WAYLAND_DISPLAY").starts_with('/') ||
         environment("XDG_RUNTIME_DIR").starts_with('/');
}

// Chooses the window system before glfwInit. GLFW 3.4 (Debian 13) is built
// for Wayland and X11 and tries Wayland first, and libwayland prints a line
// of its own on stderr when it has no compositor to ask; 3.3 (Debian 12) is
// X11 only. Without a compositor to ask, X11 it is; with neither, there is
// no display, and facet says so itself, the same with either GLFW.
void chooseWindowSystem() {
  const bool x11 = !environment("DISPLAY").empty();
  const bool wayland = (!environment("WAYLAND_DISPLAY").empty() || !environment("WAYLAND_SOCKET").empty()) && waylandReachable();
  if (!x11 && !wayland) throw Error(std::string("view: cannot open a window: DISPLAY is not set") + kNoDisplayHint);
#if GLFW_VERSION_MAJOR > 3 || (GLFW_VERSION_MAJOR == 3 && GLFW_VERSION_MINOR >= 4)
  if (!wayland && glfwPlatformSupported(GLFW_PLATFORM_X11)) glfwInitHint(GLFW_PLATFORM, GLFW_PLATFORM_X11);
#endif
}

}  // namespace

GlfwLibrary::GlfwLibrary() {
  chooseWindowSystem();
  if (!glfwInit()) {
    const std::string display = environment("DISPLAY");
    throw Error("view: cannot open a window: cannot connect to the display" + (display.empty() ? std::string() : " " + quoteInput(display)) +
                ": " + lastGlfwError() + kNoDisplayHint);
  }
}

GlfwLibrary::~GlfwLibrary() { glfwTerminate(); }

ViewerWindow::ViewerWindow(int width, int height, int besideWidth) : appliedBeside_(besideWidth) {
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  window_ = glfwCreateWindow(width + besideWidth, height, "facet view", nullptr, nullptr);
  if (!window_) {
    int code = 0;
    const std::string glfw = lastGlfwError(&code);
    // GLFW reports a context the driver refuses as GLFW_VERSION_UNAVAILABLE,
    // with the window system's own error text, which differs between X
    // servers and GLFW releases: facet names the problem in its own words.
    if (code == GLFW_VERSION_UNAVAILABLE)
      throw Error("view: cannot create a window with an OpenGL 4.5 core context: the display's OpenGL driver does not offer OpenGL 4.5 core");
    if (code == GLFW_API_UNAVAILABLE) throw Error("view: cannot create a window with an OpenGL 4.5 core context: the display offers no OpenGL");
    throw Error("view: cannot create a window with an OpenGL 4.5 core context: " + glfw);
  }
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
