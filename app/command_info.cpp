// facet info: what a scene holds, as the renderers will see it (with what the settings add: pipeline/frame_spine.h).
#include <algorithm>
#include <cstdio>
#include <memory>
#include <sstream>

#include <glm/trigonometric.hpp>

#include "command_line.h"
#include "commands.h"
#include "common/atomic_file.h"
#include "common/error.h"
#include "pipeline/frame_spine.h"
#include "pipeline/material_coefficients.h"
#include "scene/gltf_writer.h"
#include "scene/load_scene.h"

namespace facet {
namespace {

std::string str(glm::vec3 v) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g)", static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z));
  return text;
}

std::string describe(const Scene& scene, const RenderSettings& settings, const SceneAdditions& added) {
  std::ostringstream out;
  out << "scene: " << scene.source << "\n";
  if (const Volume* v = scene.volume.data.get()) {
    out << "volume: " << v->source << ", " << v->size.x << "x" << v->size.y << "x" << v->size.z << " samples, spacing " << str(v->spacing)
        << ", values " << v->minValue << " to " << v->maxValue << ", drawn by " << kVolumeModeNames[static_cast<std::size_t>(settings.volume.mode)]
        << "\n";
    if (added.isosurface) out << "iso-surface: " << added.isoTriangles << " triangles (marching cubes)\n";
    if (added.splats) out << "splats: " << added.splats << " voxels the transfer function shows\n";
  }
  if (added.particles) out << "particles: " << added.particles << " alive at time " << settings.time << " s\n";
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
  auto isosurface = std::make_shared<std::string>();
  command->add_option("--write-isosurface", *isosurface, "write the volume's iso-surface (volume.mode=isosurface) as a glTF 2.0 file");
  return [options, isosurface]() {
    if (!options->output.empty()) checkOutputFile(options->output, {options->scenePath, options->settingsPath});
    if (!isosurface->empty()) checkOutputFile(*isosurface, {options->scenePath, options->settingsPath});
    if (!options->output.empty() && !isosurface->empty()) checkDistinctOutputs({{options->output, "-o"}, {*isosurface, "--write-isosurface"}});
    const auto loaded = std::make_shared<const Scene>(loadScene(options->scenePath));
    const FrameScene frame = FrameSpine(loaded).scene(settingsFor(*options, *loaded));
    const Scene& scene = *frame.scene;
    const std::string report = describe(scene, frame.settings, frame.added);
    if (!isosurface->empty()) {
      if (!frame.added.isosurface) throw UsageError("--write-isosurface: the scene has no iso-surface (give a volume and --set volume.mode=isosurface)");
      const auto at = std::find_if(scene.meshes.begin(), scene.meshes.end(), [](const Mesh& m) { return m.name == "isosurface"; });
      if (at == scene.meshes.end()) throw Error("--write-isosurface: the iso-surface is empty at volume.isoValue");
      writeMeshGltf(*at, scene.volume.worldFromVolume, frame.settings.volume.isoColor, *isosurface);
    }
    std::fputs(report.c_str(), stdout);
    if (!options->output.empty()) {
      writeFileAtomically(options->output, {reinterpret_cast<const std::uint8_t*>(report.data()), report.size()});
      std::printf("report written to %s\n", options->output.c_str());
    }
    if (!isosurface->empty()) std::printf("iso-surface written to %s\n", isosurface->c_str());
    return 0;
  };
}

}  // namespace facet
