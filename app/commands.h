#pragma once
// One function per subcommand: registers it on the app and returns the
// action main runs when it is chosen.
#include <functional>
#include <string_view>

#include <CLI/CLI.hpp>

namespace facet {

using Command = std::function<int()>;

Command addInfoCommand(CLI::App& app);
Command addSettingsCommand(CLI::App& app);
Command addRenderCommand(CLI::App& app);
Command addDiffCommand(CLI::App& app);
Command addBenchCommand(CLI::App& app);
Command addBatchCommand(CLI::App& app);

// `facet view`: in facet, a launcher that runs the facet-view executable with
// the same arguments (app/view_launcher.cpp); in facet-view, the window
// itself (app/viewer/command_view.cpp). Both show this line in the help.
inline constexpr std::string_view kViewSummary =
    "Open the scene in a window (OpenGL 4.5): a panel for every setting, an orbit camera, the CPU reference beside the GL image";
Command addViewLauncher(CLI::App& app);
Command addViewCommand(CLI::App& app);

}  // namespace facet
