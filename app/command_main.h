#pragma once
// The command-line front shared by the two executables: `facet` (every
// headless command) and `facet-view` (the window, which alone links GLFW
// and X11). Each registers its commands; parsing, help, usage errors (64)
// and the one-line error report are the same for both.
#include <functional>
#include <vector>

#include <CLI/CLI.hpp>

#include "commands.h"

namespace facet {

using AddCommand = std::function<Command(CLI::App&)>;

// Registers `commands` on facet's app, parses argv, runs the chosen one and
// returns the process's exit code; every exception ends as one line.
int runCommands(int argc, char** argv, const std::vector<AddCommand>& commands);

// facet's version, the project's (CMake's PROJECT_VERSION): "0.1.0".
const char* facetVersion();

}  // namespace facet
