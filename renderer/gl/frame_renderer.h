#pragma once
// Draws frames with OpenGL 4.5 into an offscreen framebuffer, as
// renderer/PIPELINE.md lays them out: shadow pass 1 into a depth array
// texture, then the lit pass (background, then every mesh instance with
// flat, Gouraud or Phong shading) into a linear RGBA32F colour buffer, then
// the resolve into the RGBA8 image. A frame where nothing blends or
// averages colours writes the resolve's levels straight from the lit pass
// instead, into the RGBA8 image: the same bytes, without the float buffer. It needs only a current context and that
// context's getProcAddress, so the headless renderer (gl_renderer.cpp) and
// the viewer's GLFW window share it. Every call needs its context current.
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "gl/frame_block.h"
#include "gl/gl_functions.h"
#include "gl/render_target.h"
#include "gl/painters_draws.h"
#include "gl/scene_buffers.h"
#include "gl/shader_program.h"
#include "gl/shader_variant.h"
#include "pipeline/shadow_pass_key.h"
#include "render/renderer.h"

namespace facet::gl {

class GlFrameRenderer {
 public:
  // Loads the function table; throws facet::Error without OpenGL 4.5 core.
  explicit GlFrameRenderer(const GetProcAddress& getProcAddress);
  GlFrameRenderer(const GlFrameRenderer&) = delete;  // GL objects point at gl_
  GlFrameRenderer& operator=(const GlFrameRenderer&) = delete;

  // GL_RENDERER and GL_VERSION.
  const std::string& rendererName() const { return rendererName_; }

  // Uploads the scene's meshes and textures; the frames drawn next must be built from this scene.
  void uploadScene(const Scene& scene);

  // Pass 1, the lit pass and the resolve of one frame, with glFinish between them so that
  // each timing is that pass's. The frame must have passed checkFrame
  // (pipeline/frame_checks.h) against the uploaded scene. Throws
  // facet::Error (driver limits, framebuffer, shaders, a GL error).
  // `scene` is the uploaded one (the painter's algorithm reads its indices).
  // Encoding::ByResolve takes the float buffer and the resolve for every
  // frame (the tests hold the default to it).
  enum class Encoding { AsDrawnWherePossible, ByResolve };
  std::vector<PassTiming> drawFrame(const Scene& scene, const FrameInputs& frame, Encoding encoding = Encoding::AsDrawnWherePossible);

  // The next frame draws its shadow maps (Renderer::forgetShadowMaps).
  void forgetShadowMaps() { mapsDrawn_ = {}; }

  // The last frame's RGBA8 pixels, bottom row first as glReadPixels gives
  // them, read into `storage` (resized: a recycled image keeps its memory).
  Image readImage(Image storage = {}) const;

  // Which triangle each pixel keeps (FrameOutput::TriangleIds): the lit
  // pass's geometry, culling and z-buffer, writing ids instead of colours.
  std::vector<std::uint32_t> drawTriangleIds(const Scene& scene, const FrameInputs& frame);

  // The depth complexity (FrameOutput::FragmentCounts): every triangle the lit
  // pass draws, culled alike, with no depth test, each fragment adding 1 to
  // a 32-bit float (exact to 2^24).
  std::vector<std::uint32_t> drawFragmentCounts(const FrameInputs& frame);

  // The lit pass's z-buffer after the frame drawn at the pixel centres
  // (FrameOutput::Depth): its DEPTH_COMPONENT32F attachment read as float.
  std::vector<float> drawDepth(const Scene& scene, const FrameInputs& frame);

  // Pass 1's depth array texture (FrameOutput::ShadowMaps), drawn unless it holds this frame's maps already.
  ShadowMapTexels readShadowMaps(const Scene& scene, const FrameInputs& frame);

  // The normals stage (FrameOutput::Normals): normalsFrame's lit pass with the
  // FACET_NORMAL_OUTPUT programs, opaque triangles only, read back as float.
  std::vector<glm::vec4> drawNormals(const Scene& scene, const FrameInputs& frame);

  // The framebuffer holding drawFrame's image (colour attachment 0, RGBA8), for a viewer to blit from.
  GLuint framebuffer() const { return image_->framebuffer(); }

 private:
  // A lit-pass program and its uniform locations (shaders/draw_uniforms.glsl).
  // The program comes last: aggregate initialization evaluates in order, and
  // the locations are looked up before the program is moved in.
  // The base colour texture's sampler and the alpha mask's uniforms of a program that reads them.
  struct AlphaUniforms {
    GLint baseColorSampler, baseColorTransform, baseColorSet, baseAlpha, alphaCutoff;
  };
  struct LitProgram {
    GLint clipFromModel, worldFromModel, normalMatrix;
    GLint emissive, ka, kd, ks, shininess, metallic, roughness;
    GLint metallicRoughnessSampler, occlusionSampler, emissiveSampler, occlusionStrength, mapsSrgb;
    GLint normalMapSampler, normalScale;  // the normal texture (Phong and pbr)
    GLint mapSets;                        // the texture coordinate set of each map above
    GLint baseColorFactor;
    GLint unlit, additive;                // KHR_materials_unlit; the additive blending equation
    AlphaUniforms alpha;
    ShaderProgram program;
  };
  struct DepthProgram {
    GLint lightClipFromWorld, worldFromModel;
    AlphaUniforms alpha;
    ShaderProgram program;
  };

  // What every pass of a frame starts with: the painter's and the blended
  // triangles' index buffers, the programs, the uniform blocks, the GL
  // conventions, and pass 1 unless its maps are kept; its timings appended.
  void beginFrame(const Scene& scene, const FrameInputs& frame, LitOutput output, std::vector<PassTiming>& timings);
  // Compiles what the frame needs and has not been compiled yet; true when it compiled anything.
  bool preparePrograms(const FrameInputs& frame, LitOutput output);
  // The lit program of `frame` for draws of `variant` writing `output`; null when not prepared.
  const LitProgram* litProgram(const FrameInputs& frame, DrawVariant variant, LitOutput output) const;
  // What the instance's draw reads: a base colour texture, vertex colours.
  DrawVariant drawVariant(const FrameInputs& frame, const FrameInstance& instance) const;
  // What the shadow pass and the triangle-id pass draw `instance` with: only an alpha mask changes them.
  DrawVariant maskVariant(const FrameInputs& frame, const FrameInstance& instance) const;
  // The base colour texture, its sampler and the alpha mask's uniforms of `material` on `program`.
  void setBaseColorUniforms(GLuint program, const AlphaUniforms& uniforms, const CourseMaterial& material, bool textured);
  // Binds shading=pbr's maps the variant reads and sets their samplers and the occlusion strength.
  void setMapUniforms(const LitProgram& lit, const CourseMaterial& material, DrawVariant variant);
  AlphaUniforms alphaUniforms(const ShaderProgram& program) const;
  // Builds the program of `stages` for each mask variant the frame's instances
  // draw with and `programs` lacks (make turns it into a Program); true when it built one.
  template <class Program, class Make>
  bool prepareMaskPrograms(std::map<int, Program>& programs, const FrameInputs& frame, std::initializer_list<std::string_view> stages, Make make);
  // Back-face culling as the instance asks (FrameInstance::cullBackFaces).
  void setCulling(bool cull);
  void shadowPass(const FrameInputs& frame);
  // Nothing blends or averages the frame's colours: no blended draw, one
  // sample. Each pixel's image is then the resolve of the last colour
  // written there, which the lit pass can encode as it writes it.
  static bool encodesAsDrawn(const FrameInputs& frame);
  // The background, the opaque triangles, lines and points, then the blended
  // triangles, into target_; LitOutput::Levels: the same as levels, into
  // levels_; LitOutput::Normal: the opaque triangles alone, over 0.
  void litPass(const FrameInputs& frame, LitOutput output = LitOutput::Color);
  // The instance's triangles, or those of one painter's run (null: all, in the mesh's order).
  void drawInstance(const LitProgram& lit, const FrameInputs& frame, const FrameInstance& instance, bool flat, const PainterRun* run = nullptr);
  // The mesh's triangles through its vertex array, or one painter's run of them.
  void drawIndexed(const MeshBuffers& mesh, const PainterRun* run);
  void drawLines(const FrameInputs& frame, bool levels);
  // A colour buffer encoded into `resolved_` (shaders/resolve.frag): `source`
  // holds its colours premultiplied or not, summed over `samples` passes.
  void resolvePass(const FrameInputs& frame, GLuint source, bool premultiplied, int samples);
  // Anti-aliasing: target_'s sample added into sum_ (shaders/accumulate.frag).
  void accumulatePass(const FrameInputs& frame);
  void checkError(const char* where) const;

  GlFunctions gl_;
  std::string rendererName_;
  // Lit programs by shading mode and specialization (gl/shader_variant.h),
  // kept while the frame's lights and settings keep asking for them.
  std::map<std::string, LitProgram> litPrograms_;
  std::map<int, DepthProgram> depthPrograms_;  // by DrawVariant::index(); only masked draws differ
  std::optional<ShaderProgram> backgroundProgram_;
  GLint backgroundViewportSize_ = -1;  // its uniform vec2 viewportSize
  GLint backgroundAlpha_ = -1;         // its uniform float backgroundAlpha
  GLint backgroundPremultiplied_ = -1;  // its uniform bool premultiplied
  GLint resolvePremultiplied_ = -1;     // the resolve's
  GLint resolveSamples_ = -1;
  GLint backgroundSampleOffset_ = -1;
  GLint backgroundLevels_ = -1;         // its uniform bool levels
  std::optional<ShaderProgram> accumulateProgram_;
  GLint accumulatePremultiplied_ = -1;
  std::optional<ShaderProgram> resolveProgram_;
  struct LineProgram {
    GLint clipFromModel, colored, baseColorFactor, levels;
    ShaderProgram program;
  };
  std::optional<LineProgram> lineProgram_;  // segments and points (line.vert, line.frag)
  FogMode lineFog_ = FogMode::None;          // the fog mode lineProgram_ is built for
  struct TriangleIdProgram {
    GLint clipFromModel, firstTriangle, painted;
    AlphaUniforms alpha;
    ShaderProgram program;
  };
  std::map<int, TriangleIdProgram> triangleIdPrograms_;  // by DrawVariant::index(); only masked draws differ
  struct FragmentCountProgram {
    GLint clipFromModel;
    ShaderProgram program;
  };
  std::optional<FragmentCountProgram> fragmentCountProgram_;  // triangle_id.vert, fragment_count.frag
  GlObject frameUniforms_;     // the Frame block (FrameBlock), binding 0
  GlObject srgbUniforms_;      // the SrgbTables block (SrgbBlock), binding 1, written once
  GlObject splitSumUniforms_;  // the SplitSumTable block (SplitSumBlock), binding 2, written at the first pbr frame
  GlObject emptyVertexArray_;  // for draws that read no attributes (background, flat shading)
  SceneBuffers scene_;
  PaintersDraws painters_;  // hsr = painter: the frame's triangles back to front
  PaintersDraws transparent_;  // the blended triangles back to front, after the rest
  ShadowMapArray shadowMaps_;
  ShadowPassKey mapsDrawn_;  // what shadowMaps_ holds the maps of
  RenderTarget target_{GL_RGBA32F};  // the lit pass's colour buffer, linear RGBA
  RenderTarget resolved_{GL_RGBA8, RenderTarget::Depth::Without};
  RenderTarget levels_{GL_RGBA8};  // a frame encoded as drawn: the image, with the lit pass's depth
  const RenderTarget* image_ = &resolved_;  // which of the two holds the last frame's image
  RenderTarget sum_{GL_RGBA32F, RenderTarget::Depth::Without};  // anti-aliasing: the samples' premultiplied sum
  RenderTarget idTarget_{GL_R32UI};
  RenderTarget countTarget_{GL_R32F};
};

}  // namespace facet::gl
