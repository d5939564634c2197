// RenderSettings <-> JSON: round trip, strictness, --set.
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
