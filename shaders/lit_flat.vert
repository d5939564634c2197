#version 450 core
// Lit pass, flat shading: one illumination per triangle, from its world-space
// geometric normal normalize(cross(p1 - p0, p2 - p0)) at its centroid, V from
// the centroid, for the front and the back side (renderer/PIPELINE.md, "Shading").
//
// The mesh is drawn without indices, three vertices per triangle, and each
// vertex reads its triangle's corners from the mesh's buffers; all three
// compute the same illumination. A geometry shader would do it once, but
// with one llvmpipe maps vertices to the window in C without the fused
// multiply-add of its vertex stage, and the covered pixels would no longer be
// those of the CPU reference (renderer/PIPELINE.md, "Rasterization").
#include "frame_block.glsl"
#include "transform.glsl"
#include "shading_math.glsl"
#include "srgb.glsl"
#include "texture.glsl"
#include "procedural.glsl"
#include "draw_uniforms.glsl"
#include "environment.glsl"
#include "lighting.glsl"

layout(std430, binding = 0) readonly buffer MeshIndices { uint indices[]; };      // three per triangle
layout(std430, binding = 1) readonly buffer MeshPositions { float positions[]; }; // model space, x y z per vertex
layout(std430, binding = 2) readonly buffer MeshTexcoords { float texcoords[]; }; // TEXCOORD_0 s t per vertex (read only when textured)
layout(std430, binding = 3) readonly buffer MeshColors { float colors[]; };       // COLOR_0 r g b a per vertex (read only when coloured)
layout(std430, binding = 4) readonly buffer MeshTexcoords1 { float texcoords1[]; }; // TEXCOORD_1 s t per vertex (read only when textured)

flat out vec3 frontDiffuse;  // Illumination with N
flat out vec3 frontSpecular;
flat out vec3 backDiffuse;   // Illumination with -N, for back faces where they are not culled
flat out vec3 backSpecular;
out vec4 st;                 // a texture still varies O_d per pixel: TEXCOORD_0 in xy, TEXCOORD_1 in zw
out vec4 vertexColor;        // and so do vertex colours
out vec3 modelPoint;      // and procedural textures
#if FACET_NORMAL_OUTPUT
flat out vec3 faceNormal;    // the normals stage: N, which the fragment negates on a back face
#endif

vec3 modelPosition(uint v) {
  return vec3(positions[3u * v], positions[3u * v + 1u], positions[3u * v + 2u]);
}

vec3 worldPosition(uint v) {
  return transformPoint(worldFromModel, modelPosition(v)).xyz;
}

void main() {
  int first = gl_VertexID - gl_VertexID % 3;
  uint v = indices[gl_VertexID];
  gl_Position = transformPoint(clipFromModel, modelPosition(v));

  vec3 p0 = worldPosition(indices[first]);
  vec3 p1 = worldPosition(indices[first + 1]);
  vec3 p2 = worldPosition(indices[first + 2]);
  vec3 N = normalize3(cross3(p1 - p0, p2 - p0));
#if FACET_NORMAL_OUTPUT
  faceNormal = N;
#endif
  precise vec3 centre = (p0 + p1 + p2) / 3.0;  // the centroid (`centroid` is a GLSL keyword)
  vec3 V = viewVector(centre);
  CourseMaterial summed = summedMaterial();
  Illumination front = illuminate(summed, centre, N, V);
  Illumination back = illuminate(summed, centre, -N, V);
  frontDiffuse = front.diffuse;
  frontSpecular = front.specular;
  backDiffuse = back.diffuse;
  backSpecular = back.specular;
#if FACET_TEXTURED || FACET_EMISSIVE_MAP
  // Both sets; a set the mesh lacks reads whatever is bound in its place, and no map of the draw reads it.
  st = vec4(texcoords[2u * v], texcoords[2u * v + 1u], texcoords1[2u * v], texcoords1[2u * v + 1u]);
#else
  st = vec4(0.0);
#endif
  modelPoint = modelPosition(v);
#if FACET_COLORED
  vertexColor = vec4(colors[4u * v], colors[4u * v + 1u], colors[4u * v + 2u], colors[4u * v + 3u]);
#else
  vertexColor = vec4(1.0);
#endif
}
