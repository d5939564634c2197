#pragma once
// The OpenGL 4.5 core functions facet calls, as a table of function pointers
// filled from the current context's getProcAddress. facet keeps its own table
// because GLEW and libepoxy cannot load from an OSMesa context, and because
// the gl* symbols libOSMesa exports lack the 4.5 entry points (glClipControl,
// the direct-state-access functions).
#include <string>

#include <GL/glcorearb.h>

#include "gl/get_proc_address.h"

namespace facet::gl {

// X(type, name) for every function in the table, alphabetically.
#define FACET_GL_FUNCTIONS(X)                                                 \
  X(PFNGLATTACHSHADERPROC, glAttachShader)                                    \
  X(PFNGLBINDBUFFERBASEPROC, glBindBufferBase)                                \
  X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                              \
  X(PFNGLBINDTEXTUREUNITPROC, glBindTextureUnit)                              \
  X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                              \
  X(PFNGLBLENDEQUATIONPROC, glBlendEquation)                                  \
  X(PFNGLBLENDFUNCPROC, glBlendFunc)                                          \
  X(PFNGLBLENDFUNCSEPARATEPROC, glBlendFuncSeparate)                          \
  X(PFNGLBLITNAMEDFRAMEBUFFERPROC, glBlitNamedFramebuffer)                    \
  X(PFNGLCHECKNAMEDFRAMEBUFFERSTATUSPROC, glCheckNamedFramebufferStatus)      \
  X(PFNGLCLEARNAMEDFRAMEBUFFERFVPROC, glClearNamedFramebufferfv)              \
  X(PFNGLCLEARNAMEDFRAMEBUFFERUIVPROC, glClearNamedFramebufferuiv)            \
  X(PFNGLCLIPCONTROLPROC, glClipControl)                                      \
  X(PFNGLCOMPILESHADERPROC, glCompileShader)                                  \
  X(PFNGLCREATEBUFFERSPROC, glCreateBuffers)                                  \
  X(PFNGLCREATEFRAMEBUFFERSPROC, glCreateFramebuffers)                        \
  X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                                  \
  X(PFNGLCREATERENDERBUFFERSPROC, glCreateRenderbuffers)                      \
  X(PFNGLCREATESHADERPROC, glCreateShader)                                    \
  X(PFNGLCREATETEXTURESPROC, glCreateTextures)                                \
  X(PFNGLCREATEVERTEXARRAYSPROC, glCreateVertexArrays)                        \
  X(PFNGLCULLFACEPROC, glCullFace)                                            \
  X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                                  \
  X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)                        \
  X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                                  \
  X(PFNGLDELETERENDERBUFFERSPROC, glDeleteRenderbuffers)                      \
  X(PFNGLDELETESHADERPROC, glDeleteShader)                                    \
  X(PFNGLDELETETEXTURESPROC, glDeleteTextures)                                \
  X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)                        \
  X(PFNGLDEPTHFUNCPROC, glDepthFunc)                                          \
  X(PFNGLDEPTHMASKPROC, glDepthMask)                                          \
  X(PFNGLDISABLEPROC, glDisable)                                              \
  X(PFNGLDRAWARRAYSPROC, glDrawArrays)                                        \
  X(PFNGLDRAWELEMENTSPROC, glDrawElements)                                    \
  X(PFNGLENABLEPROC, glEnable)                                                \
  X(PFNGLENABLEVERTEXARRAYATTRIBPROC, glEnableVertexArrayAttrib)              \
  X(PFNGLFINISHPROC, glFinish)                                                \
  X(PFNGLFRONTFACEPROC, glFrontFace)                                          \
  X(PFNGLGETACTIVEUNIFORMBLOCKIVPROC, glGetActiveUniformBlockiv)              \
  X(PFNGLGETACTIVEUNIFORMSIVPROC, glGetActiveUniformsiv)                      \
  X(PFNGLGETERRORPROC, glGetError)                                            \
  X(PFNGLGETINTEGERVPROC, glGetIntegerv)                                      \
  X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)                          \
  X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                                    \
  X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                            \
  X(PFNGLGETSHADERIVPROC, glGetShaderiv)                                      \
  X(PFNGLGETSTRINGPROC, glGetString)                                          \
  X(PFNGLGETTEXTURESUBIMAGEPROC, glGetTextureSubImage)                        \
  X(PFNGLGETUNIFORMBLOCKINDEXPROC, glGetUniformBlockIndex)                    \
  X(PFNGLGETUNIFORMINDICESPROC, glGetUniformIndices)                          \
  X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)                        \
  X(PFNGLLINKPROGRAMPROC, glLinkProgram)                                      \
  X(PFNGLNAMEDBUFFERSTORAGEPROC, glNamedBufferStorage)                        \
  X(PFNGLNAMEDBUFFERSUBDATAPROC, glNamedBufferSubData)                        \
  X(PFNGLNAMEDFRAMEBUFFERDRAWBUFFERPROC, glNamedFramebufferDrawBuffer)        \
  X(PFNGLNAMEDFRAMEBUFFERREADBUFFERPROC, glNamedFramebufferReadBuffer)        \
  X(PFNGLNAMEDFRAMEBUFFERDRAWBUFFERSPROC, glNamedFramebufferDrawBuffers)      \
  X(PFNGLNAMEDFRAMEBUFFERRENDERBUFFERPROC, glNamedFramebufferRenderbuffer)    \
  X(PFNGLNAMEDFRAMEBUFFERTEXTURELAYERPROC, glNamedFramebufferTextureLayer)    \
  X(PFNGLNAMEDFRAMEBUFFERTEXTUREPROC, glNamedFramebufferTexture)              \
  X(PFNGLNAMEDRENDERBUFFERSTORAGEPROC, glNamedRenderbufferStorage)            \
  X(PFNGLNAMEDRENDERBUFFERSTORAGEMULTISAMPLEPROC, glNamedRenderbufferStorageMultisample) \
  X(PFNGLPIXELSTOREIPROC, glPixelStorei)                                      \
  X(PFNGLPROGRAMUNIFORM1FPROC, glProgramUniform1f)                            \
  X(PFNGLPROGRAMUNIFORM1IPROC, glProgramUniform1i)                            \
  X(PFNGLPROGRAMUNIFORM3IPROC, glProgramUniform3i)                            \
  X(PFNGLPROGRAMUNIFORM4IPROC, glProgramUniform4i)                            \
  X(PFNGLPROGRAMUNIFORM2FPROC, glProgramUniform2f)                            \
  X(PFNGLPROGRAMUNIFORM1UIPROC, glProgramUniform1ui)                          \
  X(PFNGLPROGRAMUNIFORM3FVPROC, glProgramUniform3fv)                          \
  X(PFNGLPROGRAMUNIFORM4FVPROC, glProgramUniform4fv)                          \
  X(PFNGLPROGRAMUNIFORMMATRIX3FVPROC, glProgramUniformMatrix3fv)              \
  X(PFNGLPROGRAMUNIFORMMATRIX4FVPROC, glProgramUniformMatrix4fv)              \
  X(PFNGLREADPIXELSPROC, glReadPixels)                                        \
  X(PFNGLSHADERSOURCEPROC, glShaderSource)                                    \
  X(PFNGLTEXTUREPARAMETERIPROC, glTextureParameteri)                          \
  X(PFNGLTEXTURESTORAGE2DPROC, glTextureStorage2D)                            \
  X(PFNGLTEXTURESTORAGE3DPROC, glTextureStorage3D)                            \
  X(PFNGLTEXTURESUBIMAGE2DPROC, glTextureSubImage2D)                          \
  X(PFNGLUSEPROGRAMPROC, glUseProgram)                                        \
  X(PFNGLVERTEXARRAYATTRIBBINDINGPROC, glVertexArrayAttribBinding)            \
  X(PFNGLVERTEXARRAYATTRIBFORMATPROC, glVertexArrayAttribFormat)              \
  X(PFNGLVERTEXARRAYELEMENTBUFFERPROC, glVertexArrayElementBuffer)            \
  X(PFNGLVERTEXARRAYVERTEXBUFFERPROC, glVertexArrayVertexBuffer)              \
  X(PFNGLVIEWPORTPROC, glViewport)

// Called as gl.glClipControl(...): the names are OpenGL's, so that the
// reference pages can be grepped for them.
struct GlFunctions {
#define FACET_GL_DECLARE(type, name) type name = nullptr;
  FACET_GL_FUNCTIONS(FACET_GL_DECLARE)
#undef FACET_GL_DECLARE
};

// Fills the table through `getProcAddress` with a context current. Throws
// facet::Error when a function is missing or the context is older than
// OpenGL 4.5 (getProcAddress of OSMesa and EGL returns stubs even for names
// a driver lacks, so the version is what proves support).
GlFunctions loadGlFunctions(const GetProcAddress& getProcAddress);

// GL_RENDERER and GL_VERSION: "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6".
std::string rendererAndVersion(const GlFunctions& gl);

// One glGetIntegerv value.
GLint getInteger(const GlFunctions& gl, GLenum name);

// Throws facet::Error "<who>OpenGL error 0x0502 in <where>" when the context
// has an error flag set, after clearing every flag.
void checkGlError(const GlFunctions& gl, const char* where, const std::string& who = "");

}  // namespace facet::gl
