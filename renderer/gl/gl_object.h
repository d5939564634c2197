#pragma once
// Ownership of OpenGL object names: each GlObject deletes its name with the
// matching glDelete* when it goes, so that an exception halfway through a
// frame leaks nothing. The function table must outlive the objects.
#include <utility>

#include "gl/gl_functions.h"

namespace facet::gl {

class GlObject {
 public:
  using Deleter = void (*)(const GlFunctions& gl, GLuint id);

  GlObject() = default;
  GlObject(const GlFunctions& gl, GLuint id, Deleter deleter) : gl_(&gl), id_(id), deleter_(deleter) {}
  GlObject(GlObject&& other) noexcept { swap(other); }
  GlObject& operator=(GlObject&& other) noexcept {
    GlObject(std::move(other)).swap(*this);
    return *this;
  }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;
  ~GlObject() {
    if (id_ != 0) deleter_(*gl_, id_);
  }

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }

 private:
  void swap(GlObject& other) noexcept {
    std::swap(gl_, other.gl_);
    std::swap(id_, other.id_);
    std::swap(deleter_, other.deleter_);
  }

  const GlFunctions* gl_ = nullptr;
  GLuint id_ = 0;
  Deleter deleter_ = nullptr;
};

// glCreate* with the matching glDelete*.
GlObject createBuffer(const GlFunctions& gl);
GlObject createVertexArray(const GlFunctions& gl);
GlObject createTexture(const GlFunctions& gl, GLenum target);
GlObject createFramebuffer(const GlFunctions& gl);
GlObject createRenderbuffer(const GlFunctions& gl);

}  // namespace facet::gl
