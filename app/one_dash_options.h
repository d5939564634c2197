#pragma once
// idiff spells its long options with one dash (-fail 0.004, -od). CLI11
// reads "-fail" as the short options -f -a -i -l, and "-od" as -o with the
// value "d", so a command that follows idiff has those words rewritten to
// two dashes before CLI11 parses them.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace facet {

// `words` (a command line after the program name, `command`'s name first)
// with each word that is one dash and the name of one of `command`'s long
// options ("-fail" for --fail) spelled with two; words after "--" stay.
std::vector<std::string> withOneDashLongOptions(const CLI::App& command, std::vector<std::string> words);

}  // namespace facet
