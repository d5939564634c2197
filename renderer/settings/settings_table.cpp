#include "settings/settings_table.h"

#include <charconv>
#include <cmath>

#include "settings/settings_fields.h"

namespace facet {
namespace {

std::string number(double v) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, static_cast<float>(v)).ptr;
  return std::string(text, end);
}

// Appended piece by piece: GCC 12's -Wrestrict misreads the inlined chain of operator+ here.
std::string vec3(glm::vec3 v) {
  std::string text = "[";
  for (int k = 0; k < 3; ++k) text.append(k ? ", " : "").append(number(v[k]));
  return text.append("]");
}

struct TableWriter {
  std::string prefix;
  std::string* out;

  void row(const FieldInfo& f, const std::string& value, const std::string& range) {
    *out += "| `" + prefix + std::string(f.key) + "` | `" + value + "` | " + range + " | " + std::string(f.help) + " |\n";
  }
  std::string range(const FieldInfo& f) const { return f.min == f.max ? "" : number(f.min) + " to " + number(f.max); }
  // The range followed by the unit: "0.5 to 89.5 degrees"; the unit alone for an unbounded value.
  std::string measured(const FieldInfo& f, const std::string& range) const {
    if (f.unit.empty()) return range;
    return range.empty() ? std::string(f.unit) : range + " " + std::string(f.unit);
  }

  void field(const FieldInfo& f, float v) { row(f, number(v), measured(f, range(f))); }
  void field(const FieldInfo& f, int v) { row(f, std::to_string(v), measured(f, range(f))); }
  void field(const FieldInfo& f, bool v) { row(f, v ? "true" : "false", "true, false"); }
  void field(const FieldInfo& f, glm::vec3 v) { row(f, vec3(v), measured(f, f.min == f.max ? "" : "each " + range(f))); }
  void field(const FieldInfo& f, const std::optional<float>& v) { row(f, v ? number(*v) : "null", "null, or " + measured(f, range(f))); }
  void field(const FieldInfo& f, const std::string& v) { row(f, v.empty() ? "\"\"" : v, f.kind == FieldKind::Text ? "text" : "a file name"); }
  template <class E, std::size_t N>
  void choice(const FieldInfo& f, E v, const std::array<std::string_view, N>& names) {
    std::string choices;
    for (std::string_view name : names) choices += (choices.empty() ? "" : ", ") + std::string(name);
    row(f, std::string(names[static_cast<std::size_t>(v)]), choices);
  }
  template <class Fn>
  void group(std::string_view key, Fn fn) {
    const std::string parent = prefix;
    prefix += std::string(key) + ".";
    fn();
    prefix = parent;
  }
  template <class T>
  void list(const ListInfo& info, std::vector<T>&) {
    *out += "| `" + prefix + std::string(info.key) + "` | `[]` | up to " + std::to_string(info.max) + " | " + std::string(info.help) +
            ", each with the keys below |\n";
    T element;
    TableWriter item{prefix + std::string(info.key) + ".N.", out};
    visitItem(item, element);
  }
};

}  // namespace

std::string settingsTable() {
  std::string out = "| key | default | range and unit | meaning |\n| --- | --- | --- | --- |\n";
  RenderSettings defaults;
  TableWriter writer{"", &out};
  visitSettings(writer, defaults);
  return out;
}

}  // namespace facet
