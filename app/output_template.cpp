#include "output_template.h"

#include <algorithm>
#include <filesystem>

#include "common/atomic_file.h"
#include "common/error.h"
#include "common/quote.h"

namespace facet {

namespace {

constexpr const char* kKnown = "known: {scene}, {backend}, {frame}, {n}, {frame:W}; {{ and }} write braces";

int digitsOf(int n) {
  int digits = 1;
  for (; n >= 10; n /= 10) ++digits;
  return digits;
}

}  // namespace

OutputTemplate::OutputTemplate(const std::string& pattern, const std::string& option) {
  const auto refuse = [&](const std::string& fault) { throw UsageError(option + " " + quotedPath(pattern) + ": " + fault); };
  std::string text;
  const auto flushText = [&] {
    if (!text.empty()) pieces_.push_back({Kind::Text, text, 0});
    text.clear();
  };
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    const char c = pattern[i];
    if ((c == '{' || c == '}') && i + 1 < pattern.size() && pattern[i + 1] == c) {
      text += c;
      ++i;
      continue;
    }
    if (c == '}') refuse("a '}' without its '{' (write }} for a brace)");
    if (c != '{') {
      text += c;
      continue;
    }
    const std::size_t close = pattern.find('}', i + 1);
    if (close == std::string::npos) refuse("a '{' without its '}' (write {{ for a brace)");
    const std::string field = pattern.substr(i + 1, close - i - 1);
    const std::size_t colon = field.find(':');
    const std::string name = field.substr(0, colon);
    Piece piece;
    if (name == "scene") piece.kind = Kind::Scene;
    else if (name == "backend") piece.kind = Kind::Backend;
    else if (name == "frame" || name == "n") piece.kind = Kind::Frame;
    else refuse("unknown placeholder " + quoteInput("{" + field + "}") + " (" + kKnown + ")");
    if (colon != std::string::npos) {
      const std::string width = field.substr(colon + 1);
      if (piece.kind != Kind::Frame) refuse(quoteInput("{" + field + "}") + ": only {frame} and {n} take a width");
      if (width.size() != 1 || width[0] < '1' || width[0] > '9') refuse(quoteInput("{" + field + "}") + ": the width must be a digit from 1 to 9");
      piece.width = width[0] - '0';
    }
    flushText();
    pieces_.push_back(piece);
    i = close;
  }
  flushText();
}

bool OutputTemplate::numbersFrames() const {
  return std::any_of(pieces_.begin(), pieces_.end(), [](const Piece& p) { return p.kind == Kind::Frame; });
}

std::string OutputTemplate::expand(const TemplateValues& values, int frame, int frames) const {
  std::string name;
  for (const Piece& p : pieces_) {
    switch (p.kind) {
      case Kind::Text: name += p.text; break;
      case Kind::Scene: name += values.scene; break;
      case Kind::Backend: name += values.backend; break;
      case Kind::Frame: {
        const std::string number = std::to_string(frame);
        const int width = p.width > 0 ? p.width : digitsOf(std::max(frames - 1, 0));
        name += std::string(static_cast<std::size_t>(std::max(width - static_cast<int>(number.size()), 0)), '0') + number;
        break;
      }
    }
  }
  return name;
}

std::string sceneNameOf(const std::string& scenePath) {
  constexpr std::string_view kBuiltin = "builtin:";
  if (scenePath.empty()) return "default";
  if (scenePath.rfind(kBuiltin, 0) == 0) return scenePath.substr(kBuiltin.size());
  std::filesystem::path file = std::filesystem::path(scenePath).filename();
  if (file.extension() == ".gz") file = file.stem();  // a.nii.gz: the volume's own extension is .nii
  const std::string stem = file.stem().string();
  return stem.empty() ? "scene" : stem;
}

}  // namespace facet
