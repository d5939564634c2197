#pragma once
// The offscreen framebuffers a frame renders into, and the checks every
// framebuffer passes before drawing.
#include <string>

#include "gl/gl_object.h"

namespace facet::gl {

// Throws facet::Error naming `what` and the status when the framebuffer is not complete.
void checkFramebufferComplete(const GlFunctions& gl, GLuint framebuffer, const std::string& what);

// Throws facet::Error when `size` exceeds the GL limit `limitName` (e.g. GL_MAX_TEXTURE_SIZE).
void checkSizeLimit(const GlFunctions& gl, const std::string& what, int size, GLenum limit, const char* limitName);

// A W×H framebuffer of one colour texture and, unless it is a resolve's
// target, GL_DEPTH_COMPONENT32F depth: the lit pass's linear colours
// (GL_RGBA32F), the resolved image (GL_RGBA8, no depth), the image a lit
// pass encodes as it draws (GL_RGBA8), the triangle ids (GL_R32UI) and the
// fragment counts (GL_R32F).
class RenderTarget {
 public:
  enum class Depth { With, Without };
  explicit RenderTarget(GLenum colorFormat, Depth depth = Depth::With) : colorFormat_(colorFormat), depthAttached_(depth) {}
  // Reallocates when the size changes. Throws facet::Error beyond the
  // driver's limits or when the framebuffer is incomplete.
  void resize(const GlFunctions& gl, int width, int height);

  GLuint framebuffer() const { return framebuffer_.id(); }
  GLuint colorTexture() const { return color_.id(); }  // read with texelFetch: no filtering, one level
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  GLenum colorFormat_;
  Depth depthAttached_;
  GlObject color_, depth_, framebuffer_;
  int width_ = 0, height_ = 0;
};

// Pass 1's target: a GL_TEXTURE_2D_ARRAY of S×S GL_DEPTH_COMPONENT32F layers,
// one per light face, each drawn through a depth-only framebuffer.
class ShadowMapArray {
 public:
  // Reallocates when S or the layer count changes; throws facet::Error beyond the driver's limits.
  void resize(const GlFunctions& gl, int size, int layers);
  // Attaches `layer` as the framebuffer's depth; throws facet::Error when incomplete.
  void attachLayer(const GlFunctions& gl, int layer) const;

  GLuint texture() const { return texture_.id(); }
  GLuint framebuffer() const { return framebuffer_.id(); }
  int size() const { return size_; }

 private:
  GlObject texture_, framebuffer_;
  int size_ = 0, layers_ = 0;
};

}  // namespace facet::gl
