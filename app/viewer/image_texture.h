#pragma once
// A facet::Image as an OpenGL texture, for ImGui::Image and the background
// draw list. Images are stored bottom row first and uploaded as they are, so
// texture coordinate t = 0 is the bottom row: draw with kTopLeftUv and
// kBottomRightUv.
#include <cstdint>

#include <imgui.h>

#include "gl/gl_object.h"
#include "image/image.h"

namespace facet::viewer {

inline const ImVec2 kTopLeftUv{0.0f, 1.0f};
inline const ImVec2 kBottomRightUv{1.0f, 0.0f};

class ImageTexture {
 public:
  // The function table must outlive the texture.
  explicit ImageTexture(const gl::GlFunctions& gl) : gl_(&gl) {}

  // Replaces the texture's pixels; reallocates when the size changes.
  void upload(const Image& image);

  bool empty() const { return !texture_; }
  int width() const { return width_; }
  int height() const { return height_; }
  // A framebuffer with the texture as its colour attachment 0, to blit from.
  unsigned framebuffer() const { return framebuffer_.id(); }
  // ImGui's opengl3 backend takes the texture name as its ImTextureID.
  ImTextureID id() const { return reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture_.id())); }

 private:
  const gl::GlFunctions* gl_;
  gl::GlObject texture_;
  gl::GlObject framebuffer_;
  int width_ = 0, height_ = 0;
};

}  // namespace facet::viewer
