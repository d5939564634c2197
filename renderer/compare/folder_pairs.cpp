#include "compare/folder_pairs.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <system_error>

#include "common/error.h"

namespace facet {
namespace {

namespace fs = std::filesystem;

bool hasPngExtension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".png";
}

// name -> path of the PNG files directly in `folder`.
std::map<std::string, std::string> pngFiles(const std::string& folder) {
  std::map<std::string, std::string> files;
  std::error_code ec;
  fs::directory_iterator it(folder, ec);
  if (ec) throw Error(folder + ": cannot read the folder (" + ec.message() + ")");
  for (; it != fs::directory_iterator(); it.increment(ec)) {
    if (ec) throw Error(folder + ": cannot read the folder (" + ec.message() + ")");
    const fs::path& path = it->path();
    // Symbolic links count as what they point to; a dangling one is kept so
    // that reading it reports the problem.
    std::error_code typeError;
    if (it->is_directory(typeError) || !hasPngExtension(path)) continue;
    files.emplace(path.filename().string(), path.string());
  }
  if (ec) throw Error(folder + ": cannot read the folder (" + ec.message() + ")");
  return files;
}

}  // namespace

std::vector<FilePair> pairFolderFiles(const std::string& expectedFolder, const std::string& actualFolder) {
  const std::map<std::string, std::string> expected = pngFiles(expectedFolder);
  const std::map<std::string, std::string> actual = pngFiles(actualFolder);
  std::map<std::string, FilePair> pairs;
  for (const auto& [name, path] : expected) pairs[name] = {name, path, {}};
  for (const auto& [name, path] : actual) {
    FilePair& pair = pairs[name];
    pair.name = name;
    pair.actualPath = path;
  }
  std::vector<FilePair> out;
  out.reserve(pairs.size());
  for (auto& [name, pair] : pairs) out.push_back(std::move(pair));
  return out;
}

}  // namespace facet
