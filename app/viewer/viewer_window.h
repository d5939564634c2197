#pragma once
// GLFW for the viewer: the library, and one window with an OpenGL 4.5 core
// context, current on the thread that made it. Failures (no display, no
// OpenGL 4.5) throw facet::Error naming the problem in facet's words.
#include <string>
#include <vector>

struct GLFWwindow;

namespace facet::viewer {

class GlfwLibrary {
 public:
  GlfwLibrary();   // glfwInit
  ~GlfwLibrary();  // glfwTerminate
  GlfwLibrary(const GlfwLibrary&) = delete;
  GlfwLibrary& operator=(const GlfwLibrary&) = delete;
};

// A key that went down, with the modifiers held (GLFW_MOD_*).
struct KeyPress {
  int key = 0;   // GLFW_KEY_*
  int mods = 0;
};

class ViewerWindow {
 public:
  // An image of width × height pixels beside a panel besideWidth pixels
  // wide: a framebuffer of (width + besideWidth) × height (on a display that
  // scales, the window's own size follows from it).
  ViewerWindow(int width, int height, int besideWidth);
  ~ViewerWindow();
  ViewerWindow(const ViewerWindow&) = delete;  // GLFW keeps a pointer to it
  ViewerWindow& operator=(const ViewerWindow&) = delete;

  GLFWwindow* handle() const { return window_; }

  // Sets the title bar's text when it changed.
  void setTitle(const std::string& title);

  // Files dropped on the window since the last call, in order.
  std::vector<std::string> takeDroppedPaths();

  // Keys pressed since the last call, in order. Queued here because a frame
  // of llvmpipe can outlast a key tap: Dear ImGui 1.86 keeps only whether a
  // key is down at the start of a frame, and would miss a press and release
  // that both arrive during one frame. (ImGui's own callbacks chain to this.)
  std::vector<KeyPress> takePressedKeys();

  // The framebuffer's size; 0×0 while minimized.
  void framebufferSize(int& width, int& height) const;

  // The smallest size syncImageSize gives the window, so that the panel
  // stays usable; 0 × 0 (the default) for none.
  void setMinimumSize(int width, int height);

  // Keeps the image size and the window in step, the image beside a panel
  // besideWidth pixels wide (0: hidden): when the panel's width changed
  // (shown, hidden, resized), the image takes what the window leaves; when
  // width or height differ from what was last applied (the panel's fields,
  // a settings file), resizes the window, unless editing (a value still
  // being typed or dragged: a window 1 pixel high on the way to 120 would
  // take the panel with it); otherwise, when the window's size changed,
  // sets them to what it leaves beside the panel.
  void syncImageSize(int& width, int& height, int besideWidth, bool editing);

 private:
  GLFWwindow* window_ = nullptr;
  std::vector<std::string> dropped_;
  std::vector<KeyPress> pressed_;
  int appliedWidth_ = 0, appliedHeight_ = 0;  // the image size last set on either side
  int appliedBeside_ = 0;                     // the panel's width then
  int minimumWidth_ = 0, minimumHeight_ = 0;
  std::string title_;
};

}  // namespace facet::viewer
