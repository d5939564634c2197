// The emitter's limits have one source, the settings' field table
// (settings/settings_fields.h): for every number of particles.N.* that it
// bounds, the settings reader and the particle system accept the bounds and
// both refuse the float just outside, naming the key.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include "common/error.h"
#include "particles/particle_system.h"
#include "settings/settings_fields.h"
#include "settings/settings_json.h"

using namespace facet;
using nlohmann::json;

namespace {

// A number of the emitter that the table bounds: its key, range and shape.
struct Bounded {
  std::string key;
  double min, max;
  enum Shape { Float, Int, Vec3 } shape;
};

struct CollectBounded {
  std::vector<Bounded> found;
  void add(const FieldInfo& f, Bounded::Shape shape) {
    if (f.min != f.max) found.push_back({std::string(f.key), f.min, f.max, shape});
  }
  void field(const FieldInfo& f, float&) { add(f, Bounded::Float); }
  void field(const FieldInfo& f, int&) { add(f, Bounded::Int); }
  void field(const FieldInfo& f, glm::vec3&) { add(f, Bounded::Vec3); }
  template <class T>
  void field(const FieldInfo&, T&) {}
  template <class E, std::size_t N>
  void choice(const FieldInfo&, E&, const std::array<std::string_view, N>&) {}
};

// Sets the number at `key` as a float would hold `value` (component `c` of a vector, or all three).
struct SetNumber {
  std::string key;
  double value;
  int c = -1;
  void field(const FieldInfo& f, float& v) {
    if (f.key == key) v = static_cast<float>(value);
  }
  void field(const FieldInfo& f, int& v) {
    if (f.key == key) v = static_cast<int>(value);
  }
  void field(const FieldInfo& f, glm::vec3& v) {
    if (f.key != key) return;
    if (c < 0) v = glm::vec3(static_cast<float>(value));
    else v[c] = static_cast<float>(value);
  }
  template <class T>
  void field(const FieldInfo&, T&) {}
  template <class E, std::size_t N>
  void choice(const FieldInfo&, E&, const std::array<std::string_view, N>&) {}
};

// An emitter whose other values let any one bound pass the checks that span
// fields: no drag (so any mass is stable) and a mass that keeps the largest
// drag stable.
json baseEmitter() { return json{{"mass", 1e9}, {"drag", 0}}; }

const std::string kKey = "particles.3";

// What simulateParticles says of `e` at time 0 with its own step ("" when it accepts it).
std::string particleRefusal(const Emitter& e) {
  try {
    simulateParticles(e, 0.0f, e.step, kKey.c_str(), 1);
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

// What the settings reader says of the emitter's JSON ("" when it accepts it).
std::string settingsRefusal(const json& j) {
  try {
    emitterFromJson(j, kKey);
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

// The float just past `bound` away from the range: below the least, above the greatest.
double justOutside(const Bounded& b, double bound) {
  const bool below = bound == b.min;
  if (b.shape == Bounded::Int) return below ? bound - 1.0 : bound + 1.0;
  const float f = static_cast<float>(bound);
  return std::nextafter(f, below ? -std::numeric_limits<float>::infinity() : std::numeric_limits<float>::infinity());
}

json jsonNumber(const Bounded& b, double value) {
  if (b.shape == Bounded::Int) return static_cast<int>(value);
  if (b.shape == Bounded::Vec3) return json{value, value, value};
  return value;
}

}  // namespace

TEST_CASE("emitter limits: the settings' field table is the particle system's, each bound accepted, just past it refused") {
  Emitter walked;
  CollectBounded collect;
  visitItem(collect, walked);
  const std::vector<Bounded>& bounded = collect.found;
  REQUIRE(bounded.size() >= 19);  // rate, startTime, ... step: every number but the positions and directions

  for (const Bounded& b : bounded) {
    for (const double bound : {b.min, b.max}) {
      CAPTURE(b.key);
      CAPTURE(bound);
      // The bound as the settings read it (a float's worth of it) is accepted by both.
      json j = baseEmitter();
      j[b.key] = jsonNumber(b, bound);
      CHECK(settingsRefusal(j) == "");
      const Emitter read = emitterFromJson(j, kKey);
      CHECK(particleRefusal(read) == "");

      // Just outside it, in one component at a time: both refuse, naming the key.
      const double outside = justOutside(b, bound);
      CAPTURE(outside);
      for (int c = 0; c < (b.shape == Bounded::Vec3 ? 3 : 1); ++c) {
        Emitter e = emitterFromJson(baseEmitter(), kKey);
        SetNumber inside{b.key, bound}, past{b.key, outside, b.shape == Bounded::Vec3 ? c : -1};
        visitItem(inside, e);
        visitItem(past, e);
        const std::string message = particleRefusal(e);
        CHECK(message.rfind(kKey + "." + b.key + ": ", 0) == 0);
        CHECK(message.find("is outside") != std::string::npos);

        json k = baseEmitter();
        k[b.key] = jsonNumber(b, bound);
        if (b.shape == Bounded::Vec3) k[b.key][static_cast<std::size_t>(c)] = outside;
        else k[b.key] = jsonNumber(b, outside);
        CHECK(settingsRefusal(k).find("'" + kKey + "." + b.key + "'") != std::string::npos);
      }
    }
  }
}
