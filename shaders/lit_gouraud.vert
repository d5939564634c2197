#version 450 core
// Lit pass, Gouraud shading: the illumination equation at each vertex (V and
// the shadow factor too), for the front and the back side; the rasterizer
// interpolates both and lit_gouraud.frag picks one (renderer/PIPELINE.md, "Shading").
#include "frame_block.glsl"
#include "transform.glsl"
#include "shading_math.glsl"
#include "srgb.glsl"
#include "texture.glsl"
#include "procedural.glsl"
#include "draw_uniforms.glsl"
#include "environment.glsl"
#include "lighting.glsl"

layout(location = 0) in vec3 position;  // model space
layout(location = 1) in vec3 normal;    // model space, unit length
layout(location = 2) in vec2 texcoord;  // TEXCOORD_0 (0, 0 when the mesh has none)
layout(location = 5) in vec2 texcoord1; // TEXCOORD_1 (0, 0 when the mesh has none)
layout(location = 3) in vec4 color0;    // COLOR_0, linear RGBA (read only when the mesh has it)

out vec3 frontDiffuse;   // Illumination with N
out vec3 frontSpecular;
out vec3 backDiffuse;    // Illumination with -N, for back faces where they are not culled
out vec3 backSpecular;
out vec4 st;  // TEXCOORD_0 in xy, TEXCOORD_1 in zw
out vec4 vertexColor;
out vec3 modelPoint;      // procedural textures

void main() {
  gl_Position = transformPoint(clipFromModel, position);
  vec3 P = transformPoint(worldFromModel, position).xyz;
  vec3 N = normalize3(transformDirection(normalMatrix, normal));
  vec3 V = viewVector(P);
  CourseMaterial summed = summedMaterial();
  Illumination front = illuminate(summed, P, N, V);
  Illumination back = illuminate(summed, P, -N, V);
  frontDiffuse = front.diffuse;
  frontSpecular = front.specular;
  backDiffuse = back.diffuse;
  backSpecular = back.specular;
  st = vec4(texcoord, texcoord1);
  vertexColor = color0;
  modelPoint = position;
}
