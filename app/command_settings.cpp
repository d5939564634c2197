// facet settings: the RenderSettings a command would run with, as JSON.
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "command_line.h"
#include "commands.h"
#include "common/atomic_file.h"
#include "scene/load_scene.h"
#include "settings/settings_json.h"
#include "settings/settings_table.h"

namespace facet {

Command addSettingsCommand(CLI::App& app) {
  auto options = std::make_shared<CommonOptions>();
  CLI::App* command = app.add_subcommand(
      "settings", "Print the RenderSettings as JSON: the defaults, or with --settings/--set/--size applied for the scene");
  addCommonOptions(*command, *options, "write the JSON to this file instead of standard output");
  auto keys = std::make_shared<bool>(false);
  command->add_flag("--keys", *keys, "print every key, its default, range and meaning as a Markdown table (docs/settings.md's) instead");
  return [options, keys]() {
    if (*keys) {
      std::fputs(settingsTable().c_str(), stdout);
      return 0;
    }
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
