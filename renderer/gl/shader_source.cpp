#include "gl/shader_source.h"

#include <algorithm>
#include <regex>

#include "common/error.h"
#include "gl/embedded_shaders.h"

namespace facet::gl {
namespace {

// The file name of an `#include "name"` line, or nullopt for any other line.
std::optional<std::string> includedFile(std::string_view line, std::string_view file, int lineNumber) {
  const std::size_t start = line.find_first_not_of(" \t");
  if (start == std::string_view::npos || line.substr(start, 8) != "#include") return std::nullopt;
  const std::size_t open = line.find('"', start + 8), close = open == std::string_view::npos ? open : line.find('"', open + 1);
  if (close == std::string_view::npos)
    throw Error("shader " + std::string(file) + ":" + std::to_string(lineNumber) + ": expected #include \"file\"");
  return std::string(line.substr(open + 1, close - open - 1));
}

void expand(std::string_view file, int sourceNumber, const ShaderFileLookup& find, ShaderSource& out) {
  const std::optional<std::string_view> text = find(file);
  if (!text) throw Error("shader " + std::string(file) + ": no such file in shaders/");
  int lineNumber = 0;
  for (std::size_t begin = 0; begin < text->size();) {
    const std::size_t end = std::min(text->find('\n', begin), text->size());
    const std::string_view line = text->substr(begin, end - begin);
    begin = end + 1;
    ++lineNumber;
    const std::optional<std::string> include = includedFile(line, file, lineNumber);
    if (!include) {
      out.text.append(line).append("\n");
      continue;
    }
    bool seen = false;
    for (const std::string& f : out.files) seen = seen || f == *include;
    if (seen) {
      out.text.append("\n");  // already in this stage: an empty line keeps the numbering
      continue;
    }
    const int included = static_cast<int>(out.files.size());
    out.files.push_back(*include);
    out.text.append("#line 1 " + std::to_string(included) + "\n");
    expand(*include, included, find, out);
    out.text.append("#line " + std::to_string(lineNumber + 1) + " " + std::to_string(sourceNumber) + "\n");
  }
}

}  // namespace

std::optional<std::string_view> findEmbeddedShaderFile(std::string_view name) {
  for (const ShaderFile& file : embeddedShaderFiles())
    if (file.name == name) return file.text;
  return std::nullopt;
}

ShaderSource assembleShaderSource(std::string_view stageFile, const ShaderFileLookup& find) {
  ShaderSource source;
  source.files.emplace_back(stageFile);
  expand(stageFile, 0, find, source);
  return source;
}

std::string describeLog(std::string_view log, const std::vector<std::string>& files) {
  static const std::regex prefix(R"(^(\d+):(\d+)\((\d+)\))");  // Mesa: "0:12(5): error: ..."
  std::string out;
  for (std::size_t begin = 0; begin < log.size();) {
    const std::size_t end = std::min(log.find('\n', begin), log.size());
    std::string line(log.substr(begin, end - begin));
    begin = end + 1;
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\0')) line.pop_back();
    if (line.empty()) continue;
    std::smatch m;
    if (std::regex_search(line, m, prefix)) {
      const std::size_t number = std::stoul(m[1].str());
      if (number < files.size()) line = files[number] + ":" + m[2].str() + "(" + m[3].str() + ")" + m.suffix().str();
    }
    if (!out.empty()) out += "; ";
    out += line;
  }
  return out.empty() ? "(the driver gave no log)" : out;
}

}  // namespace facet::gl
