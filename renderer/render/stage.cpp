#include "render/stage.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "common/error.h"
#include "common/quote.h"
#include "common/stopwatch.h"
#include "compare/depth_complexity.h"
#include "pipeline/stage_frames.h"
#include "settings/render_settings.h"

namespace facet {
namespace {

constexpr std::string_view kLightPrefix = "light-";
// A point light's faces in layer order (PIPELINE.md, "Lights").
constexpr std::array<std::string_view, 6> kFaceNames = {"+x", "-x", "+y", "-y", "+z", "-z"};

std::string nameOf(StageKind kind) { return std::string(kStageKindNames[static_cast<std::size_t>(kind)]); }

[[noreturn]] void unknownStage(std::string_view name) {
  throw UsageError("--output-stage " + quoteInput(name) + ": expected image, overdraw, depth, shadow-map, normals or light-N (N = 0, 1, ...)");
}

std::string figure(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string rangeText(const DepthRange& range) {
  return range.drawn == 0 ? std::string("nothing drawn") : "window z from " + figure("%.9g", range.near) + " to " + figure("%.9g", range.far);
}

}  // namespace

Stage parseStage(std::string_view name) {
  for (std::size_t k = 0; k < kStageKindNames.size(); ++k)
    if (static_cast<StageKind>(k) != StageKind::Light && name == kStageKindNames[k]) return {static_cast<StageKind>(k), 0};
  if (name.substr(0, kLightPrefix.size()) != kLightPrefix) unknownStage(name);
  const std::string_view digits = name.substr(kLightPrefix.size());
  if (digits.empty() || digits.size() > 9 || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
    unknownStage(name);
  return {StageKind::Light, static_cast<std::size_t>(std::stoul(std::string(digits)))};
}

std::string stageName(Stage stage) {
  return stage.kind == StageKind::Light ? std::string(kLightPrefix) + std::to_string(stage.light) : nameOf(stage.kind);
}

std::vector<std::string> stageNames(const FrameInputs& frame) {
  std::vector<std::string> names = {nameOf(StageKind::Image), nameOf(StageKind::Overdraw)};
  if (frame.hsr != HiddenSurface::Painter) names.push_back(nameOf(StageKind::Depth));
  if (frame.shadowLayerCount > 0) names.push_back(nameOf(StageKind::ShadowMap));
  names.push_back(nameOf(StageKind::Normals));
  for (std::size_t l = 0; l < frame.lights.size(); ++l) names.push_back(stageName({StageKind::Light, l}));
  return names;
}

void checkStage(const FrameInputs& frame, Stage stage) {
  const std::string option = "--output-stage " + stageName(stage) + ": ";
  if (stage.kind == StageKind::Light && stage.light >= frame.lights.size())
    throw UsageError(option + "the frame has " + countOf(frame.lights.size(), "light") +
                     (frame.lights.empty() ? "" : " (light-0" + (frame.lights.size() > 1 ? " to light-" + std::to_string(frame.lights.size() - 1) : "") + ")"));
  if (stage.kind == StageKind::ShadowMap && frame.shadowLayerCount == 0)
    throw Error(option + "the frame has no shadow maps: " +
                (!frame.shadows.enabled   ? std::string("settings key 'shadows.enabled' is false")
                 : frame.lights.empty()   ? std::string("it has no lights")
                                          : "no light casts shadows (settings key 'lights.N.castsShadow', or the scene's lights)"));
  if (stage.kind == StageKind::Depth && frame.hsr == HiddenSurface::Painter)
    throw Error(option + "settings key 'hsr': painter keeps no z-buffer (zbuffer and scanline do)");
}

DepthRange depthRangeOf(const float* depth, std::size_t count) {
  DepthRange range{1.0f, 0.0f, 0};
  for (std::size_t i = 0; i < count; ++i) {
    const float z = depth[i];
    if (!(z < 1.0f)) continue;  // nothing drawn (or NaN, which the z-buffer never keeps)
    range.near = std::min(range.near, z);
    range.far = std::max(range.far, z);
    ++range.drawn;
  }
  if (range.drawn == 0) range.far = 1.0f;
  return range;
}

std::uint8_t depthGrey(float z, const DepthRange& range) {
  if (!(z < 1.0f)) return 0;
  const double span = static_cast<double>(range.far) - static_cast<double>(range.near);
  const double t = span > 0.0 ? (static_cast<double>(range.far) - static_cast<double>(z)) / span : 1.0;  // 1 near, 0 far
  const double level = kFarGrey + (kNearGrey - kFarGrey) * std::clamp(t, 0.0, 1.0);
  return static_cast<std::uint8_t>(std::floor(level + 0.5));
}

Image depthImage(const std::vector<float>& depth, int width, int height) {
  const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (depth.size() != count) throw Error("depth image: " + std::to_string(depth.size()) + " values for " + std::to_string(count) + " pixels");
  const DepthRange range = depthRangeOf(depth.data(), count);
  Image image(width, height);
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint8_t g = depthGrey(depth[i], range);
    image.data()[i] = {g, g, g, 255};
  }
  return image;
}

Image shadowMapImage(const ShadowMapTexels& maps, int& downsample) {
  const std::size_t perLayer = static_cast<std::size_t>(maps.size) * static_cast<std::size_t>(maps.size);
  if (maps.size < 1 || maps.layers < 1 || maps.texels.size() != perLayer * static_cast<std::size_t>(maps.layers))
    throw Error("shadow-map image: " + std::to_string(maps.texels.size()) + " texels for " + std::to_string(maps.layers) + " layers of " +
                std::to_string(maps.size) + "x" + std::to_string(maps.size));
  const auto side = [&](int factor) { return (maps.size + factor - 1) / factor; };  // texels 0, f, 2f, ... of a row
  downsample = 1;
  while (static_cast<long long>(maps.layers) * side(downsample) > kMaxImageSide) ++downsample;
  const int s = side(downsample);
  Image image(maps.layers * s, s);
  for (int layer = 0; layer < maps.layers; ++layer) {
    const float* texels = maps.texels.data() + perLayer * static_cast<std::size_t>(layer);
    const DepthRange range = depthRangeOf(texels, perLayer);  // the layer's own, at full resolution
    for (int y = 0; y < s; ++y)
      for (int x = 0; x < s; ++x) {
        const float z = texels[static_cast<std::size_t>(y * downsample) * static_cast<std::size_t>(maps.size) + static_cast<std::size_t>(x * downsample)];
        const std::uint8_t g = depthGrey(z, range);
        image.at(layer * s + x, y) = {g, g, g, 255};
      }
  }
  return image;
}

Image normalsImage(const std::vector<glm::vec4>& normals, int width, int height) {
  const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (normals.size() != count) throw Error("normals image: " + std::to_string(normals.size()) + " normals for " + std::to_string(count) + " pixels");
  const auto level = [](float n) {
    const double c = (static_cast<double>(n) + 1.0) * 0.5;
    return static_cast<std::uint8_t>(std::floor(255.0 * (c > 0.0 ? (c < 1.0 ? c : 1.0) : 0.0) + 0.5));
  };
  Image image(width, height);
  for (std::size_t i = 0; i < count; ++i) {
    const glm::vec4 n = normals[i];
    image.data()[i] = n.w != 0.0f ? Rgba8{level(n.x), level(n.y), level(n.z), 255} : Rgba8{0, 0, 0, 255};
  }
  return image;
}

RenderResult renderStage(Renderer& renderer, const Scene& scene, const FrameInputs& frame, Stage stage) {
  checkStage(frame, stage);
  const std::string name = stageName(stage);
  const long long pixels = static_cast<long long>(frame.width) * frame.height;
  RenderResult result;
  const auto start = std::chrono::steady_clock::now();
  switch (stage.kind) {
    case StageKind::Image: return renderer.render(scene, frame);
    case StageKind::Light: {
      result = renderer.render(scene, lightAlone(frame, stage.light));
      const FrameLight& light = frame.lights[stage.light];
      result.notes.insert(result.notes.begin(), name + ": light " + std::to_string(stage.light) + " (" +
                                                    std::string(kLightKindNames[static_cast<std::size_t>(light.light.kind)]) + ", shadows " +
                                                    (light.hasShadowMap ? "on" : "off") +
                                                    ") alone: no ambient light, no emission, no environment map");
      return result;
    }
    case StageKind::Overdraw: {
      const std::vector<std::uint32_t> counts = *renderer.render(scene, frame, {FrameOutput::FragmentCounts}).fragmentCounts;
      result.timings.push_back({"fragment counts", millisecondsSince(start)});
      const DepthComplexity complexity = depthComplexityOf(counts);
      result.image = depthComplexityImage(counts, frame.width, frame.height);
      char line[256];
      std::snprintf(line, sizeof line, "depth complexity: %llu fragments over %llu of %lld pixels, %.2f per covered pixel, at most %u",
                    static_cast<unsigned long long>(complexity.fragments), static_cast<unsigned long long>(complexity.covered), pixels,
                    complexity.meanPerCovered(), complexity.max);
      result.notes.push_back(line);
      return result;
    }
    case StageKind::Depth: {
      const std::vector<float> depth = *renderer.render(scene, frame, {FrameOutput::Depth}).depth;
      result.timings.push_back({"lit pass + depth read-back", millisecondsSince(start)});
      result.image = depthImage(depth, frame.width, frame.height);
      const DepthRange range = depthRangeOf(depth.data(), depth.size());
      result.notes.push_back("depth: " + rangeText(range) + " over " + std::to_string(range.drawn) + " of " + std::to_string(pixels) +
                             " pixels, near white to far dark grey; nothing drawn (z = 1) black");
      return result;
    }
    case StageKind::ShadowMap: {
      const ShadowMapTexels maps = *renderer.render(scene, frame, {FrameOutput::ShadowMaps}).shadowMaps;
      result.timings.push_back({"shadow maps + read-back", millisecondsSince(start)});
      int downsample = 1;
      result.image = shadowMapImage(maps, downsample);
      std::string layout;
      for (std::size_t l = 0; l < frame.lights.size(); ++l) {
        const FrameLight& light = frame.lights[l];
        if (!light.hasShadowMap) continue;
        layout += (layout.empty() ? "" : "; ") + std::string("light ") + std::to_string(l) + " (" +
                  std::string(kLightKindNames[static_cast<std::size_t>(light.light.kind)]) + ")";
        if (light.frustum.faceCount == 1) {
          layout += " layer " + std::to_string(light.shadowLayer);
        } else {
          layout += " layers " + std::to_string(light.shadowLayer) + "-" + std::to_string(light.shadowLayer + light.frustum.faceCount - 1) + " (";
          for (int f = 0; f < light.frustum.faceCount; ++f) {
            if (f > 0) layout += ' ';
            layout += kFaceNames[static_cast<std::size_t>(f)];
          }
          layout += ')';
        }
      }
      const DepthRange range = depthRangeOf(maps.texels.data(), maps.texels.size());
      std::string line = "shadow-map: " + countOf(static_cast<std::size_t>(maps.layers), "layer") + " of " + std::to_string(maps.size) + "x" +
                         std::to_string(maps.size) + " side by side, " + layout + "; each layer near white to far dark grey over its own range (all layers: " +
                         rangeText(range) + "), nothing drawn black; " + std::to_string(result.image.width()) + "x" +
                         std::to_string(result.image.height());
      if (downsample > 1)
        line += ", downsampled by " + std::to_string(downsample) + " (nearest) to stay within " + std::to_string(kMaxImageSide) + " pixels a side";
      result.notes.push_back(line);
      return result;
    }
    case StageKind::Normals: {
      const std::vector<glm::vec4> normals = *renderer.render(scene, frame, {FrameOutput::Normals}).normals;
      result.timings.push_back({"normals pass + read-back", millisecondsSince(start)});
      result.image = normalsImage(normals, frame.width, frame.height);
      std::size_t drawn = 0;
      for (const glm::vec4& n : normals) drawn += n.w != 0.0f ? 1 : 0;
      const char* which = frame.shading == ShadingMode::Flat      ? "the triangle's geometric normal"
                          : frame.shading == ShadingMode::Gouraud ? "the interpolated vertex normal"
                                                                  : "the interpolated vertex normal after normal textures and the bump map";
      result.notes.push_back("normals: RGB = (N + 1)/2 of world-space N over " + std::to_string(drawn) + " of " + std::to_string(pixels) + " pixels (" +
                             std::string(kShadingModeNames[static_cast<std::size_t>(frame.shading)]) + ": " + which +
                             ", negated on a back face), black where no opaque triangle is kept");
      return result;
    }
    case StageKind::Count: break;
  }
  throw Error("--output-stage " + name + ": not a stage");
}

}  // namespace facet
