#include "gl/gl_object.h"

namespace facet::gl {

GlObject createBuffer(const GlFunctions& gl) {
  GLuint id = 0;
  gl.glCreateBuffers(1, &id);
  return {gl, id, [](const GlFunctions& f, GLuint name) { f.glDeleteBuffers(1, &name); }};
}

GlObject createVertexArray(const GlFunctions& gl) {
  GLuint id = 0;
  gl.glCreateVertexArrays(1, &id);
  return {gl, id, [](const GlFunctions& f, GLuint name) { f.glDeleteVertexArrays(1, &name); }};
}

GlObject createTexture(const GlFunctions& gl, GLenum target) {
  GLuint id = 0;
  gl.glCreateTextures(target, 1, &id);
  return {gl, id, [](const GlFunctions& f, GLuint name) { f.glDeleteTextures(1, &name); }};
}

GlObject createFramebuffer(const GlFunctions& gl) {
  GLuint id = 0;
  gl.glCreateFramebuffers(1, &id);
  return {gl, id, [](const GlFunctions& f, GLuint name) { f.glDeleteFramebuffers(1, &name); }};
}

GlObject createRenderbuffer(const GlFunctions& gl) {
  GLuint id = 0;
  gl.glCreateRenderbuffers(1, &id);
  return {gl, id, [](const GlFunctions& f, GLuint name) { f.glDeleteRenderbuffers(1, &name); }};
}

}  // namespace facet::gl
