#include "gl/frame_renderer.h"
#include "gl/gl_renderer.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <chrono>
#include <iterator>
#include <cstdio>
#include <string_view>

#include <glm/gtc/type_ptr.hpp>

#include "common/error.h"
#include "common/stopwatch.h"
#include "gl/shader_variant.h"
#include "shading/blending.h"
#include "image/srgb.h"
#include "pipeline/antialiasing.h"
#include "pipeline/clip_volume.h"
#include "pipeline/stage_frames.h"

namespace facet::gl {
namespace {

// Bindings the shaders declare (frame_block.glsl, draw_uniforms.glsl, lit_flat.vert).
constexpr GLuint kFrameBlockBinding = 0;      // uniform block Frame
constexpr GLuint kSrgbBlockBinding = 1;       // uniform block SrgbTables (srgb.glsl)
constexpr GLuint kSplitSumBlockBinding = 2;   // uniform block SplitSumTable (physically_based.glsl)
constexpr GLuint kShadowMapsUnit = 0;         // sampler2DArray shadowMaps
constexpr GLuint kBaseColorTextureUnit = 1;   // usampler2D baseColorTexture
constexpr GLuint kEnvironmentUnit = 2;        // usampler2D environmentMap (environment.glsl)
constexpr GLuint kMetallicRoughnessUnit = 3;  // usampler2D metallicRoughnessMap (draw_uniforms.glsl)
constexpr GLuint kOcclusionUnit = 4;          // usampler2D occlusionMap
constexpr GLuint kEmissiveUnit = 5;           // usampler2D emissiveMap
constexpr GLuint kNormalMapUnit = 6;          // usampler2D normalMap
constexpr GLuint kBumpMapUnit = 7;            // usampler2D bumpMap (bump_mapping.glsl)
constexpr GLuint kResolveUnit = 8;            // sampler2D linearColor (resolve.frag)
constexpr GLuint kMeshIndicesBinding = 0;     // storage buffers of lit_flat.vert
constexpr GLuint kMeshPositionsBinding = 1;
constexpr GLuint kMeshTexcoordsBinding = 2;
constexpr GLuint kMeshColorsBinding = 3;
constexpr GLuint kMeshTexcoords1Binding = 4;
constexpr GLint kMeshStorageBuffers = 5;
constexpr GLuint kPaintedBinding = 5;         // storage buffer of triangle_id.frag: the painter's order


// The vertex and fragment shader of each shading mode, indexed by ShadingMode.
constexpr std::array<std::string_view, 2> kLitStages[] = {
    {"lit_flat.vert", "lit_flat.frag"},
    {"lit_gouraud.vert", "lit_gouraud.frag"},
    {"lit_phong.vert", "lit_phong.frag"},
    {"lit_phong.vert", "lit_phong.frag"},  // pbr: Phong's interpolation, FACET_PBR's BRDF
};
static_assert(std::size(kLitStages) == static_cast<std::size_t>(ShadingMode::Count));

using Clock = std::chrono::steady_clock;

// Programs kept at most: each light set and settings combination a viewer
// visits adds one or two; past this the cache starts over.
constexpr std::size_t kMaxLitPrograms = 32;

std::string litProgramKey(const FrameInputs& frame, DrawVariant variant, LitOutput output) {
  return std::to_string(static_cast<int>(frame.shading)) + "\n" + litShaderDefines(frame, variant, output);
}

}  // namespace

GlFrameRenderer::GlFrameRenderer(const GetProcAddress& getProcAddress)
    : gl_(loadGlFunctions(getProcAddress)), rendererName_(rendererAndVersion(gl_)) {
  frameUniforms_ = createBuffer(gl_);
  gl_.NamedBufferStorage(frameUniforms_.id(), sizeof(FrameBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
  srgbUniforms_ = createBuffer(gl_);
  const SrgbBlock srgb = makeSrgbBlock();
  gl_.NamedBufferStorage(srgbUniforms_.id(), sizeof srgb, &srgb, 0);
  emptyVertexArray_ = createVertexArray(gl_);
}

void GlFrameRenderer::uploadScene(const Scene& scene) {
  scene_ = SceneBuffers(gl_, scene);
  checkError("scene upload");
}

void GlFrameRenderer::beginFrame(const Scene& scene, const FrameInputs& frame, LitOutput output, std::vector<PassTiming>& timings) {
  facet::refuseCpuOnlyFrame(frame);
  if (frame.hsr == HiddenSurface::Painter) painters_.prepare(gl_, scene, frame, frame.paintersOrder);
  if (!frame.transparentOrder.empty()) transparent_.prepare(gl_, scene, frame, frame.transparentOrder);
  gl_.Finish();
  Clock::time_point start = Clock::now();
  if (preparePrograms(frame, output)) {
    timings.push_back({kShaderCompilePass, millisecondsSince(start)});
    start = Clock::now();
  }

  const FrameBlock block = makeFrameBlock(frame);
  gl_.NamedBufferSubData(frameUniforms_.id(), 0, sizeof block, &block);
  gl_.BindBufferBase(GL_UNIFORM_BUFFER, kFrameBlockBinding, frameUniforms_.id());
  gl_.BindBufferBase(GL_UNIFORM_BUFFER, kSrgbBlockBinding, srgbUniforms_.id());
  if (frame.shading == ShadingMode::Pbr && !splitSumUniforms_) {
    splitSumUniforms_ = createBuffer(gl_);
    const SplitSumBlock table = makeSplitSumBlock();
    gl_.NamedBufferStorage(splitSumUniforms_.id(), sizeof table, &table, 0);
  }
  if (splitSumUniforms_) gl_.BindBufferBase(GL_UNIFORM_BUFFER, kSplitSumBlockBinding, splitSumUniforms_.id());
  // The contract's conventions, set every frame because a viewer's UI shares the context.
  gl_.ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);  // clip z in [0, w], window origin at the lower left
  gl_.FrontFace(GL_CCW);                           // counter-clockwise in window coordinates is front
  for (GLenum capability : {GL_BLEND, GL_SCISSOR_TEST, GL_STENCIL_TEST, GL_DITHER, GL_FRAMEBUFFER_SRGB, GL_POLYGON_OFFSET_FILL})
    gl_.Disable(capability);  // a pixel keeps the shader's float output, nothing else, until the resolve

  if (frame.shadowLayerCount > 0 && mapsDrawn_.matches(scene, frame)) {
    timings.push_back({shadowPassName(frame, true), 0.0});  // the maps hold this frame's (pipeline/shadow_pass_key.h)
  } else if (frame.shadowLayerCount > 0) {
    mapsDrawn_ = {};  // until every face is drawn
    shadowPass(frame);
    gl_.Finish();
    checkError("the shadow pass");
    mapsDrawn_ = ShadowPassKey(scene, frame);
    timings.push_back({shadowPassName(frame, false), millisecondsSince(start)});
  }
}

bool GlFrameRenderer::encodesAsDrawn(const FrameInputs& frame) {
  if (!frame.samples.empty() || !frame.transparentOrder.empty()) return false;
  for (const FrameInstance& instance : frame.instances)
    if (frame.materials[static_cast<std::size_t>(instance.material)].blended) return false;
  return true;
}

std::vector<PassTiming> GlFrameRenderer::drawFrame(const Scene& scene, const FrameInputs& frame, Encoding encoding) {
  std::vector<PassTiming> timings;
  const bool asDrawn = encoding == Encoding::AsDrawnWherePossible && encodesAsDrawn(frame);
  beginFrame(scene, frame, asDrawn ? LitOutput::Levels : LitOutput::Color, timings);
  Clock::time_point start = Clock::now();
  if (asDrawn) {  // the image's levels from the lit pass: no float buffer, no resolve
    litPass(frame, LitOutput::Levels);
    gl_.Finish();
    checkError("the lit pass");
    timings.push_back({"lit pass, encoded as drawn", millisecondsSince(start)});
    image_ = &levels_;
    return timings;
  }
  if (frame.samples.empty()) {
    litPass(frame);
    gl_.Finish();
    checkError("the lit pass");
    timings.push_back({"lit pass", millisecondsSince(start)});
  } else {  // anti-aliasing: a pass per sample, summed premultiplied (PIPELINE.md, "Shading")
    sum_.resize(gl_, frame.width, frame.height);
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    gl_.ClearNamedFramebufferfv(sum_.framebuffer(), GL_COLOR, 0, zero);
    for (const glm::vec2 offset : frame.samples) {
      const FrameInputs pass = sampleFrame(frame, offset);
      litPass(pass);
      accumulatePass(pass);
    }
    gl_.Finish();
    checkError("the lit pass");
    timings.push_back({"lit pass (" + std::to_string(frame.samples.size()) + " samples)", millisecondsSince(start)});
  }
  start = Clock::now();
  if (frame.samples.empty()) resolvePass(frame, target_.colorTexture(), frame.blending == Blending::Premultiplied, 1);
  else resolvePass(frame, sum_.colorTexture(), true, static_cast<int>(frame.samples.size()));
  gl_.Finish();
  checkError("the resolve");
  timings.push_back({"resolve", millisecondsSince(start)});
  image_ = &resolved_;
  return timings;
}

Image GlFrameRenderer::readImage(Image image) const {
  image.resize(image_->width(), image_->height());  // every pixel read back below
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, image_->framebuffer());
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl_.PixelStorei(GL_PACK_ROW_LENGTH, 0);
  // Row 0 of glReadPixels is the bottom row, as facet::Image stores it: no flip.
  gl_.ReadPixels(0, 0, image.width(), image.height(), GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  checkError("the read-back");
  return image;
}

std::vector<float> GlFrameRenderer::drawDepth(const Scene& scene, const FrameInputs& frame) {
  FrameInputs centred = frame;  // one pass at the pixel centres: the z-buffer the last sample left is not the frame's
  centred.samples.clear();
  drawFrame(scene, centred);
  std::vector<float> depth(static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height));
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, (image_ == &levels_ ? levels_ : target_).framebuffer());  // the lit pass's target
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 4);
  gl_.PixelStorei(GL_PACK_ROW_LENGTH, 0);
  gl_.ReadPixels(0, 0, frame.width, frame.height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());  // bottom row first, as facet stores rows
  checkError("the depth read-back");
  return depth;
}

ShadowMapTexels GlFrameRenderer::readShadowMaps(const Scene& scene, const FrameInputs& frame) {
  if (frame.shadowLayerCount == 0) return {};
  std::vector<PassTiming> timings;
  beginFrame(scene, frame, LitOutput::Color, timings);
  ShadowMapTexels maps{frame.shadows.mapSize, frame.shadowLayerCount, {}};
  const std::size_t perLayer = static_cast<std::size_t>(maps.size) * static_cast<std::size_t>(maps.size);
  maps.texels.resize(perLayer * static_cast<std::size_t>(maps.layers));
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 4);
  gl_.PixelStorei(GL_PACK_ROW_LENGTH, 0);
  for (int layer = 0; layer < maps.layers; ++layer)  // a layer at a time: the byte count of one call is a GLsizei
    gl_.GetTextureSubImage(shadowMaps_.texture(), 0, 0, 0, layer, maps.size, maps.size, 1, GL_DEPTH_COMPONENT, GL_FLOAT,
                             static_cast<GLsizei>(perLayer * sizeof(float)), maps.texels.data() + perLayer * static_cast<std::size_t>(layer));
  checkError("the shadow-map read-back");
  return maps;
}

std::vector<glm::vec4> GlFrameRenderer::drawNormals(const Scene& scene, const FrameInputs& frame) {
  const FrameInputs drawn = normalsFrame(frame);
  std::vector<PassTiming> timings;
  beginFrame(scene, drawn, LitOutput::Normal, timings);  // no shadow pass: the frame has no lights
  litPass(drawn, LitOutput::Normal);
  std::vector<glm::vec4> normals(static_cast<std::size_t>(drawn.width) * static_cast<std::size_t>(drawn.height));
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, target_.framebuffer());
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 4);
  gl_.PixelStorei(GL_PACK_ROW_LENGTH, 0);
  gl_.ReadPixels(0, 0, drawn.width, drawn.height, GL_RGBA, GL_FLOAT, normals.data());
  checkError("the normals pass");
  return normals;
}

std::vector<std::uint32_t> GlFrameRenderer::drawTriangleIds(const Scene& scene, const FrameInputs& frame) {
  facet::refuseCpuOnlyFrame(frame);
  const bool painter = frame.hsr == HiddenSurface::Painter;
  if (painter) painters_.prepare(gl_, scene, frame, frame.paintersOrder);
  const auto idVariant = [&](const FrameInstance& instance) { return maskVariant(frame, instance); };
  prepareMaskPrograms(triangleIdPrograms_, frame, {"triangle_id.vert", "triangle_id.frag"}, [&](ShaderProgram program) {
    const auto at = [&](const char* name) { return uniformLocation(gl_, program, name); };
    return TriangleIdProgram{.clipFromModel = at("clipFromModel"), .firstTriangle = at("firstTriangle"), .painted = at("painted"),
                             .alpha = alphaUniforms(program),
                             .program = std::move(program)};
  });
  idTarget_.resize(gl_, frame.width, frame.height);
  gl_.ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  gl_.FrontFace(GL_CCW);
  for (GLenum capability : {GL_BLEND, GL_SCISSOR_TEST, GL_STENCIL_TEST, GL_DITHER, GL_FRAMEBUFFER_SRGB, GL_POLYGON_OFFSET_FILL})
    gl_.Disable(capability);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, idTarget_.framebuffer());
  gl_.Viewport(0, 0, frame.width, frame.height);
  const GLuint background = 0;
  const float farDepth = 1.0f;
  gl_.ClearNamedFramebufferuiv(idTarget_.framebuffer(), GL_COLOR, 0, &background);
  gl_.DepthMask(GL_TRUE);
  gl_.ClearNamedFramebufferfv(idTarget_.framebuffer(), GL_DEPTH, 0, &farDepth);
  if (painter) gl_.Disable(GL_DEPTH_TEST);  // no depth buffer: the last triangle drawn keeps the pixel
  else gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthFunc(GL_LESS);
  gl_.CullFace(GL_BACK);
  gl_.BindBufferBase(GL_UNIFORM_BUFFER, kSrgbBlockBinding, srgbUniforms_.id());
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kPaintedBinding, painter ? painters_.triangles() : srgbUniforms_.id());
  // One draw: the instance's triangles [first, first + count) of its mesh, or of the painter's index buffer.
  const auto draw = [&](const FrameInstance& instance, GLuint first, GLsizei count, const PainterRun* run) {
    const MeshBuffers& mesh = scene_.mesh(instance.mesh);
    if (frame.materials[static_cast<std::size_t>(instance.material)].blended) return;  // they write no depth and keep no pixel
    const DrawVariant variant = idVariant(instance);
    const TriangleIdProgram& id = triangleIdPrograms_.at(variant.index());
    const GLuint program = id.program.id();
    gl_.UseProgram(program);
    setCulling(instance.cullBackFaces);
    gl_.ProgramUniformMatrix4fv(program, id.clipFromModel, 1, GL_FALSE, glm::value_ptr(instance.clipFromModel));
    gl_.ProgramUniform1ui(program, id.firstTriangle, first);
    gl_.ProgramUniform1i(program, id.painted, run ? 1 : 0);
    if (variant.masked)
      setBaseColorUniforms(program, id.alpha, frame.materials[static_cast<std::size_t>(instance.material)], variant.textured);
    if (count > 0) drawIndexed(mesh, run);
  };
  if (painter) {
    for (const PainterRun& run : painters_.runs())
      draw(frame.instances[run.instance], static_cast<GLuint>(run.first), run.count, &run);
  } else {
    GLuint first = 0;
    for (const FrameInstance& instance : frame.instances) {
      const GLsizei count = scene_.mesh(instance.mesh).indexCount / 3;
      draw(instance, first, count, nullptr);
      first += static_cast<GLuint>(count);
    }
  }
  std::vector<std::uint32_t> ids(static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height));
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, idTarget_.framebuffer());
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 4);
  gl_.PixelStorei(GL_PACK_ROW_LENGTH, 0);
  gl_.ReadPixels(0, 0, frame.width, frame.height, GL_RED_INTEGER, GL_UNSIGNED_INT, ids.data());
  checkError("the triangle id pass");
  return ids;
}

std::vector<std::uint32_t> GlFrameRenderer::drawFragmentCounts(const FrameInputs& frame) {
  if (!fragmentCountProgram_) {
    ShaderProgram program = buildProgram(gl_, {"triangle_id.vert", "fragment_count.frag"});
    const GLint clipFromModel = uniformLocation(gl_, program, "clipFromModel");
    fragmentCountProgram_.emplace(FragmentCountProgram{clipFromModel, std::move(program)});
  }
  countTarget_.resize(gl_, frame.width, frame.height);
  gl_.ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  gl_.FrontFace(GL_CCW);
  for (GLenum capability : {GL_DEPTH_TEST, GL_SCISSOR_TEST, GL_STENCIL_TEST, GL_DITHER, GL_FRAMEBUFFER_SRGB, GL_POLYGON_OFFSET_FILL})
    gl_.Disable(capability);
  gl_.Enable(GL_BLEND);  // each fragment adds its 1
  gl_.BlendEquation(GL_FUNC_ADD);
  gl_.BlendFunc(GL_ONE, GL_ONE);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, countTarget_.framebuffer());
  gl_.Viewport(0, 0, frame.width, frame.height);
  const float zero = 0.0f;
  gl_.ClearNamedFramebufferfv(countTarget_.framebuffer(), GL_COLOR, 0, &zero);
  gl_.CullFace(GL_BACK);
  const GLuint program = fragmentCountProgram_->program.id();
  gl_.UseProgram(program);
  for (const FrameInstance& instance : frame.instances) {
    const MeshBuffers& mesh = scene_.mesh(instance.mesh);
    if (mesh.indexCount == 0) continue;
    setCulling(instance.cullBackFaces);
    gl_.ProgramUniformMatrix4fv(program, fragmentCountProgram_->clipFromModel, 1, GL_FALSE, glm::value_ptr(instance.clipFromModel));
    gl_.BindVertexArray(mesh.vertexArray.id());
    gl_.DrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
  }
  gl_.Disable(GL_BLEND);
  std::vector<float> counts(static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height));
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, countTarget_.framebuffer());
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 4);
  gl_.PixelStorei(GL_PACK_ROW_LENGTH, 0);
  gl_.ReadPixels(0, 0, frame.width, frame.height, GL_RED, GL_FLOAT, counts.data());
  checkError("the fragment count pass");
  std::vector<std::uint32_t> out(counts.size());
  for (std::size_t i = 0; i < counts.size(); ++i) out[i] = static_cast<std::uint32_t>(counts[i]);
  return out;
}

DrawVariant GlFrameRenderer::drawVariant(const FrameInputs& frame, const FrameInstance& instance) const {
  const MeshBuffers& mesh = scene_.mesh(instance.mesh);
  const CourseMaterial& material = frame.materials[static_cast<std::size_t>(instance.material)];
  // A procedural texture takes the base colour texture's place (renderer/shading/texture.h, baseColorTextureOf);
  // shading=pbr alone reads the metallic-roughness and occlusion maps (renderer/shading/physically_based.h, pbrSurfaceAt).
  // Each map only where the mesh has the texture coordinate set it reads.
  const auto reads = [&](const MaterialMap& map) { return map.texture >= 0 && mesh.hasSet(map.set); };
  const bool pbr = frame.shading == ShadingMode::Pbr;
  return {frame.procedural == Procedural::None && material.baseColorTexture >= 0 && mesh.hasSet(material.baseColorSet),
          static_cast<bool>(mesh.colors),
          material.masked,
          pbr && reads(material.metallicRoughnessMap),
          pbr && reads(material.occlusionMap),
          reads(material.emissiveMap),  // every mode: k_e·E (renderer/shading/texture.h, emissionAt)
          interpolatesNormals(frame.shading) && reads(material.normalMap) && mesh.tangents,
          frame.bump.map != nullptr && mesh.tangents,
          material.blended};
}

DrawVariant GlFrameRenderer::maskVariant(const FrameInputs& frame, const FrameInstance& instance) const {
  // The shadow pass tests a blended material's α as a mask's (material_coefficients.h, masksShadow);
  // the triangle-id pass draws no blended material.
  const DrawVariant v = drawVariant(frame, instance);
  const bool masked = masksShadow(frame.materials[static_cast<std::size_t>(instance.material)]);
  return masked ? DrawVariant{v.textured, v.colored, true} : DrawVariant{};  // one program for every unmasked draw
}

void GlFrameRenderer::setCulling(bool cull) {
  if (cull) gl_.Enable(GL_CULL_FACE);
  else gl_.Disable(GL_CULL_FACE);
}

bool GlFrameRenderer::preparePrograms(const FrameInputs& frame, LitOutput output) {
  bool compiled = false;
  const bool shadows = frame.shadowLayerCount > 0;
  bool needed[DrawVariant::kCount] = {};  // some draw of the frame needs the variant
  for (const FrameInstance& instance : frame.instances)
    if (scene_.mesh(instance.mesh).indexCount > 0 &&
        (output == LitOutput::Color || !frame.materials[static_cast<std::size_t>(instance.material)].blended))  // normals: opaque draws only
      needed[drawVariant(frame, instance).index()] = true;
  if (litPrograms_.size() + static_cast<std::size_t>(std::count(std::begin(needed), std::end(needed), true)) > kMaxLitPrograms) litPrograms_.clear();
  for (int v = 0; v < DrawVariant::kCount; ++v) {
    if (!needed[v]) continue;
    const DrawVariant variant = DrawVariant::of(v);
    const std::string key = litProgramKey(frame, variant, output);
    if (litPrograms_.count(key)) continue;
    if (frame.shading == ShadingMode::Flat && getInteger(gl_, GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS) < kMeshStorageBuffers)
      throw Error("OpenGL: flat shading reads the mesh from " + std::to_string(kMeshStorageBuffers) +
                  " storage buffers in the vertex shader; this driver allows " + std::to_string(getInteger(gl_, GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS)));
    const auto& stages = kLitStages[static_cast<std::size_t>(frame.shading)];
    ShaderProgram program = buildProgram(gl_, {stages[0], stages[1]}, litShaderDefines(frame, variant, output));
    const auto at = [&](const char* name) { return uniformLocation(gl_, program, name); };
    litPrograms_.emplace(key, LitProgram{.clipFromModel = at("clipFromModel"),
                                         .worldFromModel = at("worldFromModel"),
                                         .normalMatrix = at("normalMatrix"),
                                         .emissive = at("material.emissive"),
                                         .ka = at("material.ka"),
                                         .kd = at("material.kd"),
                                         .ks = at("material.ks"),
                                         .shininess = at("material.shininess"),
                                         .metallic = at("material.metallic"),
                                         .roughness = at("material.roughness"),
                                         .metallicRoughnessSampler = at("metallicRoughnessSampler"),
                                         .occlusionSampler = at("occlusionSampler"),
                                         .emissiveSampler = at("emissiveSampler"),
                                         .occlusionStrength = at("occlusionStrength"),
                                         .mapsSrgb = at("mapsSrgb"),
                                         .normalMapSampler = at("normalMapSampler"),
                                         .normalScale = at("normalScale"),
                                         .mapSets = at("mapSets"),
                                         .baseColorFactor = at("baseColorFactor"),
                                         .unlit = at("unlit"),
                                         .additive = at("additiveBlend"),
                                         .alpha = alphaUniforms(program),
                                         .program = std::move(program)});
    compiled = true;
  }
  if (shadows)
    compiled = prepareMaskPrograms(depthPrograms_, frame, {"shadow_depth.vert", "shadow_depth.frag"}, [&](ShaderProgram program) {
                 const auto at = [&](const char* name) { return uniformLocation(gl_, program, name); };
                 return DepthProgram{.lightClipFromWorld = at("lightClipFromWorld"), .worldFromModel = at("worldFromModel"),
                                     .alpha = alphaUniforms(program), .program = std::move(program)};
               }) || compiled;
  if (!backgroundProgram_) {
    backgroundProgram_.emplace(buildProgram(gl_, {"viewport_triangle.vert", "background.frag"}));
    backgroundViewportSize_ = uniformLocation(gl_, *backgroundProgram_, "viewportSize");
    backgroundAlpha_ = uniformLocation(gl_, *backgroundProgram_, "backgroundAlpha");
    backgroundPremultiplied_ = uniformLocation(gl_, *backgroundProgram_, "premultiplied");
    backgroundSampleOffset_ = uniformLocation(gl_, *backgroundProgram_, "sampleOffset");
    backgroundLevels_ = uniformLocation(gl_, *backgroundProgram_, "levels");
    compiled = true;
  }
  if (!frame.samples.empty() && !accumulateProgram_) {
    accumulateProgram_.emplace(buildProgram(gl_, {"viewport_triangle.vert", "accumulate.frag"}));
    accumulatePremultiplied_ = uniformLocation(gl_, *accumulateProgram_, "premultiplied");
    compiled = true;
  }
  if (output != LitOutput::Levels && !resolveProgram_) {
    resolveProgram_.emplace(buildProgram(gl_, {"viewport_triangle.vert", "resolve.frag"}));
    resolvePremultiplied_ = uniformLocation(gl_, *resolveProgram_, "premultiplied");
    resolveSamples_ = uniformLocation(gl_, *resolveProgram_, "samples");
    compiled = true;
  }
  if (!lineProgram_ || lineFog_ != frame.fog.mode) {
    ShaderProgram program = buildProgram(gl_, {"line.vert", "line.frag"}, fogDefine(frame));
    const auto at = [&](const char* name) { return uniformLocation(gl_, program, name); };
    lineProgram_.emplace(LineProgram{at("clipFromModel"), at("colored"), at("baseColorFactor"), at("levels"), std::move(program)});
    lineFog_ = frame.fog.mode;
    compiled = true;
  }
  return compiled;
}

void GlFrameRenderer::shadowPass(const FrameInputs& frame) {
  shadowMaps_.resize(gl_, frame.shadows.mapSize, frame.shadowLayerCount);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, shadowMaps_.framebuffer());
  gl_.Viewport(0, 0, shadowMaps_.size(), shadowMaps_.size());
  gl_.Disable(GL_CULL_FACE);  // every triangle casts a shadow
  gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthFunc(GL_LESS);
  gl_.DepthMask(GL_TRUE);
  gl_.BindTextureUnit(kShadowMapsUnit, 0);  // the maps are the target here
  const float farDepth = 1.0f;
  for (const FrameLight& light : frame.lights) {
    if (!light.hasShadowMap) continue;
    for (int face = 0; face < light.frustum.faceCount; ++face) {
      shadowMaps_.attachLayer(gl_, light.shadowLayer + face);
      gl_.ClearNamedFramebufferfv(shadowMaps_.framebuffer(), GL_DEPTH, 0, &farDepth);
      for (const FrameInstance& instance : frame.instances) {
        const MeshBuffers& mesh = scene_.mesh(instance.mesh);
        if (mesh.indexCount == 0 || !frame.materials[static_cast<std::size_t>(instance.material)].castsShadow) continue;
        const glm::mat4& lightClipFromWorld = light.frustum.clipFromWorld[static_cast<std::size_t>(face)];
        if (clipVolumeMisses(lightClipFromWorld * instance.worldFromModel, mesh.bounds)) continue;  // draws nothing on this face
        const DrawVariant variant = maskVariant(frame, instance);
        const DepthProgram& depth = depthPrograms_.at(variant.index());
        const GLuint program = depth.program.id();
        gl_.UseProgram(program);
        gl_.ProgramUniformMatrix4fv(program, depth.lightClipFromWorld, 1, GL_FALSE, glm::value_ptr(lightClipFromWorld));
        gl_.ProgramUniformMatrix4fv(program, depth.worldFromModel, 1, GL_FALSE, glm::value_ptr(instance.worldFromModel));
        if (variant.masked)
          setBaseColorUniforms(program, depth.alpha, frame.materials[static_cast<std::size_t>(instance.material)], variant.textured);
        gl_.BindVertexArray(mesh.vertexArray.id());
        gl_.DrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
      }
    }
  }
}

void GlFrameRenderer::litPass(const FrameInputs& frame, LitOutput output) {
  const bool levels = output == LitOutput::Levels;
  RenderTarget& target = levels ? levels_ : target_;
  target.resize(gl_, frame.width, frame.height);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
  gl_.Viewport(0, 0, frame.width, frame.height);
  gl_.DepthMask(GL_TRUE);
  const float farDepth = 1.0f;
  gl_.ClearNamedFramebufferfv(target.framebuffer(), GL_DEPTH, 0, &farDepth);

  // The background over every pixel, through the same encoding as lit pixels; depth stays 1.
  // The normals stage: 0 where no triangle is kept.
  gl_.Disable(GL_DEPTH_TEST);
  gl_.Disable(GL_CULL_FACE);
  gl_.BindTextureUnit(kEnvironmentUnit, scene_.environment());
  gl_.BindTextureUnit(kBumpMapUnit, frame.bump.map ? scene_.bumpMap() : 0);
  if (output == LitOutput::Normal) {
    const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    gl_.ClearNamedFramebufferfv(target.framebuffer(), GL_COLOR, 0, none);
  } else if (!showsEnvironment(frame)) {
    // One colour everywhere: a clear to the value background.frag would write at every pixel, stored
    // by the C++ mirror of blending.glsl (the same product), instead of a full-frame draw; encoded
    // as drawn, its levels by the CPU's resolve (each level / 255, which the RGBA8 target stores as that level).
    const glm::vec4 held = stored(frame.background, frame.backgroundAlpha, frame.blending);
    const Rgba8 encoded = encodePixel(unstored(held, frame.blending));  // resolved.glsl's rule
    const glm::vec4 value = levels ? glm::vec4(encoded.r, encoded.g, encoded.b, encoded.a) / 255.0f : held;
    gl_.ClearNamedFramebufferfv(target.framebuffer(), GL_COLOR, 0, glm::value_ptr(value));
  } else {
    gl_.UseProgram(backgroundProgram_->id());
    gl_.ProgramUniform2f(backgroundProgram_->id(), backgroundViewportSize_, static_cast<float>(frame.width),
                           static_cast<float>(frame.height));
    gl_.ProgramUniform1f(backgroundProgram_->id(), backgroundAlpha_, frame.backgroundAlpha);
    gl_.ProgramUniform1i(backgroundProgram_->id(), backgroundPremultiplied_, frame.blending == Blending::Premultiplied ? 1 : 0);
    gl_.ProgramUniform2f(backgroundProgram_->id(), backgroundSampleOffset_, frame.sampleOffset.x, frame.sampleOffset.y);
    gl_.ProgramUniform1i(backgroundProgram_->id(), backgroundLevels_, levels ? 1 : 0);
    gl_.BindVertexArray(emptyVertexArray_.id());
    gl_.DrawArrays(GL_TRIANGLES, 0, 3);
  }

  // The painter's algorithm: no depth test and no depth writes, triangles in its order (PIPELINE.md, "Rasterization").
  const bool painter = frame.hsr == HiddenSurface::Painter;
  if (painter) gl_.Disable(GL_DEPTH_TEST);
  else gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthFunc(GL_LESS);
  gl_.CullFace(GL_BACK);
  gl_.BindTextureUnit(kShadowMapsUnit, frame.shadowLayerCount > 0 ? shadowMaps_.texture() : 0);
  const LitProgram* programs[DrawVariant::kCount];
  for (int v = 0; v < DrawVariant::kCount; ++v) programs[v] = litProgram(frame, DrawVariant::of(v), output);
  GLuint current = 0;
  const auto draw = [&](const FrameInstance& instance, const PainterRun* run) {
    if (scene_.mesh(instance.mesh).indexCount == 0) return;
    const LitProgram* lit = programs[drawVariant(frame, instance).index()];
    if (!lit) throw Error("OpenGL backend: no lit program was prepared for this frame");
    if (lit->program.id() != current) gl_.UseProgram(current = lit->program.id());
    setCulling(instance.cullBackFaces);
    drawInstance(*lit, frame, instance, frame.shading == ShadingMode::Flat, run);
  };
  if (painter)
    for (const PainterRun& run : painters_.runs()) draw(frame.instances[run.instance], &run);
  else
    for (const FrameInstance& instance : frame.instances)
      if (!frame.materials[static_cast<std::size_t>(instance.material)].blended) draw(instance, nullptr);
  if (output == LitOutput::Normal) return;  // lines and points have no normal, blended surfaces write no depth
  drawLines(frame, levels);
  if (frame.transparentOrder.empty()) return;
  // Transparency (PIPELINE.md, "Shading"): the blended triangles back to front, depth-tested, no depth writes;
  // each fragment blends into the colour buffer in its shader (lit_output.glsl), in primitive order.
  gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthMask(GL_FALSE);
  current = 0;
  for (const PainterRun& run : transparent_.runs()) draw(frame.instances[run.instance], &run);
  gl_.DepthMask(GL_TRUE);
}

void GlFrameRenderer::drawLines(const FrameInputs& frame, bool levels) {
  // After every triangle, instance by instance: its segments, then its points (the CPU backend's order).
  const GLuint program = lineProgram_->program.id();
  bool bound = false;
  for (const FrameInstance& instance : frame.instances) {
    const MeshBuffers& mesh = scene_.mesh(instance.mesh);
    if (mesh.lineIndexCount == 0 && mesh.pointCount == 0) continue;
    if (!bound) {
      gl_.UseProgram(program);
      setCulling(false);  // a segment or point has no face
      if (frame.hsr == HiddenSurface::Painter) gl_.Disable(GL_DEPTH_TEST);  // over what was painted, in order
      bound = true;
    }
    gl_.ProgramUniformMatrix4fv(program, lineProgram_->clipFromModel, 1, GL_FALSE, glm::value_ptr(instance.clipFromModel));
    gl_.ProgramUniform1i(program, lineProgram_->colored, mesh.colors ? 1 : 0);
    gl_.ProgramUniform1i(program, lineProgram_->levels, levels ? 1 : 0);
    gl_.ProgramUniform3fv(program, lineProgram_->baseColorFactor, 1,
                            glm::value_ptr(frame.materials[static_cast<std::size_t>(instance.material)].baseColor));
    if (mesh.lineIndexCount) {
      gl_.BindVertexArray(mesh.lineVertexArray.id());
      gl_.DrawElements(GL_LINES, mesh.lineIndexCount, GL_UNSIGNED_INT, nullptr);
    }
    if (mesh.pointCount) {
      gl_.BindVertexArray(mesh.pointVertexArray.id());
      gl_.DrawElements(GL_POINTS, mesh.pointCount, GL_UNSIGNED_INT, nullptr);
    }
  }
}

void GlFrameRenderer::accumulatePass(const FrameInputs& frame) {
  gl_.BindFramebuffer(GL_FRAMEBUFFER, sum_.framebuffer());
  gl_.Viewport(0, 0, frame.width, frame.height);
  gl_.Disable(GL_DEPTH_TEST);
  gl_.Disable(GL_CULL_FACE);
  gl_.BindTextureUnit(kResolveUnit, target_.colorTexture());
  gl_.UseProgram(accumulateProgram_->id());
  gl_.ProgramUniform1i(accumulateProgram_->id(), accumulatePremultiplied_, frame.blending == Blending::Premultiplied ? 1 : 0);
  gl_.BindVertexArray(emptyVertexArray_.id());
  gl_.DrawArrays(GL_TRIANGLES, 0, 3);
  gl_.BindTextureUnit(kResolveUnit, 0);  // the colour buffer is the next sample's target
}

void GlFrameRenderer::resolvePass(const FrameInputs& frame, GLuint source, bool premultiplied, int samples) {
  resolved_.resize(gl_, frame.width, frame.height);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, resolved_.framebuffer());
  gl_.Viewport(0, 0, frame.width, frame.height);
  gl_.Disable(GL_DEPTH_TEST);
  gl_.Disable(GL_CULL_FACE);
  gl_.BindTextureUnit(kResolveUnit, source);
  gl_.UseProgram(resolveProgram_->id());
  gl_.ProgramUniform1i(resolveProgram_->id(), resolvePremultiplied_, premultiplied ? 1 : 0);
  gl_.ProgramUniform1f(resolveProgram_->id(), resolveSamples_, static_cast<float>(samples));
  gl_.BindVertexArray(emptyVertexArray_.id());
  gl_.DrawArrays(GL_TRIANGLES, 0, 3);
  gl_.BindTextureUnit(kResolveUnit, 0);  // the colour buffer is the next frame's target
}

const GlFrameRenderer::LitProgram* GlFrameRenderer::litProgram(const FrameInputs& frame, DrawVariant variant, LitOutput output) const {
  const auto found = litPrograms_.find(litProgramKey(frame, variant, output));
  return found == litPrograms_.end() ? nullptr : &found->second;
}

void GlFrameRenderer::drawInstance(const LitProgram& lit, const FrameInputs& frame, const FrameInstance& instance, bool flat, const PainterRun* run) {
  const MeshBuffers& mesh = scene_.mesh(instance.mesh);
  if (mesh.indexCount == 0) return;
  const CourseMaterial& material = frame.materials[static_cast<std::size_t>(instance.material)];
  const DrawVariant variant = drawVariant(frame, instance);
  const bool textured = variant.textured;

  const GLuint program = lit.program.id();
  gl_.ProgramUniformMatrix4fv(program, lit.clipFromModel, 1, GL_FALSE, glm::value_ptr(instance.clipFromModel));
  gl_.ProgramUniformMatrix4fv(program, lit.worldFromModel, 1, GL_FALSE, glm::value_ptr(instance.worldFromModel));
  gl_.ProgramUniformMatrix3fv(program, lit.normalMatrix, 1, GL_FALSE, glm::value_ptr(instance.normalMatrix));
  gl_.ProgramUniform3fv(program, lit.emissive, 1, glm::value_ptr(material.emissive));
  gl_.ProgramUniform1f(program, lit.ka, material.ka);
  gl_.ProgramUniform1f(program, lit.kd, material.kd);
  gl_.ProgramUniform1f(program, lit.ks, material.ks);
  gl_.ProgramUniform1f(program, lit.shininess, material.shininess);
  gl_.ProgramUniform1f(program, lit.metallic, material.metallic);
  gl_.ProgramUniform1f(program, lit.roughness, material.roughness);
  gl_.ProgramUniform3fv(program, lit.baseColorFactor, 1, glm::value_ptr(material.baseColor));
  gl_.ProgramUniform1i(program, lit.unlit, material.unlit ? 1 : 0);
  if (lit.additive >= 0) gl_.ProgramUniform1i(program, lit.additive, material.additive ? 1 : 0);
  setBaseColorUniforms(program, lit.alpha, material, textured);
  setMapUniforms(lit, material, variant);

  if (flat) {
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kMeshIndicesBinding, run ? run->indices : mesh.indices.id());
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kMeshPositionsBinding, mesh.positions.id());
    // Read only when textured (base colour or emissive); something valid is bound either way.
    const bool mapped = textured || variant.emissiveMap;
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kMeshTexcoordsBinding, mapped && mesh.texcoords ? mesh.texcoords.id() : mesh.positions.id());
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kMeshTexcoords1Binding, mapped && mesh.texcoords1 ? mesh.texcoords1.id() : mesh.positions.id());
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kMeshColorsBinding, variant.colored ? mesh.colors.id() : mesh.positions.id());
    gl_.BindVertexArray(emptyVertexArray_.id());
    if (run) gl_.DrawArrays(GL_TRIANGLES, 3 * run->first, 3 * run->count);  // gl_VertexID counts from 3·first
    else gl_.DrawArrays(GL_TRIANGLES, 0, mesh.indexCount);
  } else {
    drawIndexed(mesh, run);
  }
}

void GlFrameRenderer::drawIndexed(const MeshBuffers& mesh, const PainterRun* run) {
  gl_.BindVertexArray(mesh.vertexArray.id());
  if (!run) {
    gl_.DrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
    return;
  }
  // The run's indices from the painter's buffer, at three GLuint per position; the vertex array gets its own back.
  gl_.VertexArrayElementBuffer(mesh.vertexArray.id(), run->indices);
  gl_.DrawElements(GL_TRIANGLES, 3 * run->count, GL_UNSIGNED_INT,
                     reinterpret_cast<const void*>(static_cast<std::uintptr_t>(run->first) * 3 * sizeof(GLuint)));
  gl_.VertexArrayElementBuffer(mesh.vertexArray.id(), mesh.indices.id());
}

GlFrameRenderer::AlphaUniforms GlFrameRenderer::alphaUniforms(const ShaderProgram& program) const {
  return {uniformLocation(gl_, program, "baseColorSampler"), uniformLocation(gl_, program, "baseColorTransform"),
          uniformLocation(gl_, program, "baseColorSet"), uniformLocation(gl_, program, "baseAlpha"), uniformLocation(gl_, program, "alphaCutoff")};
}

template <class Program, class Make>
bool GlFrameRenderer::prepareMaskPrograms(std::map<int, Program>& programs, const FrameInputs& frame, std::initializer_list<std::string_view> stages,
                                          Make make) {
  bool built = false;
  for (const FrameInstance& instance : frame.instances) {
    const DrawVariant variant = maskVariant(frame, instance);
    if (programs.count(variant.index())) continue;
    programs.emplace(variant.index(), make(buildProgram(gl_, stages, drawVariantDefines(variant))));
    built = true;
  }
  return built;
}

void GlFrameRenderer::setBaseColorUniforms(GLuint program, const AlphaUniforms& uniforms, const CourseMaterial& material, bool textured) {
  const GLint samplerLocation = uniforms.baseColorSampler;
  gl_.ProgramUniform1f(program, uniforms.baseAlpha, material.baseAlpha);
  const glm::vec3 rows[2] = {material.uvRow0, material.uvRow1};
  gl_.ProgramUniform3fv(program, uniforms.baseColorTransform, 2, glm::value_ptr(rows[0]));
  gl_.ProgramUniform1f(program, uniforms.alphaCutoff, material.alphaCutoff);
  gl_.ProgramUniform1i(program, uniforms.baseColorSet, material.baseColorSet == 1 ? 1 : 0);
  const Sampler& sampler = material.baseColorSampler;
  static_assert(static_cast<int>(MagFilter::Linear) == 1 && static_cast<int>(MinFilter::NearestMipmapNearest) == 2 &&
                    static_cast<int>(MinFilter::LinearMipmapLinear) == 5 && static_cast<int>(Wrap::MirroredRepeat) == 2,
                "shaders/texture.glsl reads these values");
  gl_.ProgramUniform4i(program, samplerLocation, static_cast<GLint>(sampler.mag), static_cast<GLint>(sampler.min), static_cast<GLint>(sampler.wrapS),
                         static_cast<GLint>(sampler.wrapT));
  gl_.BindTextureUnit(kBaseColorTextureUnit, textured ? scene_.texture(material.baseColorTexture) : 0);
}

void GlFrameRenderer::setMapUniforms(const LitProgram& lit, const CourseMaterial& material, DrawVariant variant) {
  const GLuint program = lit.program.id();
  const struct {
    bool used;
    const MaterialMap& map;
    GLint sampler;
    GLuint unit;
  } maps[] = {{variant.metallicRoughnessMap, material.metallicRoughnessMap, lit.metallicRoughnessSampler, kMetallicRoughnessUnit},
              {variant.occlusionMap, material.occlusionMap, lit.occlusionSampler, kOcclusionUnit},
              {variant.emissiveMap, material.emissiveMap, lit.emissiveSampler, kEmissiveUnit},
              {variant.normalMap, material.normalMap, lit.normalMapSampler, kNormalMapUnit}};
  for (const auto& m : maps) {
    if (!m.used) continue;
    const Sampler& s = m.map.sampler;
    gl_.ProgramUniform4i(program, m.sampler, static_cast<GLint>(s.mag), static_cast<GLint>(s.min), static_cast<GLint>(s.wrapS), static_cast<GLint>(s.wrapT));
    gl_.BindTextureUnit(m.unit, scene_.texture(m.map.texture));
  }
  if (variant.occlusionMap) gl_.ProgramUniform1f(program, lit.occlusionStrength, material.occlusionStrength);
  if (variant.normalMap) gl_.ProgramUniform1f(program, lit.normalScale, material.normalScale);
  const auto set = [](const MaterialMap& map) { return map.set == 1 ? 1 : 0; };
  gl_.ProgramUniform4i(program, lit.mapSets, set(material.metallicRoughnessMap), set(material.occlusionMap), set(material.emissiveMap),
                         set(material.normalMap));
  gl_.ProgramUniform4i(program, lit.mapsSrgb, material.metallicRoughnessMap.srgb ? 1 : 0, material.occlusionMap.srgb ? 1 : 0,
                         material.emissiveMap.srgb ? 1 : 0, material.normalMap.srgb ? 1 : 0);
}

void GlFrameRenderer::checkError(const char* where) const { checkGlError(gl_, where); }


}  // namespace facet::gl
