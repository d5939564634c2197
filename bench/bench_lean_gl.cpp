// facet bench's lean peer: the same triangles, matrices, lights and course
// coefficients as the other columns, drawn by the plainest OpenGL that gives
// the same picture.
//
// What it does: one interleaved vertex buffer (position, normal) and one
// index buffer per mesh, uploaded once per Scene; per frame, a depth-only
// pass into a DEPTH_COMPONENT32F array layer per shadow-map face (the
// frame's own light frusta), then one lit pass whose fragment shader
// evaluates facet's illumination equation (ambient, diffuse and specular
// with k_a, k_d, k_s, n, the metal's tinted highlight, f_att, the spot cone,
// S by PCF over the frame's (2r+1)² texels through sampler2DArrayShadow),
// into an SRGB8_ALPHA8 framebuffer that llvmpipe encodes on write (with
// anti-aliasing, multisampled with every sample shaded, or plain MSAA, as
// LeanSampling says, and a blit resolve); then glReadPixels.
//
// What it leaves to the product's backend: bit-exact transforms (plain
// GLSL `*`, no `precise`), the float colour buffer and its resolve, the
// per-triangle transparency order (blended instances are drawn in instance
// order), textures, vertex colours, emission, fog, environment and bump
// maps, PBR, flat and Gouraud shading, lines and points.
#include "bench_lean_gl.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <optional>
#include <string_view>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "common/error.h"
#include "common/stopwatch.h"
#include "gl/gl_functions.h"
#include "gl/gl_object.h"
#include "gl/headless_context.h"
#include "gl/shader_program.h"
#include "pipeline/shadow_pass_key.h"

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

constexpr GLuint kShadowMapsUnit = 0;

constexpr std::string_view kLitVertex = R"(#version 450 core
layout(location = 0) in vec3 position;  // model space
layout(location = 1) in vec3 normal;    // model space
uniform mat4 clipFromModel;
uniform mat4 worldFromModel;
uniform mat3 normalMatrix;
out vec3 worldPosition;
out vec3 worldNormal;
void main() {
  gl_Position = clipFromModel * vec4(position, 1.0);
  worldPosition = (worldFromModel * vec4(position, 1.0)).xyz;
  worldNormal = normalMatrix * normal;
}
)";

// LIGHTS (one addLight call per light, kind and first shadow layer as
// constants, so that the compiler drops what a light does not need),
// LIGHT_ARRAY, SHADOW_MATRICES, BLINN, PERSPECTIVE, PCF_SUM(c) and PCF_TAPS
// come from the program's defines (litDefines).
constexpr std::string_view kLitFragment = R"(#version 450 core
uniform vec3 lightPosition[LIGHT_ARRAY];
uniform vec4 lightDirection[LIGHT_ARRAY];    // xyz: where it shines; w: cos of the spot's cut-off
uniform vec3 lightIntensity[LIGHT_ARRAY];    // I_p
uniform vec3 lightAttenuation[LIGHT_ARRAY];  // c1, c2, c3
uniform mat4 shadowFromWorld[SHADOW_MATRICES];  // per map layer: world to the map's (u, v, z)
uniform vec2 shadowBias;                        // b_slope, b_min
uniform vec3 eye;                               // P_eye (perspective) or -k (parallel)
uniform float ambient;                          // I_a
uniform vec4 baseColor;                         // O_d, alpha
uniform vec4 coefficients;                      // k_a, k_d, k_s, n
uniform float metallic;                         // m: O_s = (1 - m) + m·O_d
layout(binding = 0) uniform sampler2DArrayShadow shadowMaps;

in vec3 worldPosition;
in vec3 worldNormal;
layout(location = 0) out vec4 color;

const int kPoint = 0, kDirectional = 1, kSpot = 2;
vec3 P, N, V, diffuse, highlights;

// The cube face of P - P_light: the axis of its largest component, ties to x, then y.
int cubeFace(vec3 d) {
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0 ? 2 : 3;
  return d.z >= 0.0 ? 4 : 5;
}

// S: the share of the PCF taps where P is not behind the map's depth (less the bias).
float shadowFactor(int i, int layer, bool cube, vec3 L) {
  int at = layer + (cube ? cubeFace(P - lightPosition[i]) : 0);
  vec4 s = shadowFromWorld[at] * vec4(P, 1.0);
  if (!(s.w > 0.0)) return 1.0;
  vec3 w = s.xyz / s.w;
  if (!(w.z <= 1.0)) return 1.0;  // beyond the far plane: lit
  float bias = max(shadowBias.x * (1.0 - dot(N, L)), shadowBias.y);
  vec4 c = vec4(w.xy, float(at), w.z - bias);
  return PCF_SUM(c) / PCF_TAPS;
}

void addLight(int i, int kind, int layer) {
  vec3 L = -lightDirection[i].xyz;
  float fAtt = 1.0;
  if (kind != kDirectional) {
    vec3 toLight = lightPosition[i] - P;
    float d = length(toLight);
    L = toLight / d;
    vec3 c = lightAttenuation[i];
    fAtt = min(1.0, 1.0 / (c.x + c.y * d + c.z * d * d));
  }
  if (kind == kSpot && !(dot(-L, lightDirection[i].xyz) > lightDirection[i].w)) return;
  float NdotL = dot(N, L);
  if (!(NdotL > 0.0)) return;
  float S = layer >= 0 ? shadowFactor(i, layer, kind == kPoint, L) : 1.0;
#if BLINN
  float spec = pow(max(dot(N, normalize(L + V)), 0.0), coefficients.w);
#else
  float spec = pow(max(dot(reflect(-L, N), V), 0.0), coefficients.w);
#endif
  float k = S * fAtt;
  diffuse += (k * coefficients.y * NdotL) * lightIntensity[i];
  highlights += (k * coefficients.z * spec) * lightIntensity[i];
}

void main() {
  P = worldPosition;
  N = normalize(worldNormal);
  if (!gl_FrontFacing) N = -N;  // two-sided lighting where a back face is drawn
#if PERSPECTIVE
  V = normalize(eye - P);
#else
  V = eye;
#endif
  diffuse = vec3(coefficients.x * ambient);
  highlights = vec3(0.0);
  LIGHTS
  vec3 Od = baseColor.rgb;
  color = vec4(Od * diffuse + ((1.0 - metallic) + metallic * Od) * highlights, baseColor.a);
}
)";

constexpr std::string_view kDepthVertex = R"(#version 450 core
layout(location = 0) in vec3 position;  // model space
uniform mat4 lightClipFromModel;
void main() {
  gl_Position = lightClipFromModel * vec4(position, 1.0);
}
)";

constexpr std::string_view kDepthFragment = R"(#version 450 core
void main() {}
)";

std::optional<std::string_view> leanShaderFile(std::string_view name) {
  if (name == "lean_lit.vert") return kLitVertex;
  if (name == "lean_lit.frag") return kLitFragment;
  if (name == "lean_depth.vert") return kDepthVertex;
  if (name == "lean_depth.frag") return kDepthFragment;
  return std::nullopt;
}

// What makes one lit program differ from another: the lights' kinds and
// shadow layers, the specular model, the projection and the PCF radius.
std::string litDefines(const FrameInputs& frame) {
  const int count = static_cast<int>(frame.lights.size());
  std::string lights;
  for (int i = 0; i < count; ++i) {
    const FrameLight& light = frame.lights[static_cast<std::size_t>(i)];
    lights += "addLight(" + std::to_string(i) + ", " + std::to_string(static_cast<int>(light.light.kind)) + ", " +
              std::to_string(light.hasShadowMap ? light.shadowLayer : -1) + "); ";
  }
  // textureOffset needs constant offsets: the taps are written out.
  const int r = frame.shadows.pcfRadius;
  std::string taps;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx)
      taps += std::string(taps.empty() ? "" : " + ") + "textureOffset(shadowMaps, c, ivec2(" + std::to_string(dx) + ", " + std::to_string(dy) + "))";
  static_assert(static_cast<int>(LightKind::Point) == 0 && static_cast<int>(LightKind::Directional) == 1 && static_cast<int>(LightKind::Spot) == 2,
                "kLitFragment's kPoint, kDirectional, kSpot");
  return "#define LIGHT_ARRAY " + std::to_string(std::max(count, 1)) + "\n#define SHADOW_MATRICES " +
         std::to_string(std::max(frame.shadowLayerCount, 1)) + "\n#define BLINN " + (frame.specular == SpecularModel::BlinnPhong ? "1" : "0") +
         "\n#define PERSPECTIVE " + (frame.perspective ? "1" : "0") + "\n#define PCF_SUM(c) (" + taps + ")\n#define PCF_TAPS " +
         std::to_string((2 * r + 1) * (2 * r + 1)) + ".0\n#define LIGHTS " + lights + "\n";
}

struct LeanMesh {
  gl::GlObject vertices;  // position, normal: six floats a vertex
  gl::GlObject indices;
  gl::GlObject vertexArray;
  GLsizei indexCount = 0;
};

struct LitProgram {
  GLint clipFromModel, worldFromModel, normalMatrix, baseColor, coefficients, metallic;
  GLint lightPosition, lightDirection, lightIntensity, lightAttenuation, shadowFromWorld, shadowBias, eye, ambient;
  gl::ShaderProgram program;  // last: the locations above are read from it before it moves in
};

struct DepthProgram {
  GLint lightClipFromModel;
  gl::ShaderProgram program;
};

// Whether an untextured material's constant alpha passes its mask: it keeps all of its fragments or none.
bool keptByMask(float alpha, float cutoff) { return alpha >= cutoff; }

class LeanGlRenderer final : public Renderer {
 public:
  explicit LeanGlRenderer(LeanSampling sampling)
      : sampling_(sampling),
        context_(gl::makeHeadlessContext(GlContextKind::OsMesa)),
        gl_(gl::loadGlFunctions([this](const char* name) { return context_->getProcAddress(name); })),
        name_(gl::rendererAndVersion(gl_)) {}

  // GL objects go while their context is current, then the context.
  ~LeanGlRenderer() override {
    try {
      context_->makeCurrent();
    } catch (...) {  // a destructor must not throw
    }
  }

  std::string description() const override {
    return "lean: " + name_ + " via " + std::string(context_->name()) + ", minimal programs" +
           (sampling_ == LeanSampling::EverySample ? "" : ", anti-aliasing by MSAA shading once a pixel");
  }

  // The image alone: the stages are facet's backends' to draw.
  RenderResult render(const Scene& scene, const FrameInputs& frame, const FrameOutputs& asked) override {
    refuseUndrawn(asked, {FrameOutput::Image});
    if (const std::string why = leanUnsupported(scene, frame); !why.empty()) throw Error("lean: no minimal program for this scene (" + why + ")");
    context_->makeCurrent();  // the gl column's context may be current
    RenderResult result;
    Clock::time_point start = Clock::now();
    if (!scene.identity.is(uploaded_)) {
      upload(scene);
      result.timings.push_back({kSceneUploadPass, millisecondsSince(start)});
      start = Clock::now();
    }
    bool compiled = false;
    const LitProgram& lit = litProgram(frame, compiled);
    if (frame.shadowLayerCount > 0 && !depth_) {
      gl::ShaderProgram program = gl::buildProgram(gl_, {"lean_depth.vert", "lean_depth.frag"}, {}, leanShaderFile);
      const GLint at = gl::uniformLocation(gl_, program, "lightClipFromModel");
      depth_.emplace(DepthProgram{at, std::move(program)});
      compiled = true;
    }
    if (compiled) {
      result.timings.push_back({kShaderCompilePass, millisecondsSince(start)});
      start = Clock::now();
    }

    gl_.ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);  // facet's projections give clip z in [0, w]
    gl_.FrontFace(GL_CCW);
    gl_.CullFace(GL_BACK);
    gl_.Enable(GL_DEPTH_TEST);
    gl_.DepthFunc(GL_LESS);
    // The maps are kept while the frame's pass 1 would draw the same ones, as the cpu and gl columns keep
    // theirs; bench forgets them before each timed frame unless --keep-shadow-maps.
    const bool kept = frame.shadowLayerCount > 0 && mapsDrawn_.matches(scene, frame);
    if (frame.shadowLayerCount > 0 && !kept) {
      mapsDrawn_ = {};
      shadowPass(frame);
      mapsDrawn_ = ShadowPassKey(scene, frame);
    }
    litPass(frame, lit);
    result.image = readImage(frame, recycledImage());
    checkError("the frame");
    result.timings.push_back({(frame.shadowLayerCount > 0 ? shadowPassName(frame, kept) + ", " : std::string()) + "lit pass and read-back",
                              millisecondsSince(start)});
    return result;
  }

  void forgetShadowMaps() override { mapsDrawn_ = {}; }

 private:
  void upload(const Scene& scene) {
    meshes_.clear();
    uploaded_.reset();
    mapsDrawn_ = {};
    std::vector<float> interleaved;
    for (const Mesh& mesh : scene.meshes) {
      LeanMesh m;
      m.indexCount = static_cast<GLsizei>(mesh.indices.size() / 3 * 3);
      if (m.indexCount > 0) {
        interleaved.resize(6 * mesh.positions.size());
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
          std::copy_n(glm::value_ptr(mesh.positions[v]), 3, interleaved.data() + 6 * v);
          std::copy_n(glm::value_ptr(mesh.normals[v]), 3, interleaved.data() + 6 * v + 3);
        }
        m.vertices = gl::createBuffer(gl_);
        gl_.NamedBufferStorage(m.vertices.id(), static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)), interleaved.data(), 0);
        m.indices = gl::createBuffer(gl_);
        gl_.NamedBufferStorage(m.indices.id(), static_cast<GLsizeiptr>(m.indexCount) * static_cast<GLsizeiptr>(sizeof(std::uint32_t)),
                                 mesh.indices.data(), 0);
        m.vertexArray = gl::createVertexArray(gl_);
        const GLuint vao = m.vertexArray.id();
        gl_.VertexArrayVertexBuffer(vao, 0, m.vertices.id(), 0, 6 * sizeof(float));
        for (GLuint attribute : {0u, 1u}) {
          gl_.EnableVertexArrayAttrib(vao, attribute);
          gl_.VertexArrayAttribFormat(vao, attribute, 3, GL_FLOAT, GL_FALSE, attribute * 3 * sizeof(float));
          gl_.VertexArrayAttribBinding(vao, attribute, 0);
        }
        gl_.VertexArrayElementBuffer(vao, m.indices.id());
      }
      meshes_.push_back(std::move(m));
    }
    checkError("the scene upload");
    uploaded_ = scene.identity.token();
  }

  const LitProgram& litProgram(const FrameInputs& frame, bool& compiled) {
    const std::string defines = litDefines(frame);
    const auto found = litPrograms_.find(defines);
    if (found != litPrograms_.end()) return found->second;
    gl::ShaderProgram program = gl::buildProgram(gl_, {"lean_lit.vert", "lean_lit.frag"}, defines, leanShaderFile);
    const auto at = [&](const char* name) { return gl::uniformLocation(gl_, program, name); };
    LitProgram lit{.clipFromModel = at("clipFromModel"),
                   .worldFromModel = at("worldFromModel"),
                   .normalMatrix = at("normalMatrix"),
                   .baseColor = at("baseColor"),
                   .coefficients = at("coefficients"),
                   .metallic = at("metallic"),
                   .lightPosition = at("lightPosition"),
                   .lightDirection = at("lightDirection"),
                   .lightIntensity = at("lightIntensity"),
                   .lightAttenuation = at("lightAttenuation"),
                   .shadowFromWorld = at("shadowFromWorld"),
                   .shadowBias = at("shadowBias"),
                   .eye = at("eye"),
                   .ambient = at("ambient"),
                   .program = std::move(program)};
    compiled = true;
    return litPrograms_.emplace(defines, std::move(lit)).first->second;
  }

  void shadowPass(const FrameInputs& frame) {
    const int size = frame.shadows.mapSize, layers = frame.shadowLayerCount;
    if (size != shadowSize_ || layers != shadowLayers_) {
      shadowMaps_ = gl::createTexture(gl_, GL_TEXTURE_2D_ARRAY);
      gl_.TextureStorage3D(shadowMaps_.id(), 1, GL_DEPTH_COMPONENT32F, size, size, layers);
      // One texel per tap, compared against z - bias: lit where z - bias <= depth, as facet's rule.
      gl_.TextureParameteri(shadowMaps_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      gl_.TextureParameteri(shadowMaps_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      gl_.TextureParameteri(shadowMaps_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
      gl_.TextureParameteri(shadowMaps_.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
      // A cube face's taps beyond its edge read the edge texel, as facet's do; a spot's map
      // edge lies outside its cone, so the same wrap serves it.
      gl_.TextureParameteri(shadowMaps_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      gl_.TextureParameteri(shadowMaps_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
      shadowFramebuffer_ = gl::createFramebuffer(gl_);
      gl_.NamedFramebufferDrawBuffer(shadowFramebuffer_.id(), GL_NONE);
      gl_.NamedFramebufferReadBuffer(shadowFramebuffer_.id(), GL_NONE);
      shadowSize_ = size, shadowLayers_ = layers;
    }
    gl_.BindTextureUnit(kShadowMapsUnit, 0);  // the maps are the target here
    gl_.BindFramebuffer(GL_FRAMEBUFFER, shadowFramebuffer_.id());
    gl_.Viewport(0, 0, size, size);
    gl_.Disable(GL_CULL_FACE);  // every triangle casts a shadow
    gl_.Disable(GL_BLEND);
    gl_.DepthMask(GL_TRUE);
    const GLuint program = depth_->program.id();
    gl_.UseProgram(program);
    const float farDepth = 1.0f;
    for (const FrameLight& light : frame.lights) {
      if (!light.hasShadowMap) continue;
      for (int face = 0; face < light.frustum.faceCount; ++face) {
        gl_.NamedFramebufferTextureLayer(shadowFramebuffer_.id(), GL_DEPTH_ATTACHMENT, shadowMaps_.id(), 0, light.shadowLayer + face);
        gl_.ClearNamedFramebufferfv(shadowFramebuffer_.id(), GL_DEPTH, 0, &farDepth);
        for (const FrameInstance& instance : frame.instances) {
          const LeanMesh& mesh = meshes_.at(static_cast<std::size_t>(instance.mesh));
          const CourseMaterial& material = frame.materials[static_cast<std::size_t>(instance.material)];
          if (mesh.indexCount == 0 || !material.castsShadow) continue;
          if (masksShadow(material) && !keptByMask(material.baseAlpha, material.alphaCutoff)) continue;
          const glm::mat4 lightClipFromModel = light.frustum.clipFromWorld[static_cast<std::size_t>(face)] * instance.worldFromModel;
          gl_.ProgramUniformMatrix4fv(program, depth_->lightClipFromModel, 1, GL_FALSE, glm::value_ptr(lightClipFromModel));
          gl_.BindVertexArray(mesh.vertexArray.id());
          gl_.DrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
        }
      }
    }
  }

  // The lit pass's framebuffer: SRGB8_ALPHA8 colour and DEPTH_COMPONENT32F,
  // multisampled with anti-aliasing, then a single-sample one to resolve into.
  void resizeTargets(int width, int height, int samples) {
    if (width == width_ && height == height_ && samples == samples_) return;
    const auto storage = [&](const gl::GlObject& buffer, GLenum format, int s) {
      if (s > 1) gl_.NamedRenderbufferStorageMultisample(buffer.id(), s, format, width, height);
      else gl_.NamedRenderbufferStorage(buffer.id(), format, width, height);
    };
    color_ = gl::createRenderbuffer(gl_);
    depthBuffer_ = gl::createRenderbuffer(gl_);
    storage(color_, GL_SRGB8_ALPHA8, samples);
    storage(depthBuffer_, GL_DEPTH_COMPONENT32F, samples);
    framebuffer_ = gl::createFramebuffer(gl_);
    gl_.NamedFramebufferRenderbuffer(framebuffer_.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_.id());
    gl_.NamedFramebufferRenderbuffer(framebuffer_.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depthBuffer_.id());
    checkComplete(framebuffer_.id(), "the lit pass's framebuffer");
    resolvedColor_ = {}, resolved_ = {};
    if (samples > 1) {
      resolvedColor_ = gl::createRenderbuffer(gl_);
      storage(resolvedColor_, GL_SRGB8_ALPHA8, 1);
      resolved_ = gl::createFramebuffer(gl_);
      gl_.NamedFramebufferRenderbuffer(resolved_.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolvedColor_.id());
      checkComplete(resolved_.id(), "the resolve's framebuffer");
    }
    width_ = width, height_ = height, samples_ = samples;
  }

  void litPass(const FrameInputs& frame, const LitProgram& lit) {
    const int samples = frame.samples.empty() ? 1 : static_cast<int>(frame.samples.size());
    if (samples > gl::getInteger(gl_, GL_MAX_SAMPLES))
      throw Error("lean: " + std::to_string(samples) + " samples a pixel, more than this driver's multisampling gives");
    resizeTargets(frame.width, frame.height, samples);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    gl_.Viewport(0, 0, frame.width, frame.height);
    gl_.Enable(GL_FRAMEBUFFER_SRGB);  // linear colours in, sRGB bytes stored; blending and the resolve in linear
    if (samples > 1 && sampling_ == LeanSampling::EverySample) {  // the fragment shader once per sample, at the sample
      gl_.Enable(GL_SAMPLE_SHADING);
      gl_.MinSampleShading(1.0f);
    } else {
      gl_.Disable(GL_SAMPLE_SHADING);
    }
    gl_.DepthMask(GL_TRUE);
    const float background[4] = {frame.background.r, frame.background.g, frame.background.b, frame.backgroundAlpha};
    const float farDepth = 1.0f;
    gl_.ClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, background);
    gl_.ClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &farDepth);

    const GLuint program = lit.program.id();
    gl_.UseProgram(program);
    setFrameUniforms(frame, lit);
    gl_.BindTextureUnit(kShadowMapsUnit, frame.shadowLayerCount > 0 ? shadowMaps_.id() : 0);
    for (const FrameInstance& instance : frame.instances)
      if (!frame.materials[static_cast<std::size_t>(instance.material)].blended) draw(frame, lit, instance);
    // Blended instances after the opaque ones, depth-tested without depth writes, in instance order.
    bool blending = false;
    for (const FrameInstance& instance : frame.instances) {
      if (!frame.materials[static_cast<std::size_t>(instance.material)].blended) continue;
      if (!blending) {
        gl_.Enable(GL_BLEND);
        gl_.BlendEquation(GL_FUNC_ADD);
        gl_.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        gl_.DepthMask(GL_FALSE);
        blending = true;
      }
      draw(frame, lit, instance);
    }
    gl_.Disable(GL_BLEND);
    gl_.DepthMask(GL_TRUE);
    if (samples > 1)
      gl_.BlitNamedFramebuffer(framebuffer_.id(), resolved_.id(), 0, 0, frame.width, frame.height, 0, 0, frame.width, frame.height,
                                 GL_COLOR_BUFFER_BIT, GL_NEAREST);
    gl_.Disable(GL_FRAMEBUFFER_SRGB);
  }

  void setFrameUniforms(const FrameInputs& frame, const LitProgram& lit) {
    const GLuint program = lit.program.id();
    std::vector<glm::vec3> position, intensity, attenuation;
    std::vector<glm::vec4> direction;
    std::vector<glm::mat4> shadowFromWorld(static_cast<std::size_t>(std::max(frame.shadowLayerCount, 1)), glm::mat4(1.0f));
    for (const FrameLight& light : frame.lights) {
      position.push_back(light.light.position);
      direction.push_back(glm::vec4(light.light.direction, light.cosCutoff));
      intensity.push_back(light.intensity);
      attenuation.push_back(light.light.attenuation);
      if (light.hasShadowMap)
        for (int face = 0; face < light.frustum.faceCount; ++face)
          shadowFromWorld[static_cast<std::size_t>(light.shadowLayer + face)] = light.shadowFromWorld[static_cast<std::size_t>(face)];
    }
    if (!frame.lights.empty()) {
      const auto count = static_cast<GLsizei>(frame.lights.size());
      gl_.ProgramUniform3fv(program, lit.lightPosition, count, glm::value_ptr(position[0]));
      gl_.ProgramUniform4fv(program, lit.lightDirection, count, glm::value_ptr(direction[0]));
      gl_.ProgramUniform3fv(program, lit.lightIntensity, count, glm::value_ptr(intensity[0]));
      gl_.ProgramUniform3fv(program, lit.lightAttenuation, count, glm::value_ptr(attenuation[0]));
    }
    gl_.ProgramUniformMatrix4fv(program, lit.shadowFromWorld, static_cast<GLsizei>(shadowFromWorld.size()), GL_FALSE,
                                  glm::value_ptr(shadowFromWorld[0]));
    gl_.ProgramUniform2f(program, lit.shadowBias, frame.shadows.biasSlope, frame.shadows.biasMin);
    const glm::vec3 eye = frame.perspective ? frame.eyePosition : frame.towardEye;
    gl_.ProgramUniform3fv(program, lit.eye, 1, glm::value_ptr(eye));
    gl_.ProgramUniform1f(program, lit.ambient, frame.ambient);
  }

  void draw(const FrameInputs& frame, const LitProgram& lit, const FrameInstance& instance) {
    const LeanMesh& mesh = meshes_.at(static_cast<std::size_t>(instance.mesh));
    const CourseMaterial& material = frame.materials[static_cast<std::size_t>(instance.material)];
    if (mesh.indexCount == 0 || (material.masked && !keptByMask(material.baseAlpha, material.alphaCutoff))) return;
    if (instance.cullBackFaces) gl_.Enable(GL_CULL_FACE);
    else gl_.Disable(GL_CULL_FACE);
    const GLuint program = lit.program.id();
    const float alpha = material.blended ? std::clamp(material.baseAlpha, 0.0f, 1.0f) : 1.0f;
    gl_.ProgramUniformMatrix4fv(program, lit.clipFromModel, 1, GL_FALSE, glm::value_ptr(instance.clipFromModel));
    gl_.ProgramUniformMatrix4fv(program, lit.worldFromModel, 1, GL_FALSE, glm::value_ptr(instance.worldFromModel));
    gl_.ProgramUniformMatrix3fv(program, lit.normalMatrix, 1, GL_FALSE, glm::value_ptr(instance.normalMatrix));
    gl_.ProgramUniform4fv(program, lit.baseColor, 1, glm::value_ptr(glm::vec4(material.baseColor, alpha)));
    gl_.ProgramUniform4fv(program, lit.coefficients, 1, glm::value_ptr(glm::vec4(material.ka, material.kd, material.ks, material.shininess)));
    gl_.ProgramUniform1f(program, lit.metallic, material.metallic);
    gl_.BindVertexArray(mesh.vertexArray.id());
    gl_.DrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
  }

  Image readImage(const FrameInputs& frame, Image image) const {
    image.resize(frame.width, frame.height);  // the recycled image's storage where it fits: every pixel is read back
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, samples_ > 1 ? resolved_.id() : framebuffer_.id());
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl_.PixelStorei(GL_PACK_ROW_LENGTH, 0);
    // The stored sRGB bytes as they are (GL_FRAMEBUFFER_SRGB is off); row 0 is the bottom row, as facet::Image's.
    gl_.ReadPixels(0, 0, frame.width, frame.height, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
    return image;
  }

  void checkComplete(GLuint framebuffer, const char* what) const {
    if (gl_.CheckNamedFramebufferStatus(framebuffer, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw Error(std::string("lean: ") + what + " is not complete");
  }

  void checkError(const char* where) const { gl::checkGlError(gl_, where, "lean: "); }

  // Declared first: the GL objects below go before the function table, and the table before the context.
  LeanSampling sampling_;
  std::unique_ptr<gl::HeadlessContext> context_;
  gl::GlFunctions gl_;
  std::string name_;
  std::weak_ptr<const char> uploaded_;  // Scene::identity's token of the meshes in meshes_
  std::vector<LeanMesh> meshes_;
  std::map<std::string, LitProgram> litPrograms_;  // by their defines
  std::optional<DepthProgram> depth_;
  gl::GlObject shadowMaps_, shadowFramebuffer_;
  int shadowSize_ = 0, shadowLayers_ = 0;
  ShadowPassKey mapsDrawn_;
  gl::GlObject color_, depthBuffer_, framebuffer_, resolvedColor_, resolved_;
  int width_ = 0, height_ = 0, samples_ = 0;
};

}  // namespace

std::string leanUnsupported(const Scene& scene, const FrameInputs& frame) {
  if (frame.volume.placed) return "a ray-cast volume";
  if (frame.shading != ShadingMode::Phong) return "shading other than phong";
  if (frame.hsr != HiddenSurface::ZBuffer) return "hidden surfaces other than the z-buffer";
  if (frame.areaAveraged) return "area-averaged anti-aliasing";
  if (frame.fog.mode != FogMode::None) return "fog";
  if (frame.environment.map || frame.bump.map || frame.procedural != Procedural::None) return "environment, bump or procedural maps";
  for (const FrameInstance& instance : frame.instances) {
    const Mesh& mesh = scene.meshes.at(static_cast<std::size_t>(instance.mesh));
    const CourseMaterial& m = frame.materials[static_cast<std::size_t>(instance.material)];
    if (!mesh.colors.empty()) return "vertex colours";
    if (!mesh.lines.empty() || !mesh.points.empty()) return "lines or points";
    if (mesh.normals.size() != mesh.positions.size()) return "a mesh without a normal per vertex";
    if (m.unlit || m.additive) return "unlit or additive materials";
    if (m.baseColorTexture >= 0 || m.normalMap.texture >= 0) return "textures";
    if (m.emissive != glm::vec3(0.0f)) return "emission";
    if (m.blended && frame.backgroundAlpha != 1.0f) return "blending over a background with alpha below 1";
  }
  return {};
}

std::unique_ptr<Renderer> makeLeanGlRenderer(LeanSampling sampling) { return std::make_unique<LeanGlRenderer>(sampling); }

}  // namespace facet
