// facet render's -o templates (app/output_template.h): F3D's syntax, facet's
// placeholders, frame numbers padded so that names sort, and one usage error
// naming the option and the fault for anything else.
#include <string>

#include <doctest/doctest.h>

#include "common/error.h"
#include "output_template.h"

using namespace facet;

namespace {

const TemplateValues kValues{"DamagedHelmet", "cpu"};

std::string expand(const std::string& pattern, int frame = 0, int frames = 1) { return OutputTemplate(pattern, "-o").expand(kValues, frame, frames); }

}  // namespace

TEST_CASE("a name without placeholders is itself, and numbers no frames") {
  CHECK(expand("out.png") == "out.png");
  CHECK_FALSE(OutputTemplate("out.png", "-o").numbersFrames());
}

TEST_CASE("{scene} and {backend} name the run, and {{ and }} write braces") {
  CHECK(expand("renders/{scene}-{backend}.png") == "renders/DamagedHelmet-cpu.png");
  CHECK(expand("{{scene}}.png") == "{scene}.png");
  CHECK(expand("a{{{backend}}}.png") == "a{cpu}.png");
}

TEST_CASE("{frame} and {n} are the frame, padded to the digits of the last one, {frame:W} to W") {
  CHECK(OutputTemplate("t_{frame}.png", "-o").numbersFrames());
  CHECK(OutputTemplate("t_{n}.png", "-o").numbersFrames());
  CHECK(expand("t_{frame}.png", 3, 4) == "t_3.png");
  CHECK(expand("t_{n}.png", 3, 36) == "t_03.png");
  CHECK(expand("t_{frame}.png", 35, 36) == "t_35.png");
  CHECK(expand("t_{frame}.png", 7, 3600) == "t_0007.png");
  CHECK(expand("t_{frame:4}.png", 7, 36) == "t_0007.png");
  CHECK(expand("t_{frame:1}.png", 12, 36) == "t_12.png");  // a width is a minimum
  CHECK(expand("{scene}_{frame}.png", 0, 1) == "DamagedHelmet_0.png");
}

TEST_CASE("an unknown placeholder, a lone brace or a bad width is one usage error naming the option") {
  CHECK_THROWS_WITH_AS(OutputTemplate("out_{model}.png", "-o"),
                       "-o 'out_{model}.png': unknown placeholder '{model}' (known: {scene}, {backend}, {frame}, {n}, {frame:W}; {{ and }} write braces)",
                       UsageError);
  CHECK_THROWS_WITH_AS(OutputTemplate("out_{}.png", "-o"), doctest::Contains("unknown placeholder '{}'"), UsageError);
  CHECK_THROWS_WITH_AS(OutputTemplate("out_{frame.png", "-o"), "-o 'out_{frame.png': a '{' without its '}' (write {{ for a brace)", UsageError);
  CHECK_THROWS_WITH_AS(OutputTemplate("out_frame}.png", "-o"), "-o 'out_frame}.png': a '}' without its '{' (write }} for a brace)", UsageError);
  CHECK_THROWS_WITH_AS(OutputTemplate("{frame:0}.png", "-o"), doctest::Contains("'{frame:0}': the width must be a digit from 1 to 9"), UsageError);
  CHECK_THROWS_WITH_AS(OutputTemplate("{frame:12}.png", "-o"), doctest::Contains("the width must be a digit from 1 to 9"), UsageError);
  CHECK_THROWS_WITH_AS(OutputTemplate("{scene:3}.png", "--shadow-report"),
                       "--shadow-report '{scene:3}.png': '{scene:3}': only {frame} and {n} take a width", UsageError);
}

TEST_CASE("{scene} is the file's name without folder and extension, or the builtin's name") {
  CHECK(sceneNameOf("") == "default");
  CHECK(sceneNameOf("builtin:default") == "default");
  CHECK(sceneNameOf("builtin:torus+ground") == "torus+ground");
  CHECK(sceneNameOf("/models/DamagedHelmet.glb") == "DamagedHelmet");
  CHECK(sceneNameOf("scene.gltf") == "scene");
  CHECK(sceneNameOf("data/anatomical.nii.gz") == "anatomical");
  CHECK(sceneNameOf("data/anatomical.nii") == "anatomical");
}
