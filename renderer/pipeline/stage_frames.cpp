#include "pipeline/stage_frames.h"

#include <string>

#include "common/error.h"

namespace facet {

FrameInputs lightAlone(const FrameInputs& frame, std::size_t light) {
  if (light >= frame.lights.size())
    throw Error("light " + std::to_string(light) + ": the frame has " + std::to_string(frame.lights.size()) +
                (frame.lights.size() == 1 ? " light" : " lights"));
  FrameInputs alone = frame;
  FrameLight kept = frame.lights[light];
  alone.shadowLayerCount = 0;
  if (kept.hasShadowMap) {  // its faces become the first layers, as buildFrameInputs lays out a one-light frame
    kept.shadowLayer = 0;
    alone.shadowLayerCount = kept.frustum.faceCount;
  }
  alone.lights = {kept};
  alone.ambient = 0.0f;
  for (CourseMaterial& material : alone.materials) {
    material.emissive = glm::vec3(0.0f);
    material.emissiveMap.texture = -1;
    if (material.unlit) material.baseColor = glm::vec3(0.0f);  // O_d; the alpha (baseAlpha) stays
  }
  alone.environment.map = nullptr;
  alone.environment.reflectivity = 0.0f;
  alone.environment.background = false;
  return alone;
}

FrameInputs normalsFrame(const FrameInputs& frame) {
  FrameInputs normals = frame;
  normals.samples.clear();
  normals.areaAveraged = false;
  normals.lights.clear();
  normals.shadowLayerCount = 0;
  if (normals.shading == ShadingMode::Gouraud) {
    normals.shading = ShadingMode::Phong;
    normals.bump.map = nullptr;
    for (CourseMaterial& material : normals.materials) material.normalMap.texture = -1;
  }
  return normals;
}

}  // namespace facet
