#include "settings/settings_json.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <set>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "common/atomic_file.h"
#include "common/error.h"
#include "common/json_text.h"
#include "common/quote.h"
#include "settings/settings_fields.h"
#include "vocabulary/limits.h"

namespace facet {
namespace {

using nlohmann::json;

std::string join(const std::string& prefix, std::string_view key) {
  return prefix.empty() ? std::string(key) : prefix + "." + std::string(key);
}

// How every message names a key: "settings key 'lights.0.intensity'".
std::string settingsKey(const std::string& dotted) { return "settings key " + quoteInput(dotted); }


// The shortest decimal that reads back as the same float, as a double: 0.15f
// is written 0.15, not 0.15000000596046448.
double shortest(float v) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, v);
  return std::strtod(std::string(text, result.ptr).c_str(), nullptr);
}

struct JsonWriter {
  json* out;

  void field(const FieldInfo& f, float v) { (*out)[std::string(f.key)] = shortest(v); }
  void field(const FieldInfo& f, int v) { (*out)[std::string(f.key)] = v; }
  void field(const FieldInfo& f, bool v) { (*out)[std::string(f.key)] = v; }
  void field(const FieldInfo& f, glm::vec3 v) { (*out)[std::string(f.key)] = {shortest(v.x), shortest(v.y), shortest(v.z)}; }
  void field(const FieldInfo& f, const std::optional<float>& v) { (*out)[std::string(f.key)] = v ? json(shortest(*v)) : json(nullptr); }
  void field(const FieldInfo& f, const std::string& v) { (*out)[std::string(f.key)] = v; }
  template <class E, std::size_t N>
  void choice(const FieldInfo& f, E v, const std::array<std::string_view, N>& names) {
    (*out)[std::string(f.key)] = std::string(names[static_cast<std::size_t>(v)]);
  }
  template <class Fn>
  void group(std::string_view key, Fn fn) {
    json* parent = out;
    json child = json::object();
    out = &child;
    fn();
    out = parent;
    (*out)[std::string(key)] = std::move(child);
  }
  template <class T>
  void list(const ListInfo& info, std::vector<T>& list) {
    json array = json::array();
    for (T& element : list) {
      json item = json::object();
      JsonWriter w{&item};
      visitItem(w, element);
      array.push_back(std::move(item));
    }
    (*out)[std::string(info.key)] = std::move(array);
  }
};

// Reads the keys a JSON object has into the fields; every key must be known.
struct JsonReader {
  const json* in;
  std::string prefix;           // dotted path of the current object
  std::set<std::string> seen;   // keys of the current object that a field took

  const json* find(const FieldInfo& f) {
    seen.insert(std::string(f.key));
    const auto it = in->find(std::string(f.key));
    return it == in->end() ? nullptr : &*it;
  }
  [[noreturn]] void fail(const FieldInfo& f, const std::string& why) const { throw Error(settingsKey(join(prefix, f.key)) + ": " + why); }

  double number(const FieldInfo& f, const json& j) const {
    if (!j.is_number()) fail(f, "expected a number, got " + describeJson(j));
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail(f, "must be finite");
    if (f.min != f.max && (v < f.min || v > f.max))
      fail(f, exactNumber(v) + " is out of range [" + exactNumber(f.min) + ", " + exactNumber(f.max) + "]");
    return v;
  }
  // Every setting is kept as a float: a double beyond its range would turn
  // into infinity there and could not be written back.
  float floatNumber(const FieldInfo& f, const json& j) const {
    const double v = number(f, j);
    const float narrowed = static_cast<float>(v);
    if (!std::isfinite(narrowed)) fail(f, exactNumber(v) + " is too large for a float (largest " + exactNumber(std::numeric_limits<float>::max()) + ")");
    return narrowed;
  }

  void field(const FieldInfo& f, float& v) {
    if (const json* j = find(f)) v = floatNumber(f, *j);
  }
  void field(const FieldInfo& f, int& v) {
    if (const json* j = find(f)) {
      if (!j->is_number_integer()) fail(f, "expected an integer, got " + describeJson(*j));
      v = static_cast<int>(number(f, *j));
    }
  }
  void field(const FieldInfo& f, bool& v) {
    if (const json* j = find(f)) {
      if (!j->is_boolean()) fail(f, "expected true or false, got " + describeJson(*j));
      v = j->get<bool>();
    }
  }
  void field(const FieldInfo& f, glm::vec3& v) {
    if (const json* j = find(f)) {
      if (!j->is_array() || j->size() != 3) fail(f, "expected [x, y, z], got " + describeJson(*j));
      for (int i = 0; i < 3; ++i) v[i] = floatNumber(f, (*j)[static_cast<std::size_t>(i)]);
    }
  }
  void field(const FieldInfo& f, std::optional<float>& v) {
    if (const json* j = find(f)) {
      if (j->is_null()) v.reset();
      else v = floatNumber(f, *j);
    }
  }
  void field(const FieldInfo& f, std::string& v) {
    if (const json* j = find(f)) {
      const std::string what = f.kind == FieldKind::Text ? "a text" : "a file name";
      if (!j->is_string()) fail(f, "expected " + what + " (a string), got " + describeJson(*j));
      const std::string text = j->get<std::string>();
      if (text.size() > kMaxSettingsPathBytes) fail(f, what + " of " + std::to_string(text.size()) + " bytes is longer than " + std::to_string(kMaxSettingsPathBytes));
      if (text.find('\0') != std::string::npos) fail(f, what + " cannot hold a NUL byte");
      v = text;
    }
  }
  template <class E, std::size_t N>
  void choice(const FieldInfo& f, E& v, const std::array<std::string_view, N>& names) {
    const json* j = find(f);
    if (!j) return;
    std::string allowed;
    for (std::size_t i = 0; i < N; ++i) {
      if (j->is_string() && j->get<std::string>() == names[i]) {
        v = static_cast<E>(i);
        return;
      }
      allowed += (i ? ", " : "") + std::string(names[i]);
    }
    fail(f, "expected one of " + allowed + ", got " + describeJson(*j));
  }
  template <class Fn>
  void group(std::string_view key, Fn fn) {
    const json* j = find({key, ""});
    if (!j) return;
    if (!j->is_object()) fail({key, ""}, "expected an object, got " + describeJson(*j));
    JsonReader nested{j, join(prefix, key), {}};
    std::swap(*this, nested);
    fn();
    checkNoUnknownKeys();
    std::swap(*this, nested);
  }
  template <class T>
  void list(const ListInfo& info, std::vector<T>& list) {
    const FieldInfo f{info.key, ""};
    const json* j = find(f);
    if (!j) return;
    if (!j->is_array()) fail(f, "expected an array of " + std::string(info.item) + "s, got " + describeJson(*j));
    if (j->size() > info.max)
      fail(f, std::to_string(j->size()) + " " + std::string(info.item) + "s, a frame takes at most " + std::to_string(info.max));
    list.assign(j->size(), T{});
    for (std::size_t i = 0; i < j->size(); ++i) {
      const std::string path = join(prefix, info.key) + "." + std::to_string(i);
      if (!(*j)[i].is_object()) throw Error(settingsKey(path) + ": expected an object, got " + describeJson((*j)[i]));
      JsonReader item{&(*j)[i], path, {}};
      visitItem(item, list[i]);
      item.checkNoUnknownKeys();
    }
  }
  void checkNoUnknownKeys() const {
    for (const auto& [key, value] : in->items())
      if (!seen.count(key)) throw Error(settingsKey(join(prefix, key)) + ": unknown key");
  }
};

// Rules that span fields, checked after every read.
void validate(const RenderSettings& s) {
  if (!(s.camera.far > s.camera.near)) throw Error("settings key 'camera.far': must be greater than camera.near");
  if (s.fog.mode == FogMode::Linear && !(s.fog.end > s.fog.start)) throw Error("settings key 'fog.end': must be greater than fog.start");
  const int side = samplesPerSide(s.antialiasing.samples);
  if (side * side != s.antialiasing.samples)
    throw Error("settings key 'antialiasing.samples': " + std::to_string(s.antialiasing.samples) + " is not one of 1, 4, 9, 16 (s x s samples)");
  for (std::size_t i = 0; i < s.lights.size(); ++i) {
    const Light& l = s.lights[i];
    const std::string key = "settings key 'lights." + std::to_string(i);
    if (l.kind != LightKind::Point && !(glm::length(l.direction) > 0.0f)) throw Error(key + ".direction': must not be zero");
    if (l.kind != LightKind::Directional && !(l.attenuation.x + l.attenuation.y + l.attenuation.z > 0.0f))
      throw Error(key + ".attenuation': c1 + c2 + c3 must be positive");
  }
  for (std::size_t i = 0; i < s.particles.size(); ++i)
    if (!(glm::length(s.particles[i].direction) > 0.0f))
      throw Error("settings key 'particles." + std::to_string(i) + ".direction': must not be zero");
}

// The JSON of a default element of the list at dotted key `listKey` ("lights", "particles.emitters").
struct DefaultItemWriter {
  std::string target, prefix;
  json found;

  template <class T>
  void field(const FieldInfo&, const T&) {}
  template <class E, std::size_t N>
  void choice(const FieldInfo&, E, const std::array<std::string_view, N>&) {}
  template <class Fn>
  void group(std::string_view key, Fn fn) {
    const std::string parent = prefix;
    prefix = join(prefix, key);
    fn();
    prefix = parent;
  }
  template <class T>
  void list(const ListInfo& info, std::vector<T>&) {
    if (join(prefix, info.key) != target) return;
    T element;
    found = json::object();
    JsonWriter writer{&found};
    visitItem(writer, element);
  }
};
json defaultItem(const std::string& listKey) {
  RenderSettings defaults;
  DefaultItemWriter writer{listKey, "", json::object()};
  visitSettings(writer, defaults);
  return writer.found;
}

}  // namespace

json settingsToJson(const RenderSettings& settings) {
  json out = json::object();
  RenderSettings copy = settings;
  JsonWriter writer{&out};
  visitSettings(writer, copy);
  return out;
}

RenderSettings settingsFromJson(const json& j) {
  if (!j.is_object()) throw Error("settings: expected a JSON object, got " + describeJson(j));
  RenderSettings settings;
  JsonReader reader{&j, "", {}};
  visitSettings(reader, settings);
  reader.checkNoUnknownKeys();
  validate(settings);
  return settings;
}

Emitter emitterFromJson(const json& j, const std::string& where) {
  if (!j.is_object()) throw Error(settingsKey(where) + ": expected an object, got " + describeJson(j));
  Emitter emitter;
  JsonReader reader{&j, where, {}};
  visitItem(reader, emitter);
  reader.checkNoUnknownKeys();
  if (!(glm::length(emitter.direction) > 0.0f)) throw Error(settingsKey(where + ".direction") + ": must not be zero");
  return emitter;
}

RenderSettings loadSettingsFile(const std::string& path) {
  const std::string text = readFile(path, kMaxSettingsFileBytes);
  try {
    return settingsFromJson(parseStrictJson(text, kMaxSettingsDepth));
  } catch (const Error& e) {
    throw Error(path + ": " + e.what());
  }
}

void applySetting(RenderSettings& settings, const std::string& assignment) {
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0)
    throw Error("--set " + quoteInput(assignment) + ": expected key=value, e.g. shading=gouraud or lights.0.position=[1,4,2]");
  const std::string key = assignment.substr(0, equals);
  const std::string text = assignment.substr(equals + 1);
  json value;
  try {
    value = parseStrictJson(text, kMaxSettingsDepth);
  } catch (const JsonSyntaxError&) {
    value = text;  // a bare word such as gouraud
  } catch (const Error& e) {
    throw Error(settingsKey(key) + ": " + e.what());
  }

  json root = settingsToJson(settings);
  json* node = &root;
  std::string walked;
  for (std::size_t start = 0;;) {
    const auto dot = key.find('.', start);
    const std::string part = key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    walked = walked.empty() ? part : walked + "." + part;
    if (node->is_array()) {
      std::size_t index = 0;
      try {
        std::size_t used = 0;
        index = std::stoul(part, &used);
        if (used != part.size()) throw std::invalid_argument(part);
      } catch (const std::exception&) {
        throw Error(settingsKey(walked) + ": expected an index into the list");
      }
      if (index == node->size()) node->push_back(defaultItem(walked.substr(0, walked.rfind('.'))));  // one past the end appends a default element
      if (index >= node->size()) throw Error(settingsKey(walked) + ": index past the end of the list (" + std::to_string(node->size()) + " elements)");
      node = &(*node)[index];
    } else if (node->is_object()) {
      if (!node->contains(part)) throw Error(settingsKey(walked) + ": unknown key");
      node = &(*node)[part];
    } else {
      throw Error(settingsKey(walked) + ": unknown key");
    }
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  *node = value;
  settings = settingsFromJson(root);
}

}  // namespace facet
