#pragma once
// One function per subcommand: registers it on the app and returns the
// action main runs when it is chosen.
#include <functional>

#include <CLI/CLI.hpp>

namespace facet {

using Command = std::function<int()>;

Command addInfoCommand(CLI::App& app);
Command addSettingsCommand(CLI::App& app);
Command addRenderCommand(CLI::App& app);
Command addDiffCommand(CLI::App& app);
Command addBenchCommand(CLI::App& app);
#if FACET_HAVE_VIEWER
Command addViewCommand(CLI::App& app);  // app/viewer
#endif

}  // namespace facet
