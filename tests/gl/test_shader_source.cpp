// Shader sources: #include expansion, error messages that name the file, and
// every embedded program compiling and linking on the driver.
#include <map>
#include <regex>
#include <string>

#include <vector>

#include <doctest/doctest.h>

#include "common/error.h"
#include "gl/embedded_shaders.h"
#include "gl/shader_program.h"
#include "gl/shader_source.h"
#include "gl/shader_variant.h"
#include "gl_test_support.h"
#include "pipeline/frame_inputs.h"
#include "scene/default_scene.h"

using namespace facet;
using namespace facet::gl;

namespace {

// Shader files from a map, then from the embedded shaders/.
ShaderFileLookup lookupIn(const std::map<std::string, std::string, std::less<>>& files) {
  return [&files](std::string_view name) -> std::optional<std::string_view> {
    if (auto it = files.find(name); it != files.end()) return it->second;
    return findEmbeddedShaderFile(name);
  };
}

}  // namespace

TEST_CASE("#include lines are replaced by the file, once per stage, between #line directives") {
  const std::map<std::string, std::string, std::less<>> files = {
      {"main.frag", "#version 450 core\n#include \"a.glsl\"\n#include \"b.glsl\"\nvoid main() {}\n"},
      {"a.glsl", "float a() { return 1.0; }\n"},
      {"b.glsl", "#include \"a.glsl\"\nfloat b() { return a(); }"},  // a.glsl again, and no final newline
  };
  const ShaderSource source = assembleShaderSource("main.frag", lookupIn(files));
  CHECK(source.files == std::vector<std::string>{"main.frag", "a.glsl", "b.glsl"});
  CHECK(source.text ==
        "#version 450 core\n"
        "#line 1 1\nfloat a() { return 1.0; }\n#line 3 0\n"
        "#line 1 2\n\nfloat b() { return a(); }\n#line 4 0\n"
        "void main() {}\n");
  CHECK_THROWS_WITH_AS(assembleShaderSource("nothere.frag", lookupIn(files)), doctest::Contains("nothere.frag: no such file"), Error);
}

TEST_CASE("a driver log names files, on one line") {
  const std::vector<std::string> files = {"lit_phong.frag", "frame_block.glsl"};
  CHECK(describeLog("1:12(5): error: `x' undeclared\n0:3(1): error: y\n\n", files) ==
        "frame_block.glsl:12(5): error: `x' undeclared; lit_phong.frag:3(1): error: y");
  CHECK(describeLog("7:1(1): warning: z\n", files) == "7:1(1): warning: z");  // no such file: left as it is
}

namespace {

// The draw variants with at most two macros on, and those with at most two
// off: every pair of macros is compiled in all four combinations (and every
// macro alone), at a fifth of the cost of all 2^9 variants.
std::vector<int> pairwiseVariants() {
  std::vector<int> variants;
  for (int v = 0; v < DrawVariant::kCount; ++v) {
    const int on = __builtin_popcount(static_cast<unsigned>(v)), bits = __builtin_popcount(static_cast<unsigned>(DrawVariant::kCount - 1));
    if (on <= 2 || bits - on <= 2) variants.push_back(v);
  }
  return variants;
}

// The lights the lit programs are specialized for: none; the default point
// light with its shadow maps; three kinds, the first without a map, Phong
// specular, PCF radius 0.
enum class Lights { None, Default, ThreeKinds };

RenderSettings settingsWith(Lights lights) {
  RenderSettings settings;
  if (lights == Lights::None) {
    settings.lightSource = Source::Manual;
    settings.lights.clear();
  } else if (lights == Lights::ThreeKinds) {
    settings.lightSource = Source::Manual;
    settings.specular = SpecularModel::Phong;
    settings.shadows.pcfRadius = 0;
    for (LightKind kind : {LightKind::Directional, LightKind::Spot, LightKind::Point}) {
      Light light;
      light.kind = kind;
      light.position = {1.0f, 5.0f, 2.0f};
      light.direction = glm::normalize(glm::vec3(-1.0f, -5.0f, -2.0f));
      light.castsShadow = kind != LightKind::Directional;
      settings.lights.push_back(light);
    }
  }
  return settings;
}

// lit_MODE with `lights`: a fourth of the pairwise variants, every fourth
// one from `quarter` on. A quarter per test case, so that ctest compiles
// them in parallel and none takes long: with a cold shader cache llvmpipe
// compiles each program anew (Phong with every map on the longest), and the
// nine families hold 828 programs.
constexpr int kQuarters = 4;
void checkLitPrograms(ShadingMode mode, Lights lights, int quarter) {
  test::GlHarness harness;
  const FrameInputs frame = buildFrameInputs(makeDefaultScene(), settingsWith(lights));
  const std::string name(kShadingModeNames[static_cast<std::size_t>(mode)]);
  const std::vector<int> variants = pairwiseVariants();
  for (std::size_t i = static_cast<std::size_t>(quarter); i < variants.size(); i += kQuarters) {
    const std::string defines = litShaderDefines(frame, DrawVariant::of(variants[i]));
    INFO(name, "\n", defines);
    CHECK_NOTHROW(buildProgram(harness.gl, {"lit_" + name + ".vert", "lit_" + name + ".frag"}, defines));
  }
}

}  // namespace

TEST_CASE("every shader file is embedded") {
  for (const char* name : {"frame_block.glsl", "transform.glsl", "shading_math.glsl", "lighting.glsl", "srgb.glsl", "texture.glsl", "draw_uniforms.glsl"})
    CHECK_MESSAGE(findEmbeddedShaderFile(name).has_value(), name);
}

// The lit programs of one shading mode and set of lights, every pair of specializations, in four test cases.
#define FACET_LIT_PROGRAMS(mode, lights, family)                                                                                                      \
  TEST_CASE("every lit program compiles and links, every pair of specializations: " family ", quarter 1") { checkLitPrograms(mode, lights, 0); } \
  TEST_CASE("every lit program compiles and links, every pair of specializations: " family ", quarter 2") { checkLitPrograms(mode, lights, 1); } \
  TEST_CASE("every lit program compiles and links, every pair of specializations: " family ", quarter 3") { checkLitPrograms(mode, lights, 2); } \
  TEST_CASE("every lit program compiles and links, every pair of specializations: " family ", quarter 4") { checkLitPrograms(mode, lights, 3); }
static_assert(kQuarters == 4, "FACET_LIT_PROGRAMS declares a test case per quarter");
FACET_LIT_PROGRAMS(ShadingMode::Flat, Lights::None, "flat, no light")
FACET_LIT_PROGRAMS(ShadingMode::Flat, Lights::Default, "flat, the default light")
FACET_LIT_PROGRAMS(ShadingMode::Flat, Lights::ThreeKinds, "flat, three kinds of light")
FACET_LIT_PROGRAMS(ShadingMode::Gouraud, Lights::None, "gouraud, no light")
FACET_LIT_PROGRAMS(ShadingMode::Gouraud, Lights::Default, "gouraud, the default light")
FACET_LIT_PROGRAMS(ShadingMode::Gouraud, Lights::ThreeKinds, "gouraud, three kinds of light")
FACET_LIT_PROGRAMS(ShadingMode::Phong, Lights::None, "phong, no light")
FACET_LIT_PROGRAMS(ShadingMode::Phong, Lights::Default, "phong, the default light")
FACET_LIT_PROGRAMS(ShadingMode::Phong, Lights::ThreeKinds, "phong, three kinds of light")
#undef FACET_LIT_PROGRAMS

// The shadow pass and the triangle-id pass, each its own family.
TEST_CASE("every shadow-depth program compiles and links, every pair of specializations") {
  test::GlHarness harness;
  for (const int variant : pairwiseVariants()) {
    const std::string defines = drawVariantDefines(DrawVariant::of(variant));
    INFO(defines);
    CHECK_NOTHROW(buildProgram(harness.gl, {"shadow_depth.vert", "shadow_depth.frag"}, defines));
  }
}

TEST_CASE("every triangle-id program compiles and links, every pair of specializations") {
  test::GlHarness harness;
  for (const int variant : pairwiseVariants()) {
    const std::string defines = drawVariantDefines(DrawVariant::of(variant));
    INFO(defines);
    CHECK_NOTHROW(buildProgram(harness.gl, {"triangle_id.vert", "triangle_id.frag"}, defines));
  }
}

TEST_CASE("the background program compiles and links, and each fog mode in the lit programs (every texture and map on) and the line program") {
  test::GlHarness harness;
  const Scene scene = makeDefaultScene();
  CHECK_NOTHROW(buildProgram(harness.gl, {"viewport_triangle.vert", "background.frag"}));
  for (FogMode fog : {FogMode::None, FogMode::Linear, FogMode::Exponential, FogMode::Exponential2}) {
    RenderSettings settings;
    settings.fog.mode = fog;
    const FrameInputs frame = buildFrameInputs(scene, settings);
    for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong}) {
      const std::string name(kShadingModeNames[static_cast<std::size_t>(mode)]);
      const std::string defines = litShaderDefines(frame, DrawVariant::of(DrawVariant::kCount - 1));
      INFO(name, "\n", defines);
      CHECK_NOTHROW(buildProgram(harness.gl, {"lit_" + name + ".vert", "lit_" + name + ".frag"}, defines));
    }
    CHECK_NOTHROW(buildProgram(harness.gl, {"line.vert", "line.frag"}, fogDefine(frame)));
  }
}

TEST_CASE("the normals stage's lit programs compile and link: flat, Phong and pbr, each draw variant that is not blended") {
  // FACET_NORMAL_OUTPUT (renderer/PIPELINE.md, "Stages"); Gouraud frames are drawn as Phong ones.
  test::GlHarness harness;
  const Scene scene = makeDefaultScene();
  std::vector<int> variants = {0, DrawVariant::kCount - 1 - DrawVariant{.blended = true}.index()};  // none, and every one but blending
  for (int bit = 1; bit < DrawVariant::kCount / 2; bit <<= 1) variants.push_back(bit);
  for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Phong, ShadingMode::Pbr}) {
    RenderSettings settings;
    settings.shading = mode;
    const FrameInputs frame = buildFrameInputs(scene, settings);
    const std::string stages = mode == ShadingMode::Flat ? "lit_flat" : "lit_phong";
    for (const int variant : variants) {
      const std::string defines = litShaderDefines(frame, DrawVariant::of(variant), LitOutput::Normal);
      INFO(stages, "\n", defines);
      CHECK(defines.find("#define FACET_NORMAL_OUTPUT 1\n") != std::string::npos);
      CHECK_NOTHROW(buildProgram(harness.gl, {stages + ".vert", stages + ".frag"}, defines));
    }
  }
}

TEST_CASE("a shader that does not compile: facet::Error names the file and line, with the driver's log") {
  test::GlHarness harness;
  const std::map<std::string, std::string, std::less<>> files = {
      {"broken.frag", "#version 450 core\n#include \"helper.glsl\"\nout vec4 color;\nvoid main() { color = helper(); }\n"},
      {"helper.glsl", "vec4 helper() {\n  return undeclaredThing;\n}\n"},
  };
  try {
    buildProgram(harness.gl, {"viewport_triangle.vert", "broken.frag"}, "", lookupIn(files));
    FAIL("expected facet::Error");
  } catch (const Error& e) {
    const std::string message = e.what();
    INFO(message);
    CHECK(message.find("shader broken.frag does not compile") == 0);
    CHECK(message.find("helper.glsl:2(") != std::string::npos);  // the line inside the included file
    CHECK(message.find("undeclaredThing") != std::string::npos);  // the driver's own words
    CHECK(message.find('\n') == std::string::npos);
  }
}

TEST_CASE("defines after #version leave the driver's line numbers those of the file") {
  test::GlHarness harness;
  const std::map<std::string, std::string, std::less<>> files = {
      {"broken.frag", "#version 450 core\nout vec4 color;\nvoid main() { color = vec4(FACET_VALUE) + undeclaredThing; }\n"},
  };
  try {
    buildProgram(harness.gl, {"viewport_triangle.vert", "broken.frag"}, "#define FACET_VALUE 1.0\n#define FACET_OTHER 2\n", lookupIn(files));
    FAIL("expected facet::Error");
  } catch (const Error& e) {
    const std::string message = e.what();
    INFO(message);
    CHECK(message.find("broken.frag:3(") != std::string::npos);
    CHECK(message.find("undeclaredThing") != std::string::npos);
  }
}

TEST_CASE("stages that do not link: facet::Error names the program, with the driver's log") {
  test::GlHarness harness;
  const std::map<std::string, std::string, std::less<>> files = {
      {"mismatch.vert", "#version 450 core\nout vec3 value;\nvoid main() { value = vec3(1.0); gl_Position = vec4(0.0); }\n"},
      {"mismatch.frag", "#version 450 core\nin vec4 value;\nout vec4 color;\nvoid main() { color = value; }\n"},
  };
  try {
    buildProgram(harness.gl, {"mismatch.vert", "mismatch.frag"}, "", lookupIn(files));
    FAIL("expected facet::Error");
  } catch (const Error& e) {
    const std::string message = e.what();
    INFO(message);
    CHECK(message.find("shader program mismatch.vert + mismatch.frag does not link: ") == 0);
    CHECK(message.find("value") != std::string::npos);
  }
}

// A loop that skips its rest by `continue` made llvmpipe's code for the lit
// pass slower than the same loop skipping by an `if` (the same
// instructions, one more branch), so no
// shader has one. Comments are left out of the search.
TEST_CASE("no shader skips a loop's rest by continue") {
  const std::regex word("\\bcontinue\\b");
  for (const ShaderFile& file : embeddedShaderFiles()) {
    std::string code(file.text);
    code = std::regex_replace(code, std::regex("//[^\n]*"), "");
    INFO(file.name);
    CHECK_FALSE(std::regex_search(code, word));
  }
}
