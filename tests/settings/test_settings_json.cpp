// RenderSettings <-> JSON: round trip, strictness, --set.
#include <filesystem>
#include <fstream>
#include <limits>

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include "common/error.h"
#include "settings/settings_json.h"

using namespace facet;
using nlohmann::json;

TEST_CASE("defaults survive a JSON round trip unchanged") {
  RenderSettings s;
  s.lights.push_back(Light{});
  s.material.ks = 0.25f;
  const json j = settingsToJson(s);
  CHECK(settingsToJson(settingsFromJson(j)) == j);
  CHECK(j["shading"] == "phong");
  CHECK(j["material"]["ka"].is_null());
  CHECK(j["material"]["ks"] == 0.25);
  CHECK(j["ambient"] == 0.15);  // floats are written as their shortest decimal
}

TEST_CASE("reading a partial object keeps the other defaults") {
  const RenderSettings s = settingsFromJson(json::parse(R"({"shading": "gouraud", "shadows": {"pcfRadius": 2}})"));
  CHECK(s.shading == ShadingMode::Gouraud);
  CHECK(s.shadows.pcfRadius == 2);
  CHECK(s.shadows.mapSize == RenderSettings{}.shadows.mapSize);
}

TEST_CASE("bad settings name the key") {
  CHECK_THROWS_WITH_AS(settingsFromJson(json::parse(R"({"camera": {"ey": [1,2,3]}})")), "settings key 'camera.ey': unknown key", Error);
  CHECK_THROWS_WITH_AS(settingsFromJson(json::parse(R"({"shading": "toon"})")), doctest::Contains("'shading': expected one of flat, gouraud, phong"), Error);
  CHECK_THROWS_WITH_AS(settingsFromJson(json::parse(R"({"width": 0})")), doctest::Contains("'width': 0"), Error);
  CHECK_THROWS_WITH_AS(settingsFromJson(json::parse(R"({"width": 10.5})")), doctest::Contains("'width': expected an integer"), Error);
  CHECK_THROWS_WITH_AS(settingsFromJson(json::parse(R"({"lights": [{"intensity": -1}]})")), doctest::Contains("'lights.0.intensity'"), Error);
  CHECK_THROWS_WITH_AS(settingsFromJson(json::parse(R"({"lights": [{"kind": "point", "colour": [1,1,1]}]})")), "settings key 'lights.0.colour': unknown key", Error);
  CHECK_THROWS_WITH_AS(settingsFromJson(json::parse(R"({"camera": {"near": 5, "far": 1}})")), doctest::Contains("'camera.far'"), Error);
  CHECK_THROWS_WITH_AS(settingsFromJson(json::parse(R"({"background": [0, 0]})")), doctest::Contains("'background': expected [x, y, z]"), Error);
  CHECK_THROWS_WITH_AS(settingsFromJson(json::parse(R"({"shadows": {"biasMin": "small"}})")), doctest::Contains("'shadows.biasMin': expected a number"), Error);
}

TEST_CASE("--set assigns dotted keys, parses JSON values and bare words, appends lights") {
  RenderSettings s;
  applySetting(s, "shading=gouraud");
  applySetting(s, "camera.eye=[1,4,2]");
  applySetting(s, "shadows.enabled=false");
  applySetting(s, "material.shininess=64");
  applySetting(s, "lights.0.kind=spot");  // index == size appends a default light
  applySetting(s, "lights.0.position=[0,3,0]");
  CHECK(s.shading == ShadingMode::Gouraud);
  CHECK(s.camera.eye == glm::vec3(1, 4, 2));
  CHECK_FALSE(s.shadows.enabled);
  CHECK(s.material.shininess.value() == 64.0f);
  REQUIRE(s.lights.size() == 1);
  CHECK(s.lights[0].kind == LightKind::Spot);
  CHECK(s.lights[0].position == glm::vec3(0, 3, 0));
  CHECK_THROWS_WITH_AS(applySetting(s, "lights.5.kind=spot"), doctest::Contains("'lights.5': index past the end"), Error);
  CHECK_THROWS_WITH_AS(applySetting(s, "camera.fov=3"), "settings key 'camera.fov': unknown key", Error);
  CHECK_THROWS_WITH_AS(applySetting(s, "shading"), doctest::Contains("expected key=value"), Error);
  CHECK_THROWS_WITH_AS(applySetting(s, "shadows.mapSize=1"), doctest::Contains("'shadows.mapSize'"), Error);
}

TEST_CASE("a settings file with an error names the file and the key") {
  CHECK_THROWS_WITH_AS(loadSettingsFile(FACET_TEST_DATA "/settings/bad_key.json"), doctest::Contains("bad_key.json: settings key 'shadows.pcf'"), Error);
  CHECK_THROWS_WITH_AS(loadSettingsFile(FACET_TEST_DATA "/settings/not_json.json"), doctest::Contains("not_json.json: not valid JSON"), Error);
  const RenderSettings s = loadSettingsFile(FACET_TEST_DATA "/settings/gouraud_spot.json");
  CHECK(s.shading == ShadingMode::Gouraud);
  REQUIRE(s.lights.size() == 1);
  CHECK(s.lights[0].kind == LightKind::Spot);
}

namespace {

// Writes `text` to a fresh file under the build's temporary folder.
std::string settingsFileWith(const std::string& name, const std::string& text) {
  const std::string path = std::string(std::filesystem::temp_directory_path() / ("facet_settings_" + name));
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::string nested(std::size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

}  // namespace

TEST_CASE("settings text is read strictly: UTF-8, no NUL, no key twice, numbers that fit a double") {
  const auto load = [](const std::string& name, const std::string& text) { return loadSettingsFile(settingsFileWith(name, text)); };
  CHECK_THROWS_WITH_AS(load("utf16.json", std::string("\xff\xfe{\0}\0", 6)),
                       doctest::Contains("utf16.json: not UTF-8 text (byte 0xff at offset 0; this looks like UTF-16)"), Error);
  CHECK_THROWS_WITH_AS(load("latin1.json", "{\"shading\": \"caf\xe9\"}"), doctest::Contains("not UTF-8 text (byte 0xe9 at offset 16)"), Error);
  CHECK_THROWS_WITH_AS(load("nul.json", std::string("{\"ambient\": 0.2}\0{\"ambient\": 0.9}", 33)),
                       doctest::Contains("nul.json: a NUL byte at offset 16"), Error);
  CHECK_THROWS_WITH_AS(load("twice.json", R"({"ambient": 0.2, "ambient": 0.3})"), doctest::Contains("twice.json: the key 'ambient' appears twice"), Error);
  CHECK_THROWS_WITH_AS(load("twice_nested.json", R"({"lights": [{"kind": "point"}, {"kind": "spot", "kind": "point"}]})"),
                       doctest::Contains("the key 'lights.1.kind' appears twice"), Error);
  CHECK_THROWS_WITH_AS(load("huge.json", R"({"ambient": 1e400})"), doctest::Contains("huge.json: the number '1e400' is too large for a double"), Error);
  // The same key in two different objects is not a duplicate.
  CHECK(load("two_lights.json", R"({"lightSource": "manual", "lights": [{"kind": "point"}, {"kind": "spot"}]})").lights.size() == 2);

  RenderSettings s;
  CHECK_THROWS_WITH_AS(applySetting(s, "ambient=1e400"), "settings key 'ambient': the number '1e400' is too large for a double", Error);
  CHECK_THROWS_WITH_AS(applySetting(s, "ambient=1.0000001"), "settings key 'ambient': 1.0000001 is out of range [0, 1]", Error);
  // A key without a range still holds a float: past its largest value it would be infinite.
  CHECK_THROWS_WITH_AS(applySetting(s, "camera.eye=[1e39,0,0]"), "settings key 'camera.eye': 1e+39 is too large for a float (largest 3.4028234663852886e+38)", Error);
  CHECK_THROWS_WITH_AS(load("far_light.json", R"({"lights": [{"position": [0, -4e38, 0]}]})"), doctest::Contains("far_light.json: settings key 'lights.0.position': -4e+38 is too large for a float"), Error);
  applySetting(s, "camera.eye=[3.4028234663852886e38,0,0]");
  CHECK(s.camera.eye.x == std::numeric_limits<float>::max());
  CHECK(settingsFromJson(settingsToJson(s)).camera.eye.x == std::numeric_limits<float>::max());
}

TEST_CASE("settings nested without bound are refused before anything walks them") {
  // nlohmann::json copies and dumps recursively: 60,000 levels overflowed the
  // stack in --set (a copy) and in the error message of a file (a dump).
  RenderSettings s;
  CHECK_THROWS_WITH_AS(applySetting(s, "camera.eye=" + nested(60000)), doctest::Contains("settings key 'camera.eye': nested deeper than 8 levels"), Error);
  CHECK_THROWS_WITH_AS(loadSettingsFile(settingsFileWith("deep.json", nested(100000))), doctest::Contains("deep.json: nested deeper than 8 levels"), Error);
  CHECK_THROWS_WITH_AS(loadSettingsFile(settingsFileWith("deep_key.json", "{\"camera\": " + nested(100000) + "}")),
                       doctest::Contains("nested deeper than 8 levels at 'camera.0.0"), Error);
  // The deepest real settings still read (lights -> a light -> its position).
  CHECK_NOTHROW(applySetting(s, "lights=[{\"kind\": \"point\", \"position\": [1, 2, 3]}]"));
}

TEST_CASE("error lines quote at most a short prefix of a value or key, with control bytes escaped") {
  RenderSettings s;
  const std::string huge(15u << 20, 'x');
  try {
    applySetting(s, "ambient=" + huge);
    FAIL("a 15 MB string was taken as the ambient intensity");
  } catch (const Error& e) {
    const std::string line = e.what();
    CHECK(line.size() < 200);
    CHECK(line == "settings key 'ambient': expected a number, got '" + std::string(48, 'x') + "...' (15728640 bytes)");
  }
  CHECK_THROWS_WITH_AS(applySetting(s, std::string("amb\0ient=1", 10)), "settings key 'amb\\x00ient': unknown key", Error);
  CHECK_THROWS_WITH_AS(applySetting(s, "shading=" + std::string("\x1b[2J", 4)), doctest::Contains("got '\\x1b[2J'"), Error);
  CHECK_THROWS_WITH_AS(applySetting(s, "background=[0, 0]"), "settings key 'background': expected [x, y, z], got an array of 2 elements", Error);
  CHECK_THROWS_WITH_AS(applySetting(s, huge), doctest::Contains("...' (15728640 bytes): expected key=value"), Error);
}
