#include "common/json_text.h"

#include <charconv>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "common/quote.h"

namespace facet {
namespace {

using nlohmann::json;

// Offset of the first byte that is not part of well-formed UTF-8, or npos.
std::size_t firstNonUtf8(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    const auto b = static_cast<std::uint8_t>(text[i]);
    std::size_t n = b < 0x80 ? 1 : (b & 0xe0) == 0xc0 ? 2 : (b & 0xf0) == 0xe0 ? 3 : (b & 0xf8) == 0xf0 ? 4 : 0;
    if (n == 0 || i + n > text.size()) return i;
    std::uint32_t code = n == 1 ? b : n == 2 ? (b & 0x1fu) : n == 3 ? (b & 0x0fu) : (b & 0x07u);
    for (std::size_t k = 1; k < n; ++k) {
      const auto c = static_cast<std::uint8_t>(text[i + k]);
      if ((c & 0xc0) != 0x80) return i;
      code = (code << 6) | (c & 0x3fu);
    }
    static constexpr std::uint32_t kMinimum[5] = {0, 0, 0x80, 0x800, 0x10000};
    if (code < kMinimum[n] || code > 0x10ffff || (code >= 0xd800 && code <= 0xdfff)) return i;
    i += n;
  }
  return std::string_view::npos;
}

std::string hexByte(unsigned char b) {
  static constexpr char kDigits[] = "0123456789abcdef";
  return std::string("0x") + kDigits[b >> 4] + kDigits[b & 15];
}

// The path of the value being read ("lights.0.position") and the keys each
// open object has had, kept by the parser callback.
struct Frame {
  bool isObject;
  std::set<std::string> keys;
  std::string key;        // object: the key of the value being read
  std::size_t count = 0;  // array: the index of the element being read
};

std::string pathOf(const std::vector<Frame>& frames) {
  std::string path;
  for (const Frame& f : frames) {
    const std::string part = f.isObject ? f.key : std::to_string(f.count);
    path += path.empty() ? part : "." + part;
  }
  return path;
}

// nlohmann's message without its "[json.exception.parse_error.101] " tag,
// and its "last read: '...'" (which echoes raw input) bounded by quoteInput().
std::string reasonOf(const json::exception& e) {
  std::string what = e.what();
  if (const auto tag = what.find("] "); what.rfind("[json.exception.", 0) == 0 && tag != std::string::npos) what.erase(0, tag + 2);
  const std::string marker = "; last read: '";
  if (const auto at = what.find(marker); at != std::string::npos) {
    std::string read = what.substr(at + marker.size());
    if (!read.empty() && read.back() == '\'') read.pop_back();
    what = what.substr(0, at) + "; last read: " + quoteInput(read);
  }
  return what;
}

}  // namespace

json parseStrictJson(std::string_view text, std::size_t maxDepth) {
  if (const std::size_t bad = firstNonUtf8(text); bad != std::string_view::npos) {
    const auto b = static_cast<unsigned char>(text[bad]);
    const bool utf16 = text.size() >= 2 && ((text[0] == '\xff' && text[1] == '\xfe') || (text[0] == '\xfe' && text[1] == '\xff'));
    throw Error("not UTF-8 text (byte " + hexByte(b) + " at offset " + std::to_string(bad) + (utf16 ? "; this looks like UTF-16" : "") +
                "); JSON is read as UTF-8");
  }
  if (const auto nul = text.find('\0'); nul != std::string_view::npos)
    throw Error("a NUL byte at offset " + std::to_string(nul) + (nul < 2 ? " (UTF-16?)" : "") + "; JSON text has none");

  std::vector<Frame> frames;
  const auto enter = [&](bool isObject) {
    if (frames.size() >= maxDepth)
      throw Error("nested deeper than " + std::to_string(maxDepth) + " levels at " + (frames.empty() ? "the top" : quoteInput(pathOf(frames))));
    frames.push_back(Frame{isObject, {}, {}, 0});
  };
  const auto valueDone = [&] {
    if (!frames.empty() && !frames.back().isObject) ++frames.back().count;
  };
  const json::parser_callback_t callback = [&](int, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start: enter(true); break;
      case json::parse_event_t::array_start: enter(false); break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        frames.pop_back();
        valueDone();
        break;
      case json::parse_event_t::key: {
        Frame& f = frames.back();
        f.key = parsed.get<std::string>();
        if (!f.keys.insert(f.key).second) throw Error("the key " + quoteInput(pathOf(frames)) + " appears twice");
        break;
      }
      case json::parse_event_t::value: valueDone(); break;
    }
    return true;
  };
  try {
    return json::parse(text.begin(), text.end(), callback);
  } catch (const json::parse_error& e) {
    throw JsonSyntaxError("not valid JSON (" + reasonOf(e) + ")");
  } catch (const json::out_of_range& e) {
    // nlohmann's text is "number overflow parsing '<the number>'".
    const std::string what = e.what();
    const auto at = what.find("parsing '");
    const std::string number = at == std::string::npos ? std::string() : what.substr(at + 9, what.size() - at - 10);
    throw Error("the number " + quoteInput(number) + " is too large for a double");
  } catch (const json::exception& e) {
    throw Error("not valid JSON (" + reasonOf(e) + ")");
  }
}

std::string describeJson(const json& value) {
  switch (value.type()) {
    case json::value_t::string: return quoteInput(value.get_ref<const std::string&>());
    case json::value_t::array: return "an array of " + std::to_string(value.size()) + (value.size() == 1 ? " element" : " elements");
    case json::value_t::object: return "an object";
    case json::value_t::number_float: return exactNumber(value.get<double>());
    default: return value.dump();  // null, true, false, integers: short, no nesting
  }
}

std::string exactNumber(double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

}  // namespace facet
