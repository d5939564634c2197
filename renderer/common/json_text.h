#pragma once
// Reading JSON text strictly, the way facet reads every JSON it is given
// (settings files, --set values): UTF-8 only, no NUL byte, no key twice in
// one object, numbers that fit a double, and nesting bounded so that nothing
// that walks the value afterwards (copy, dump, compare: all recursive in
// nlohmann::json) can run out of stack. Messages leave out the file name;
// the caller puts it in front.
#include <cstddef>
#include <string_view>

#include <nlohmann/json.hpp>

#include "common/error.h"

namespace facet {

// Thrown when the text is not JSON at all (the grammar fails): a caller that
// accepts bare words (--set shading=gouraud) takes the text as a string then.
// Every other refusal is a plain facet::Error.
class JsonSyntaxError : public Error {
 public:
  using Error::Error;
};

// Parses `text`; objects and arrays may nest at most `maxDepth` deep.
nlohmann::json parseStrictJson(std::string_view text, std::size_t maxDepth);

// A JSON value as an error line shows it: a scalar as written (a string
// through quoteInput()), an array or object by its size, never walking into it.
std::string describeJson(const nlohmann::json& value);

// The shortest decimal that reads back as `value` (1.0000001, not 1.000000).
std::string exactNumber(double value);

}  // namespace facet
