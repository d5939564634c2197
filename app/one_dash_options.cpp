#include "one_dash_options.h"

namespace facet {

std::vector<std::string> withOneDashLongOptions(const CLI::App& command, std::vector<std::string> words) {
  for (std::size_t i = 1; i < words.size(); ++i) {
    std::string& word = words[i];
    if (word == "--") break;
    // "-o" and "-q" are short options already; "--fail" needs nothing.
    if (word.size() < 3 || word[0] != '-' || word[1] == '-') continue;
    const std::string twoDashes = "-" + word;
    if (command.get_option_no_throw(twoDashes) != nullptr) word = twoDashes;
  }
  return words;
}

}  // namespace facet
