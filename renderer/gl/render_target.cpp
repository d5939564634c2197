#include "gl/render_target.h"

#include <algorithm>
#include <cstdio>

#include "common/error.h"

namespace facet::gl {
namespace {

std::string statusName(GLenum status) {
  switch (status) {
    case GL_FRAMEBUFFER_UNDEFINED: return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
    case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
    case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS: return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
    default: {
      char text[16];
      std::snprintf(text, sizeof text, "0x%04x", status);
      return text;
    }
  }
}

}  // namespace

void checkFramebufferComplete(const GlFunctions& gl, GLuint framebuffer, const std::string& what) {
  const GLenum status = gl.CheckNamedFramebufferStatus(framebuffer, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) throw Error("OpenGL: the " + what + " framebuffer is incomplete (" + statusName(status) + ")");
}

void checkSizeLimit(const GlFunctions& gl, const std::string& what, int size, GLenum limit, const char* limitName) {
  GLint values[2] = {0, 0};  // GL_MAX_VIEWPORT_DIMS has two; the smaller one bounds both sides
  gl.GetIntegerv(limit, values);
  const GLint maximum = limit == GL_MAX_VIEWPORT_DIMS ? std::min(values[0], values[1]) : values[0];
  if (size > maximum)
    throw Error(what + ": larger than this OpenGL allows (" + limitName + " " + std::to_string(maximum) + ")");
}

void RenderTarget::resize(const GlFunctions& gl, int width, int height) {
  if (framebuffer_ && width == width_ && height == height_) return;
  const std::string what = "image size " + std::to_string(width) + "x" + std::to_string(height);
  for (int side : {width, height}) {
    checkSizeLimit(gl, what, side, GL_MAX_TEXTURE_SIZE, "GL_MAX_TEXTURE_SIZE");
    checkSizeLimit(gl, what, side, GL_MAX_RENDERBUFFER_SIZE, "GL_MAX_RENDERBUFFER_SIZE");
    checkSizeLimit(gl, what, side, GL_MAX_VIEWPORT_DIMS, "GL_MAX_VIEWPORT_DIMS");
  }
  const GLenum format = colorFormat_;
  const Depth depth = depthAttached_;
  *this = RenderTarget(format, depth);
  color_ = createTexture(gl, GL_TEXTURE_2D);
  gl.TextureStorage2D(color_.id(), 1, format, width, height);
  gl.TextureParameteri(color_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl.TextureParameteri(color_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  framebuffer_ = createFramebuffer(gl);
  gl.NamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
  if (depth == Depth::With) {
    depth_ = createRenderbuffer(gl);
    gl.NamedRenderbufferStorage(depth_.id(), GL_DEPTH_COMPONENT32F, width, height);
    gl.NamedFramebufferRenderbuffer(framebuffer_.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
  }
  gl.NamedFramebufferDrawBuffer(framebuffer_.id(), GL_COLOR_ATTACHMENT0);
  gl.NamedFramebufferReadBuffer(framebuffer_.id(), GL_COLOR_ATTACHMENT0);
  checkFramebufferComplete(gl, framebuffer_.id(), format == GL_RGBA32F ? "lit pass (RGBA32F + DEPTH_COMPONENT32F)"
                                              : format == GL_RGBA8   ? (depth == Depth::With ? "lit pass encoded as drawn (RGBA8 + DEPTH_COMPONENT32F)" : "resolve (RGBA8)")
                                              : format == GL_R32UI   ? "triangle id (R32UI + DEPTH_COMPONENT32F)"
                                                                     : "fragment count (R32F + DEPTH_COMPONENT32F)");
  width_ = width;
  height_ = height;
}

void ShadowMapArray::resize(const GlFunctions& gl, int size, int layers) {
  if (texture_ && size == size_ && layers == layers_) return;
  const std::string what = "settings key 'shadows.mapSize': " + std::to_string(size);
  checkSizeLimit(gl, what, size, GL_MAX_TEXTURE_SIZE, "GL_MAX_TEXTURE_SIZE");
  checkSizeLimit(gl, what, size, GL_MAX_VIEWPORT_DIMS, "GL_MAX_VIEWPORT_DIMS");
  checkSizeLimit(gl, std::to_string(layers) + " shadow maps", layers, GL_MAX_ARRAY_TEXTURE_LAYERS, "GL_MAX_ARRAY_TEXTURE_LAYERS");
  *this = ShadowMapArray();
  texture_ = createTexture(gl, GL_TEXTURE_2D_ARRAY);
  gl.TextureStorage3D(texture_.id(), 1, GL_DEPTH_COMPONENT32F, size, size, layers);
  // Read with texelFetch and textureGather: no filtering, no depth comparison.
  gl.TextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl.TextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl.TextureParameteri(texture_.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
  // The 3×3 PCF window's gathers (shaders/lighting.glsl) read the edge texel past an edge, as a cube face's taps do.
  gl.TextureParameteri(texture_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.TextureParameteri(texture_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  framebuffer_ = createFramebuffer(gl);
  gl.NamedFramebufferDrawBuffer(framebuffer_.id(), GL_NONE);
  gl.NamedFramebufferReadBuffer(framebuffer_.id(), GL_NONE);
  size_ = size;
  layers_ = layers;
}

void ShadowMapArray::attachLayer(const GlFunctions& gl, int layer) const {
  gl.NamedFramebufferTextureLayer(framebuffer_.id(), GL_DEPTH_ATTACHMENT, texture_.id(), 0, layer);
  checkFramebufferComplete(gl, framebuffer_.id(), "shadow map (DEPTH_COMPONENT32F array layer " + std::to_string(layer) + ")");
}

}  // namespace facet::gl
