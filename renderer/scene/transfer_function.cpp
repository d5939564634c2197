// Transfer functions: the setting volume.transfer parsed (a preset or control points) and evaluated.
#include "scene/transfer_function.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "common/error.h"
#include "common/quote.h"

namespace facet {
namespace {

constexpr std::string_view kKey = "volume.transfer: ";
constexpr std::size_t kNumbersPerPoint = 5;  // value r g b a
constexpr std::size_t kMaxShownNumber = 24;  // longer numbers are shown as %g

// A preset's control point at a fraction t of the data range.
struct PresetPoint {
  float t;
  float r, g, b;
  float opacity;
};

struct Preset {
  std::string_view name;
  std::span<const PresetPoint> points;
};

// Grey: a linear ramp from black and transparent to white and nearly opaque.
constexpr PresetPoint kGrey[] = {{0.0f, 0.0f, 0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f, 1.0f, 0.8f}};
// MR heads: background and noise (the lowest tenth) transparent, soft tissue
// a faint warm haze, the brightest tissue whiter and more opaque.
constexpr PresetPoint kMri[] = {{0.0f, 0.0f, 0.0f, 0.0f, 0.0f},     {0.1f, 0.0f, 0.0f, 0.0f, 0.0f},  {0.25f, 0.75f, 0.45f, 0.35f, 0.02f},
                                {0.5f, 0.95f, 0.7f, 0.55f, 0.06f}, {0.75f, 1.0f, 0.9f, 0.8f, 0.3f}, {1.0f, 1.0f, 1.0f, 1.0f, 0.7f}};
// CT-like: air and soft tissue (below 40 %) transparent, bone ivory, denser bone more opaque.
constexpr PresetPoint kBone[] = {
    {0.0f, 0.0f, 0.0f, 0.0f, 0.0f}, {0.4f, 0.9f, 0.85f, 0.7f, 0.0f}, {0.55f, 0.95f, 0.9f, 0.78f, 0.4f}, {1.0f, 1.0f, 0.98f, 0.92f, 0.9f}};
// Hue from blue through cyan, green and yellow to red, opacity rising with the value.
constexpr PresetPoint kRainbow[] = {{0.0f, 0.0f, 0.0f, 1.0f, 0.0f},
                                    {0.25f, 0.0f, 1.0f, 1.0f, 0.1f},
                                    {0.5f, 0.0f, 1.0f, 0.0f, 0.2f},
                                    {0.75f, 1.0f, 1.0f, 0.0f, 0.4f},
                                    {1.0f, 1.0f, 0.0f, 0.0f, 0.7f}};
// A narrow opaque band at the middle of the range, elsewhere transparent: an
// iso-surface look (Marschner-Lobb's surface of interest is at 0.5 of [0, 1]).
constexpr PresetPoint kIsoSurface[] = {{0.0f, 1.0f, 0.9f, 0.7f, 0.0f},
                                       {0.45f, 1.0f, 0.9f, 0.7f, 0.0f},
                                       {0.5f, 1.0f, 0.9f, 0.7f, 0.9f},
                                       {0.55f, 1.0f, 0.9f, 0.7f, 0.0f},
                                       {1.0f, 1.0f, 0.9f, 0.7f, 0.0f}};

constexpr std::array<Preset, 5> kPresets = {{
    {"grey", kGrey},
    {"mri", kMri},
    {"bone", kBone},
    {"rainbow", kRainbow},
    {"iso-surface", kIsoSurface},
}};

std::string presetList() {
  std::string names;
  for (const Preset& p : kPresets) names += (names.empty() ? "" : ", ") + std::string(p.name);
  return names;
}

// A preset spread over [minValue, maxValue]; an empty or non-finite range
// becomes a unit one so that the points still increase.
TransferFunction presetFunction(const Preset& preset, float minValue, float maxValue) {
  double lo = minValue, hi = maxValue;
  if (!std::isfinite(lo) || !std::isfinite(hi)) lo = 0.0, hi = 1.0;
  if (!(hi > lo)) hi = lo + 1.0;
  TransferFunction f;
  for (const PresetPoint& p : preset.points) {
    TransferPoint point;
    point.value = static_cast<float>(lo + static_cast<double>(p.t) * (hi - lo));
    // Where floats cannot tell two preset values apart (a huge minValue and a tiny range), the next float keeps them increasing.
    if (!f.points.empty() && !(point.value > f.points.back().value))
      point.value = std::nextafter(f.points.back().value, std::numeric_limits<float>::infinity());
    point.color = {p.r, p.g, p.b};
    point.opacity = p.opacity;
    f.points.push_back(point);
  }
  return f;
}

bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && isSpace(text.front())) text.remove_prefix(1);
  while (!text.empty() && isSpace(text.back())) text.remove_suffix(1);
  return text;
}

// A name rather than numbers: a letter, then letters, digits, '-' or '_'.
bool looksLikeName(std::string_view text) {
  if (text.empty() || !std::isalpha(static_cast<unsigned char>(text.front()))) return false;
  return std::all_of(text.begin(), text.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_'; });
}

std::string pointName(std::size_t index) { return "point " + std::to_string(index + 1); }

// A number of the text as an error line shows it: as written unless very long.
std::string shownNumber(std::string_view token, float value) {
  if (token.size() <= kMaxShownNumber) return std::string(token);
  char text[32];
  std::snprintf(text, sizeof text, "%g", static_cast<double>(value));
  return text;
}

struct Token {
  std::string_view text;
  float value = 0.0f;
};

float parseNumber(std::string_view token, std::size_t index) {
  std::string_view digits = token;
  if (digits.size() > 1 && digits.front() == '+') digits.remove_prefix(1);  // from_chars takes no '+'
  float value = 0.0f;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec == std::errc::result_out_of_range && end == digits.data() + digits.size())
    throw Error(std::string(kKey) + pointName(index) + ": " + quoteInput(token) + " is not a finite number");
  if (ec != std::errc() || end != digits.data() + digits.size())
    throw Error(std::string(kKey) + pointName(index) + ": " + quoteInput(token) + " is not a number");
  if (!std::isfinite(value)) throw Error(std::string(kKey) + pointName(index) + ": " + quoteInput(token) + " is not a finite number");
  return value;
}

TransferPoint parsePoint(std::string_view text, std::size_t index) {
  std::vector<Token> tokens;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && isSpace(text[i])) ++i;
    const std::size_t start = i;
    while (i < text.size() && !isSpace(text[i])) ++i;
    if (i > start) {
      const std::string_view token = text.substr(start, i - start);
      tokens.push_back({token, parseNumber(token, index)});
    }
  }
  if (tokens.empty()) throw Error(std::string(kKey) + pointName(index) + " is empty (expected value r g b a)");
  if (tokens.size() != kNumbersPerPoint)
    throw Error(std::string(kKey) + pointName(index) + " has " + countOf(tokens.size(), "number") + ", expected 5 (value r g b a" +
                (tokens.size() > kNumbersPerPoint ? "; points are separated by commas)" : ")"));
  static constexpr std::string_view kChannels[] = {"red", "green", "blue", "opacity"};
  for (std::size_t c = 0; c < 4; ++c) {
    const Token& t = tokens[c + 1];
    if (t.value < 0.0f || t.value > 1.0f)
      throw Error(std::string(kKey) + pointName(index) + ": " + std::string(kChannels[c]) + " " + shownNumber(t.text, t.value) +
                  " is outside [0, 1]");
  }
  TransferPoint point;
  point.value = tokens[0].value;
  point.color = {tokens[1].value, tokens[2].value, tokens[3].value};
  point.opacity = tokens[4].value;
  return point;
}

}  // namespace

glm::vec4 TransferFunction::operator()(float value) const {
  if (points.empty()) return glm::vec4(0.0f);
  const auto rgba = [](const TransferPoint& p) { return glm::vec4(p.color, p.opacity); };
  // Not above the first point (and NaN, which compares with nothing): the first point's.
  if (!(value > points.front().value)) return rgba(points.front());
  if (value >= points.back().value) return rgba(points.back());
  const auto upper = std::upper_bound(points.begin(), points.end(), value, [](float v, const TransferPoint& p) { return v < p.value; });
  const TransferPoint& a = *(upper - 1);
  const TransferPoint& b = *upper;
  const float t = (value - a.value) / (b.value - a.value);
  const glm::vec4 from = rgba(a), to = rgba(b);
  glm::vec4 result;
  for (int i = 0; i < 4; ++i) result[i] = from[i] + t * (to[i] - from[i]);
  return result;
}

TransferFunction parseTransferFunction(std::string_view text, float minValue, float maxValue) {
  const std::string_view all = trimmed(text);
  if (all.empty())
    throw Error(std::string(kKey) + "empty (give a preset, one of " + presetList() + ", or points \"value r g b a, value r g b a, ...\")");
  if (looksLikeName(all)) {
    for (const Preset& preset : kPresets)
      if (preset.name == all) return presetFunction(preset, minValue, maxValue);
    throw Error(std::string(kKey) + "unknown preset " + quoteInput(all) + " (presets: " + presetList() + ")");
  }
  TransferFunction f;
  std::vector<std::string_view> valueTexts;  // each point's value as written, for messages
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = all.find(',', start);
    const std::string_view piece = all.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
    const std::size_t index = f.points.size();
    const TransferPoint point = parsePoint(piece, index);
    const std::string_view valueText = trimmed(piece).substr(0, trimmed(piece).find_first_of(" \t\n\r\f\v"));
    if (index > 0 && !(point.value > f.points.back().value))
      throw Error(std::string(kKey) + pointName(index) + " (value " + shownNumber(valueText, point.value) + ") is not above " +
                  pointName(index - 1) + " (value " + shownNumber(valueTexts.back(), f.points.back().value) + ")");
    f.points.push_back(point);
    valueTexts.push_back(valueText);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return f;
}

std::vector<std::string_view> transferPresetNames() {
  std::vector<std::string_view> names;
  for (const Preset& p : kPresets) names.push_back(p.name);
  return names;
}

}  // namespace facet
