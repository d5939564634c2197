// The per-frame uniform block. Its C++ mirror, byte for byte in std140, is
// renderer/gl/frame_block.h (static_asserted, and checked against the
// driver's offsets in tests/gl). Filled from FrameInputs only. What the
// program is specialized on (light count and kinds, which lights have maps,
// the specular model, the PCF radius: renderer/gl/shader_variant.cpp) is not
// in the block: each setting reaches the shaders once.
// FACET_MAX_LIGHTS is facet::kMaxLights, defined for every program (renderer/gl/shader_program.cpp).
const int kLightPoint = 0;
const int kLightDirectional = 1;
const int kLightSpot = 2;

struct LightData {
  vec4 position;            // xyz: world position (point, spot)
  vec4 directionCosCutoff;  // xyz: world direction, unit; w: cos β (spot)
  vec4 intensity;           // rgb: I_p = colour · intensity
  vec4 attenuation;         // xyz: c1, c2, c3
  ivec4 shadow;             // x: the first layer of its faces in shadowMaps
  mat4 shadowFromWorld[6];  // per face: world -> shadow-map (u, v, z) after the divide
};

layout(std140, binding = 0) uniform Frame {
  vec4 eyePosition;         // xyz: P_eye; w: 1 perspective, 0 parallel
  vec4 towardEye;           // xyz: -k, V under parallel projection
  vec4 ambient;             // x: I_a; y: k, the procedural texture's cells per model unit; z: k of the bump map
  vec4 shadowParams;        // x: b_slope; y: b_min; z: map size S
  vec4 background;          // rgb: linear background
  LightData lights[FACET_MAX_LIGHTS];
  vec4 environment;         // x: k_r; y: 1 with a map; z: 1 when empty pixels show it; w: its last mip level
  vec4 backgroundForward;   // xyz: F, of D = (F + x·X) + y·Y at NDC (x, y)
  vec4 backgroundRight;     // xyz: X
  vec4 backgroundUp;        // xyz: Y
  vec4 irradiance[9];       // rgb: the map's E(N)/π coefficients (shading=pbr)
  vec4 fog;                 // x: start; y: end; z: density; w: cot θ (fog.glsl)
  vec4 fogColor;            // rgb: C_fog, linear
  vec4 fogRange;            // x: N, y: F (parallel projection's eye depth)
} frame;

// The course material of the draw being shaded (uniforms set per draw).
struct CourseMaterial {
  vec3 emissive;   // k_e
  float ka;
  float kd;
  float ks;
  float shininess; // n
  float metallic;  // m in O_s = (1 - m) + m·O_d
  float roughness; // r (shading=pbr)
};
