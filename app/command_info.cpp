// facet info: what a scene holds, as the renderers will see it.
#include <cstdio>
#include <memory>
#include <sstream>

#include <glm/trigonometric.hpp>

#include "command_line.h"
#include "commands.h"
#include "common/atomic_file.h"
#include "pipeline/material_coefficients.h"
#include "scene/load_scene.h"

namespace facet {
namespace {

std::string str(glm::vec3 v) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g)", static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z));
  return text;
}

std::string describe(const Scene& scene, const RenderSettings& settings) {
  std::ostringstream out;
  out << "scene: " << scene.source << "\n";
  out << "meshes: " << scene.meshes.size() << ", instances: " << scene.instances.size()
      << ", triangles: " << scene.triangleCount() << "\n";
  const Bounds b = scene.worldBounds();
  if (b.empty) out << "bounds: empty\n";
  else out << "bounds: min " << str(b.min) << " max " << str(b.max) << " radius " << b.radius() << "\n";

  out << "materials: " << scene.materials.size() << "\n";
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    const CourseMaterial c = courseMaterial(m, settings.material, settings.transparency);
    out << "  " << i << " '" << m.name << "': base colour " << str(glm::vec3(m.baseColor)) << (m.baseColorTexture >= 0 ? " x texture" : "")
        << ", metallic " << m.metallic << ", roughness " << m.roughness << " -> k_a " << c.ka << ", k_d " << c.kd << ", k_s " << c.ks
        << ", n " << c.shininess << (m.doubleSided ? ", double-sided" : "");
    if (c.blended) out << ", blended (alpha " << c.baseAlpha << ")";
    else if (c.masked) out << ", masked at alpha " << c.alphaCutoff;
    out << "\n";
  }
  out << "textures: " << scene.textures.size() << "\n";
  for (std::size_t i = 0; i < scene.textures.size(); ++i)
    out << "  " << i << " '" << scene.textures[i].name << "': " << scene.textures[i].image.width() << "x" << scene.textures[i].image.height() << "\n";
  out << "lights: " << scene.lights.size() << "\n";
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& l = scene.lights[i];
    out << "  " << i << " " << kLightKindNames[static_cast<std::size_t>(l.kind)];
    if (l.kind != LightKind::Directional) out << " at " << str(l.position);
    if (l.kind != LightKind::Point) out << " toward " << str(l.direction);
    out << ", colour " << str(l.color) << " x " << l.intensity << ", attenuation " << str(l.attenuation);
    if (l.kind == LightKind::Spot) out << ", cut-off " << l.spotCutoffDeg << " deg";
    out << (l.castsShadow ? ", casts shadows" : "") << "\n";
  }
  out << "cameras: " << scene.cameras.size() << "\n";
  for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
    const SceneCamera& c = scene.cameras[i];
    out << "  " << i << " '" << c.name << "': " << kProjectionKindNames[static_cast<std::size_t>(c.projection)] << ", eye " << str(c.eye)
        << " looking at " << str(c.reference);
    if (c.projection == ProjectionKind::Perspective) out << ", vertical angle of view " << glm::degrees(c.yfov) << " deg";
    else out << ", half extents " << c.xmag << " x " << c.ymag;
    out << ", near " << c.near << ", far ";
    if (c.far) out << *c.far;
    else out << "infinite";
    out << "\n";
  }
  out << "warnings: " << scene.warnings.size() << "\n";
  for (const std::string& w : scene.warnings) out << "  " << w << "\n";
  return out.str();
}

}  // namespace

Command addInfoCommand(CLI::App& app) {
  auto options = std::make_shared<CommonOptions>();
  CLI::App* command = app.add_subcommand("info", "Print a scene's meshes, triangle count, materials, lights, cameras and bounds");
  addCommonOptions(*command, *options, "also write the report to this file");
  return [options]() {
    if (!options->output.empty()) checkOutputFile(options->output, {options->scenePath, options->settingsPath});
    const Scene scene = loadScene(options->scenePath);
    const RenderSettings settings = settingsFor(*options, scene);
    const std::string report = describe(scene, settings);
    std::fputs(report.c_str(), stdout);
    if (!options->output.empty()) {
      writeFileAtomically(options->output, {reinterpret_cast<const std::uint8_t*>(report.data()), report.size()});
      std::printf("report written to %s\n", options->output.c_str());
    }
    return 0;
  };
}

}  // namespace facet
