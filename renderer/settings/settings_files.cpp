#include "settings/settings_files.h"

#include <optional>

#include "settings/settings_fields.h"

namespace facet {
namespace {

// Walks the field table; the string fields not marked Text are file names.
struct FileVisitor {
  const std::function<void(std::string&)>* visit;

  template <class T>
  void field(const FieldInfo&, T&) {}
  void field(const FieldInfo& info, std::string& value) {
    if (info.kind != FieldKind::Text && !value.empty()) (*visit)(value);
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

void forEachNamedFile(RenderSettings& settings, const std::function<void(std::string&)>& visit) {
  FileVisitor visitor{&visit};
  visitSettings(visitor, settings);
}

std::vector<std::string> namedFiles(const RenderSettings& settings) {
  std::vector<std::string> files;
  RenderSettings copy = settings;  // the visitor takes the fields as it would edit them
  forEachNamedFile(copy, [&](std::string& file) { files.push_back(file); });
  return files;
}

}  // namespace facet
