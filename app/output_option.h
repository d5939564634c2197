#pragma once
// -o/--output as every facet command takes it.
#include <CLI/CLI.hpp>

namespace facet {

// An empty name (-o "", --output=) is a command line that does not parse
// (exit 64), never "no output" or a default file name.
CLI::Option* refuseEmptyName(CLI::Option* output);

}  // namespace facet
