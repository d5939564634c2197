#pragma once
// One function per subcommand: registers it on the app and returns the
// action main runs when it is chosen.
#include <functional>

#include <CLI/CLI.hpp>

namespace facet {

using Command = std::function<int()>;

Command addInfoCommand(CLI::App& app);
Command addSettingsCommand(CLI::App& app);

}  // namespace facet
