#include "command_line.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "common/error.h"
#include "common/quote.h"
#include "pipeline/frame_checks.h"
#include "pipeline/view_setup.h"
#include "output_option.h"
#include "settings/settings_json.h"

namespace facet {

namespace {

// What is wrong with a --size value, or "" with width and height set.
std::string sizeProblem(const std::string& text, int& width, int& height) {
  const auto x = text.find('x');
  if (x == std::string::npos) return "expected WxH, e.g. 800x600";
  int* sides[2] = {&width, &height};
  const std::string parts[2] = {text.substr(0, x), text.substr(x + 1)};
  for (int i = 0; i < 2; ++i) {
    const std::string& part = parts[i];
    if (part.empty() || part.size() > 5 || part.find_first_not_of("0123456789") != std::string::npos)
      return "expected WxH with whole numbers, e.g. 800x600";
    *sides[i] = std::stoi(part);
    if (*sides[i] < 1 || *sides[i] > kMaxImageSide) return "each side must be in [1, " + std::to_string(kMaxImageSide) + "]";
  }
  return {};
}

}  // namespace

void addCommonOptions(CLI::App& command, CommonOptions& options, const std::string& outputHelp) {
  command.add_option("scene", options.scenePath,
                     "glTF 2.0 scene (.gltf or .glb), or builtin:default|cornell|fountain|sphere|cube|plane|cylinder|torus, or a volume (.nrrd, .nhdr, .nii, .nii.gz, builtin:marschner-lobb); none: the built-in default scene");
  command.add_option("--settings", options.settingsPath, "RenderSettings JSON file (print the defaults with `facet settings`)");
  command.add_option("--set", options.assignments,
                     "override one settings key, repeatable: --set shading=gouraud --set lights.0.position=[1,4,2]")
      ->take_all()
      ->allow_extra_args(false);
  // Checked while the command line is parsed, before any file is read.
  command.add_option("--size", options.size, "image size WxH, e.g. 1280x720 (overrides width and height)")
      ->check(CLI::Validator(
          [](std::string& text) {
            int width = 0, height = 0;
            const std::string problem = sizeProblem(text, width, height);
            return problem.empty() ? problem : quoteInput(text) + ": " + problem;
          },
          "WxH"));
  // F3D's names (--camera-azimuth-angle, ...) too: an F3D command line's camera carries over.
  command.add_option("--camera-azimuth,--camera-azimuth-angle", options.orbit.azimuthDeg,
                     "degrees: turn the camera (the scene's, the fitted one or camera.eye) about camera.up through camera.reference; "
                     "+ moves the eye to its right (F3D's --camera-azimuth-angle)")
      ->check(numberIn(-1e6, 1e6));
  command.add_option("--camera-elevation,--camera-elevation-angle", options.orbit.elevationDeg,
                     "degrees: raise the eye about the camera's right axis through camera.reference, stopping 1 degree short of the "
                     "pole (F3D's --camera-elevation-angle)")
      ->check(numberIn(-1e6, 1e6));
  command.add_option("--camera-zoom,--camera-zoom-factor", options.orbit.zoom,
                     "factor: divide the eye's distance from camera.reference (2: twice as close; F3D's --camera-zoom-factor)")
      ->check(numberIn(1e-6, 1e6));
  refuseEmptyName(command.add_option("-o,--output", options.output, outputHelp));
}


void parseSize(const std::string& text, int& width, int& height) {
  if (const std::string problem = sizeProblem(text, width, height); !problem.empty())
    throw UsageError("--size " + quoteInput(text) + ": " + problem);
}

std::array<int, 2> parsePixel(const std::string& text, const std::string& option) {
  std::array<int, 2> xy{};
  const std::size_t comma = text.find(',');
  bool ok = comma != std::string::npos;
  for (int k = 0; ok && k < 2; ++k) {
    const std::string part = k == 0 ? text.substr(0, comma) : text.substr(comma + 1);
    std::size_t used = 0;
    try {
      const long value = std::stol(part, &used);
      ok = used == part.size() && value >= 0 && value <= kMaxImageSide;
      xy[static_cast<std::size_t>(k)] = static_cast<int>(value);
    } catch (const std::exception&) {
      ok = false;
    }
  }
  if (!ok) throw UsageError(option + " " + quoteInput(text) + ": expected X,Y, whole numbers from 0 (the pixel from the top left)");
  return xy;
}

CLI::Validator wholeNumberIn(int min, int max) {
  return CLI::Validator(
      [min, max](std::string& text) -> std::string {
        long value = 0;
        std::size_t used = 0;
        try {
          value = std::stol(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != text.size()) return quoteInput(text) + " is not a whole number";
        if (value < min || value > max)
          return text + " is out of range [" + std::to_string(min) + ", " + std::to_string(max) + "]";
        return {};
      },
      "INT in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
}

CLI::Validator numberIn(double min, double max) {
  const auto shortest = [](double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return std::string(text);
  };
  return CLI::Validator(
      [min, max, shortest](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = text.empty() || std::isspace(static_cast<unsigned char>(text[0])) ? NAN : std::strtod(text.c_str(), &end);
        if (!std::isfinite(value) || end != text.c_str() + text.size()) return quoteInput(text) + " is not a number";
        if (value < min || value > max) return text + " is out of range [" + shortest(min) + ", " + shortest(max) + "]";
        return {};
      },
      "FLOAT in [" + shortest(min) + ", " + shortest(max) + "]");
}

RenderSettings settingsFor(const CommonOptions& options, const Scene& scene) {
  RenderSettings base;
  if (!options.settingsPath.empty()) {
    base = loadSettingsFile(options.settingsPath);
    try {
      checkSettings(base);
    } catch (const Error& e) {
      throw Error(options.settingsPath + ": " + e.what());
    }
  }
  RenderSettings settings = settingsFor(base, options.assignments, options.size, scene);
  // After the size: the auto camera is fitted to the image's aspect.
  if (options.orbit.moves()) settings.camera = orbitCamera(resolveCamera(scene, settings), options.orbit);
  return settings;
}

RenderSettings settingsFor(RenderSettings settings, const std::vector<std::string>& assignments, const std::string& size, const Scene& scene) {
  if (!size.empty()) parseSize(size, settings.width, settings.height);
  for (const std::string& assignment : assignments) {
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
  if (!size.empty()) parseSize(size, settings.width, settings.height);  // --size wins over --set width
  // What no single key's range says (a transfer function, a camera, an
  // emitter's drag against its step), checked now rather than at frame time.
  try {
    checkSettings(settings);
  } catch (const UsageError&) {
    throw;
  } catch (const Error& e) {
    if (assignments.empty()) throw;
    throw UsageError(e.what());
  }
  return settings;
}

}  // namespace facet
