#include "gl/scene_buffers.h"

#include <string>

#include "common/error.h"
#include "pipeline/clip_volume.h"

namespace facet::gl {
namespace {

template <typename T>
GlObject uploadBuffer(const GlFunctions& gl, const std::vector<T>& data) {
  GlObject buffer = createBuffer(gl);
  gl.NamedBufferStorage(buffer.id(), static_cast<GLsizeiptr>(data.size() * sizeof(T)), data.data(), 0);
  return buffer;
}

void addAttribute(const GlFunctions& gl, GLuint vertexArray, GLuint location, const GlObject& buffer, GLint components) {
  gl.VertexArrayVertexBuffer(vertexArray, location, buffer.id(), 0, components * static_cast<GLsizei>(sizeof(float)));
  gl.VertexArrayAttribFormat(vertexArray, location, components, GL_FLOAT, GL_FALSE, 0);
  gl.VertexArrayAttribBinding(vertexArray, location, location);
  gl.EnableVertexArrayAttrib(vertexArray, location);
}

// A vertex array with the mesh's attributes and `indices` as its index buffer.
GlObject attributeArray(const GlFunctions& gl, const MeshBuffers& buffers, const GlObject& indices) {
  GlObject array = createVertexArray(gl);
  const GLuint vao = array.id();
  addAttribute(gl, vao, kPositionAttribute, buffers.positions, 3);
  addAttribute(gl, vao, kNormalAttribute, buffers.normals, 3);
  if (buffers.texcoords) addAttribute(gl, vao, kTexcoordAttribute, buffers.texcoords, 2);
  if (buffers.texcoords1) addAttribute(gl, vao, kTexcoord1Attribute, buffers.texcoords1, 2);
  if (buffers.colors) addAttribute(gl, vao, kColorAttribute, buffers.colors, 4);
  if (buffers.tangents) addAttribute(gl, vao, kTangentAttribute, buffers.tangents, 4);
  gl.VertexArrayElementBuffer(vao, indices.id());
  return array;
}

MeshBuffers uploadMesh(const GlFunctions& gl, const Mesh& mesh) {
  MeshBuffers buffers;
  const auto triangles = static_cast<GLsizei>(mesh.indices.size() / 3 * 3), segments = static_cast<GLsizei>(mesh.lines.size() / 2 * 2),
             points = static_cast<GLsizei>(mesh.points.size());
  if ((triangles == 0 && segments == 0 && points == 0) || mesh.positions.empty()) return buffers;  // nothing to draw; GL refuses empty storage
  if (mesh.normals.size() != mesh.positions.size()) return {};  // checkScene refuses it; no frame draws it
  buffers.positions = uploadBuffer(gl, mesh.positions);
  buffers.bounds = meshBounds(mesh);
  buffers.normals = uploadBuffer(gl, mesh.normals);
  if (mesh.texcoords.size() == mesh.positions.size()) buffers.texcoords = uploadBuffer(gl, mesh.texcoords);
  if (mesh.texcoords1.size() == mesh.positions.size()) buffers.texcoords1 = uploadBuffer(gl, mesh.texcoords1);
  if (mesh.colors.size() == mesh.positions.size()) buffers.colors = uploadBuffer(gl, mesh.colors);
  if (mesh.tangents.size() == mesh.positions.size()) buffers.tangents = uploadBuffer(gl, mesh.tangents);
  if (triangles) {
    buffers.indexCount = triangles;
    buffers.indices = uploadBuffer(gl, mesh.indices);
    buffers.vertexArray = attributeArray(gl, buffers, buffers.indices);
  }
  if (segments) {
    buffers.lineIndexCount = segments;
    buffers.lineIndices = uploadBuffer(gl, mesh.lines);
    buffers.lineVertexArray = attributeArray(gl, buffers, buffers.lineIndices);
  }
  if (points) {
    buffers.pointCount = points;
    buffers.pointIndices = uploadBuffer(gl, mesh.points);
    buffers.pointVertexArray = attributeArray(gl, buffers, buffers.pointIndices);
  }
  return buffers;
}

// Level 0 and the levels below it (image/mipmap.h), uploaded as they are: both backends read the same bytes.
GlObject uploadTexture(const GlFunctions& gl, const Image& image, const std::vector<Image>& mips) {
  if (image.empty()) return {};
  // Unsigned integer texels: the shader turns bytes into [0,1] itself (shaders/texture.glsl says why).
  GlObject object = createTexture(gl, GL_TEXTURE_2D);
  gl.TextureStorage2D(object.id(), 1 + static_cast<GLsizei>(mips.size()), GL_RGBA8UI, image.width(), image.height());
  // Read with texelFetch only; integer textures are complete only with NEAREST filters.
  gl.TextureParameteri(object.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  gl.TextureParameteri(object.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  for (std::size_t k = 0; k <= mips.size(); ++k) {
    const Image& level = k == 0 ? image : mips[k - 1];
    gl.TextureSubImage2D(object.id(), static_cast<GLint>(k), 0, 0, level.width(), level.height(), GL_RGBA_INTEGER, GL_UNSIGNED_BYTE, level.data());
  }
  return object;
}

}  // namespace

SceneBuffers::SceneBuffers(const GlFunctions& gl, const Scene& scene) {
  static_assert(sizeof(glm::vec4) == 4 * sizeof(float) && sizeof(glm::vec3) == 3 * sizeof(float) && sizeof(glm::vec2) == 2 * sizeof(float) &&
                sizeof(Rgba8) == 4);
  meshes_.reserve(scene.meshes.size());
  for (const Mesh& mesh : scene.meshes) meshes_.push_back(uploadMesh(gl, mesh));
  textures_.reserve(scene.textures.size());
  for (const Texture& texture : scene.textures) textures_.push_back(uploadTexture(gl, texture.image, texture.mips));
  if (!scene.environment.empty()) {
    // Level k of the strip is 6·max(1, N >> k) wide, within the 6N >> k that storage allots it.
    environment_ = uploadTexture(gl, scene.environment.faces, scene.environment.mips);
  }
  if (!scene.bumpMap.image.empty()) bumpMap_ = uploadTexture(gl, scene.bumpMap.image, {});  // read at level 0 only
}

const MeshBuffers& SceneBuffers::mesh(int index) const {
  if (index < 0 || static_cast<std::size_t>(index) >= meshes_.size())
    throw Error("OpenGL backend: the frame draws mesh " + std::to_string(index) + " but the uploaded scene has " +
                std::to_string(meshes_.size()));
  return meshes_[static_cast<std::size_t>(index)];
}

GLuint SceneBuffers::texture(int index) const {
  if (index < 0 || static_cast<std::size_t>(index) >= textures_.size() || !textures_[static_cast<std::size_t>(index)])
    throw Error("OpenGL backend: texture " + std::to_string(index) + " is missing or empty in the uploaded scene");
  return textures_[static_cast<std::size_t>(index)].id();
}

}  // namespace facet::gl
