// facet settings: the RenderSettings a command would run with, as JSON.
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "command_line.h"
#include "commands.h"
#include "common/atomic_file.h"
#include "scene/load_scene.h"
#include "settings/settings_json.h"

namespace facet {

Command addSettingsCommand(CLI::App& app) {
  auto options = std::make_shared<CommonOptions>();
  CLI::App* command = app.add_subcommand(
      "settings", "Print the RenderSettings as JSON: the defaults, or with --settings/--set/--size applied for the scene");
  addCommonOptions(*command, *options, "write the JSON to this file instead of standard output");
  return [options]() {
    if (!options->output.empty()) checkOutputFile(options->output, {options->scenePath, options->settingsPath});
    const Scene scene = loadScene(options->scenePath);
    const std::string text = settingsToJson(settingsFor(*options, scene)).dump(2) + "\n";
    if (options->output.empty()) {
      std::fputs(text.c_str(), stdout);
    } else {
      writeFileAtomically(options->output, text);
      std::printf("settings written to %s\n", options->output.c_str());
    }
    return 0;
  };
}

}  // namespace facet
