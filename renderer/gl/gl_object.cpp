#include "gl/gl_object.h"

namespace facet::gl {

GlObject createBuffer(const GlFunctions& gl) {
  GLuint id = 0;
  gl.CreateBuffers(1, &id);
  return {gl, id, [](const GlFunctions& f, GLuint name) { f.DeleteBuffers(1, &name); }};
}

GlObject createVertexArray(const GlFunctions& gl) {
  GLuint id = 0;
  gl.CreateVertexArrays(1, &id);
  return {gl, id, [](const GlFunctions& f, GLuint name) { f.DeleteVertexArrays(1, &name); }};
}

GlObject createTexture(const GlFunctions& gl, GLenum target) {
  GLuint id = 0;
  gl.CreateTextures(target, 1, &id);
  return {gl, id, [](const GlFunctions& f, GLuint name) { f.DeleteTextures(1, &name); }};
}

GlObject createFramebuffer(const GlFunctions& gl) {
  GLuint id = 0;
  gl.CreateFramebuffers(1, &id);
  return {gl, id, [](const GlFunctions& f, GLuint name) { f.DeleteFramebuffers(1, &name); }};
}

GlObject createRenderbuffer(const GlFunctions& gl) {
  GLuint id = 0;
  gl.CreateRenderbuffers(1, &id);
  return {gl, id, [](const GlFunctions& f, GLuint name) { f.DeleteRenderbuffers(1, &name); }};
}

}  // namespace facet::gl
