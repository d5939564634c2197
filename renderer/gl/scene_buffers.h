#pragma once
// A scene's meshes and base colour textures in OpenGL buffers and textures,
// uploaded once per scene and drawn by every frame of it.
#include <vector>

#include "gl/gl_object.h"
#include "scene/scene.h"

namespace facet::gl {

// Vertex attribute locations of the lit and shadow vertex shaders.
inline constexpr GLuint kPositionAttribute = 0;  // vec3, model space
inline constexpr GLuint kNormalAttribute = 1;    // vec3, model space
inline constexpr GLuint kTexcoordAttribute = 2;  // vec2, TEXCOORD_0
inline constexpr GLuint kColorAttribute = 3;     // vec4, COLOR_0 (linear RGBA)
inline constexpr GLuint kTangentAttribute = 4;   // vec4, TANGENT (xyz unit, w ±1); (0, 0, 0, 1) when the mesh has none
inline constexpr GLuint kTexcoord1Attribute = 5; // vec2, TEXCOORD_1

struct MeshBuffers {
  GlObject positions;    // x y z per vertex; also read as a storage buffer by lit_flat.vert
  GlObject normals;
  GlObject texcoords;    // none when the mesh has no TEXCOORD_0; also a storage buffer for lit_flat.vert
  GlObject texcoords1;   // none when the mesh has no TEXCOORD_1; also a storage buffer for lit_flat.vert
  GlObject colors;       // none when the mesh has no COLOR_0; also a storage buffer for lit_flat.vert
  GlObject tangents;     // none when the mesh has no tangents
  GlObject indices;      // three per triangle; also a storage buffer for lit_flat.vert
  GlObject vertexArray;  // the attributes above and the index buffer
  GLsizei indexCount = 0;  // whole triangles only
  Bounds bounds;           // of the positions, model space: pass 1 skips a face's draw that cannot reach it (pipeline/clip_volume.h)
  GlObject lineIndices, pointIndices;          // two per segment, one per point
  GlObject lineVertexArray, pointVertexArray;  // the attributes with those as index buffers
  GLsizei lineIndexCount = 0, pointCount = 0;
  // Whether texture coordinate set `set` (1: TEXCOORD_1, else TEXCOORD_0) was uploaded.
  bool hasSet(int set) const { return static_cast<bool>(set == 1 ? texcoords1 : texcoords); }
};

class SceneBuffers {
 public:
  SceneBuffers() = default;
  // A mesh that checkScene would refuse (normals that do not match its
  // positions) is left empty; checkFrame keeps any frame from drawing it.
  SceneBuffers(const GlFunctions& gl, const Scene& scene);

  // Throw facet::Error for an index the uploaded scene does not have.
  const MeshBuffers& mesh(int index) const;
  GLuint texture(int index) const;
  // The scene's environment cube strip (GL_RGBA8UI, with its mips); 0 when it has none.
  GLuint environment() const { return environment_ ? environment_.id() : 0; }
  // The scene's bump map (GL_RGBA8UI, level 0); 0 when it has none.
  GLuint bumpMap() const { return bumpMap_ ? bumpMap_.id() : 0; }

 private:
  std::vector<MeshBuffers> meshes_;
  std::vector<GlObject> textures_;  // GL_RGBA8UI: the sRGB-encoded bytes as stored, bottom row first
  GlObject environment_;
  GlObject bumpMap_;
};

}  // namespace facet::gl
