#include "settings/settings_files.h"

#include <optional>

#include "settings/settings_fields.h"

namespace facet {
namespace {

// Walks the field table; the string fields not marked Text are file names.
struct FileCollector {
  std::vector<std::string>* files;

  template <class T>
  void field(const FieldInfo&, const T&) {}
  void field(const FieldInfo& info, const std::string& value) {
    if (info.kind != FieldKind::Text && !value.empty()) files->push_back(value);
  }
  template <class E, std::size_t N>
  void choice(const FieldInfo&, E, const std::array<std::string_view, N>&) {}
  template <class Fn>
  void group(const GroupInfo&, Fn fn) {
    fn();
  }
  template <class T>
  void list(const ListInfo&, std::vector<T>& items) {
    for (T& item : items) visitItem(*this, item);
  }
};

}  // namespace

std::vector<std::string> namedFiles(const RenderSettings& settings) {
  std::vector<std::string> files;
  FileCollector collector{&files};
  RenderSettings copy = settings;  // the visitors take the fields as they would edit them
  visitSettings(collector, copy);
  return files;
}

}  // namespace facet
