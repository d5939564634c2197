#include "command_line.h"

#include "common/error.h"
#include "pipeline/view_setup.h"
#include "settings/settings_json.h"

namespace facet {

void addCommonOptions(CLI::App& command, CommonOptions& options, const std::string& outputHelp) {
  command.add_option("scene", options.scenePath,
                     "glTF 2.0 scene (.gltf or .glb), or builtin:default|sphere|cube|plane|cylinder|torus; none: the built-in default scene");
  command.add_option("--settings", options.settingsPath, "RenderSettings JSON file (print the defaults with `facet settings`)");
  command.add_option("--set", options.assignments,
                     "override one settings key, repeatable: --set shading=gouraud --set lights.0.position=[1,4,2]")
      ->take_all()
      ->allow_extra_args(false);
  command.add_option("--size", options.size, "image size WxH, e.g. 1280x720 (overrides width and height)");
  command.add_option("-o,--output", options.output, outputHelp);
}

void parseSize(const std::string& text, int& width, int& height) {
  const auto x = text.find('x');
  const auto parse = [&](const std::string& part) {
    if (part.empty() || part.size() > 5 || part.find_first_not_of("0123456789") != std::string::npos)
      throw UsageError("--size '" + text + "': expected WxH with whole numbers, e.g. 800x600");
    const int v = std::stoi(part);
    if (v < 1 || v > kMaxImageSide)
      throw UsageError("--size '" + text + "': each side must be in [1, " + std::to_string(kMaxImageSide) + "]");
    return v;
  };
  if (x == std::string::npos) throw UsageError("--size '" + text + "': expected WxH, e.g. 800x600");
  width = parse(text.substr(0, x));
  height = parse(text.substr(x + 1));
}

RenderSettings settingsFor(const CommonOptions& options, const Scene& scene) {
  RenderSettings settings = options.settingsPath.empty() ? RenderSettings{} : loadSettingsFile(options.settingsPath);
  if (!options.size.empty()) parseSize(options.size, settings.width, settings.height);
  for (const std::string& assignment : options.assignments) {
    const std::string key = assignment.substr(0, assignment.find('='));
    const bool cameraKey = key.rfind("camera.", 0) == 0 && key != "camera.source";
    const bool lightKey = key == "lights" || key.rfind("lights.", 0) == 0;
    if (cameraKey && settings.camera.source == Source::Auto) settings = materialize(scene, settings, true, false);
    if (lightKey && settings.lightSource == Source::Auto) settings = materialize(scene, settings, false, true);
    try {
      applySetting(settings, assignment);
    } catch (const UsageError&) {
      throw;
    } catch (const Error& e) {
      throw UsageError(e.what());
    }
  }
  if (!options.size.empty()) parseSize(options.size, settings.width, settings.height);  // --size wins over --set width
  return settings;
}

}  // namespace facet
