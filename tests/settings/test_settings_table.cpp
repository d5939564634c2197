// The settings table of docs/settings.md is the field table's: `facet
// settings --keys` prints it, and this holds the document's copy (between
// its two markers) to
// that output, so a key added, renamed or given a new default cannot leave
// the documentation behind. And every field of the table has a label and,
// when it measures something, a unit.
#include <algorithm>
#include <cctype>
#include <optional>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <doctest/doctest.h>

#include "scratch_folder.h"
#include "settings/settings_fields.h"
#include "settings/settings_table.h"

using namespace facet;

TEST_CASE("the settings table of docs/settings.md is settingsTable(), key for key") {
  const std::string readme = test::readAll(FACET_SETTINGS_DOC);
  const std::string begin = "<!-- settings table: facet settings --keys -->\n", end = "<!-- end of settings table -->";
  const std::size_t from = readme.find(begin), to = readme.find(end);
  REQUIRE(from != std::string::npos);
  REQUIRE(to != std::string::npos);
  const std::string table = settingsTable();
  CHECK(table.find("| `textures.filter` | `auto` | auto, nearest, bilinear, trilinear |") != std::string::npos);
  CHECK(table.find("| `lights.N.kind` | `point` |") != std::string::npos);
  CHECK(readme.substr(from + begin.size(), to - from - begin.size()) == table);
}

namespace {

// Every field of the table with its dotted key and whether it holds a real number.
struct LabelledField {
  std::string key;
  FieldInfo info;
  bool real;  // float, std::optional<float> or a vec3 that is not a colour: a measure that may need a unit
};

struct FieldLister {
  std::string prefix;
  std::vector<LabelledField>* fields;
  std::vector<std::pair<std::string, std::string_view>>* headers;  // groups' and lists' dotted keys and labels

  template <class T>
  void field(const FieldInfo& f, const T&) {
    constexpr bool real = std::is_same_v<T, float> || std::is_same_v<T, std::optional<float>> || std::is_same_v<T, glm::vec3>;
    fields->push_back({prefix + std::string(f.key), f, real && f.kind != FieldKind::Color});
  }
  template <class E, std::size_t N>
  void choice(const FieldInfo& f, const E&, const std::array<std::string_view, N>&) {
    fields->push_back({prefix + std::string(f.key), f, false});
  }
  template <class Fn>
  void group(const GroupInfo& g, Fn fn) {
    headers->emplace_back(prefix + std::string(g.key), g.label);
    const std::string parent = prefix;
    prefix += std::string(g.key) + ".";
    fn();
    prefix = parent;
  }
  template <class T>
  void list(const ListInfo& l, std::vector<T>&) {
    headers->emplace_back(prefix + std::string(l.key), l.label);
    T item;
    FieldLister items{prefix + std::string(l.key) + ".N.", fields, headers};
    visitItem(items, item);
  }
};

// A raw key: camelCase, a lowercase letter directly followed by an uppercase one.
bool camelCase(std::string_view text) {
  for (std::size_t i = 1; i < text.size(); ++i)
    if (std::islower(static_cast<unsigned char>(text[i - 1])) && std::isupper(static_cast<unsigned char>(text[i]))) return true;
  return false;
}

// The pure numbers whose range reaches outside [0, 1] (settings_fields.h
// says why they have no unit). A new measure either has a unit or is added
// here on purpose.
const std::set<std::string> kPureNumbers = {
    "lights.N.intensity",    // a factor of the light's colour
    "lights.N.attenuation",  // c1, c2, c3: three factors of different dimensions
    "material.shininess",    // an exponent
    "material.ior",          // a ratio of speeds
};

}  // namespace

// The rule for units (see FieldInfo): a real-valued number (a float, an
// optional float, a vector that is not a colour) whose range reaches outside
// [0, 1] is a measure and has a unit, unless it is a listed pure number.
// Integers are counts and seeds or say their unit by choice (pixels,
// texels); booleans, choices, file names and colours have none.
TEST_CASE("every settings field has a human label, and every measure a unit") {
  std::vector<LabelledField> fields;
  std::vector<std::pair<std::string, std::string_view>> headers;
  RenderSettings settings;
  FieldLister lister{"", &fields, &headers};
  visitSettings(lister, settings);
  REQUIRE(fields.size() > 100);

  for (const LabelledField& f : fields) {
    INFO(f.key, " labelled \"", f.info.label, "\" in \"", f.info.unit, "\"");
    CHECK_FALSE(f.info.label.empty());
    CHECK(f.info.label != f.info.key);
    CHECK_FALSE(camelCase(f.info.label));
    CHECK_FALSE(camelCase(f.info.unit));
    const bool measure = f.real && f.info.min < f.info.max && (f.info.min < 0.0 || f.info.max > 1.0);
    if (measure && !kPureNumbers.count(f.key)) CHECK_FALSE(f.info.unit.empty());
    if (kPureNumbers.count(f.key)) CHECK(f.info.unit.empty());
  }
  for (const auto& header : headers) {
    const auto& key = header.first;  // named, not bound: INFO's lambda takes them
    const auto& label = header.second;
    INFO(key, " labelled \"", label, "\"");
    CHECK_FALSE(label.empty());
    CHECK_FALSE(camelCase(label));
  }
  for (const std::string& key : kPureNumbers)
    CHECK_MESSAGE(std::any_of(fields.begin(), fields.end(), [&](const LabelledField& f) { return f.key == key; }), key, " is not a field");
}
