// libFuzzer target: the CPU rasterizer, its area-weighted averaging and the
// ray tracer on arbitrary triangles and settings.
// The bytes become a few vertices (any float: NaN, infinities, huge), index
// triples, a camera, a light and the shading knobs; the frame is rendered
// small. It must end in an image or a facet::Error, never a crash, an
// out-of-bounds access or undefined behaviour (run under ASan and UBSan).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "common/error.h"
#include "cpu/cpu_renderer.h"
#include "ray/ray_renderer.h"
#include "pipeline/frame_inputs.h"

namespace {

class Reader {
 public:
  Reader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t byte() { return at_ < size_ ? data_[at_++] : 0; }
  float number() {
    float f = 0;
    if (at_ + 4 <= size_) std::memcpy(&f, data_ + at_, 4);
    at_ += 4;
    return f;
  }
  glm::vec3 vec3() {
    const float x = number(), y = number();
    return {x, y, number()};
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_, at_ = 0;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Reader in(data, size);
  facet::RenderSettings s;
  s.width = 1 + in.byte() % 48;
  s.height = 1 + in.byte() % 48;
  const std::uint8_t knobs = in.byte();
  s.shading = static_cast<facet::ShadingMode>(knobs % 3);
  s.specular = static_cast<facet::SpecularModel>((knobs >> 2) & 1);
  s.cullBackFaces = (knobs >> 3) & 1;
  s.shadows.enabled = (knobs >> 4) & 1;
  s.shadows.mapSize = 16 + in.byte() % 48;
  s.shadows.pcfRadius = in.byte() % 3;
  s.camera.source = facet::Source::Manual;
  s.camera.projection = static_cast<facet::ProjectionKind>((knobs >> 5) & 1);
  s.camera.eye = in.vec3();
  s.camera.reference = in.vec3();
  s.camera.near = 0.01f + static_cast<float>(in.byte()) / 16.0f;
  s.camera.far = s.camera.near + 0.01f + static_cast<float>(in.byte());
  s.lightSource = facet::Source::Manual;
  facet::Light light;
  light.kind = static_cast<facet::LightKind>(in.byte() % 3);
  light.position = in.vec3();
  light.direction = in.vec3();
  light.spotCutoffDeg = 1.0f + static_cast<float>(in.byte() % 88);
  s.lights = {light};

  facet::Scene scene;
  facet::Mesh mesh;
  const int vertices = 3 + in.byte() % 6;
  for (int v = 0; v < vertices; ++v) {
    mesh.positions.push_back(in.vec3());
    mesh.normals.push_back(in.vec3());
    mesh.texcoords.push_back({in.number(), in.number()});
  }
  const int triangles = 1 + in.byte() % 6;
  for (int t = 0; t < 3 * triangles; ++t) mesh.indices.push_back(in.byte() % static_cast<std::uint32_t>(vertices));
  scene.meshes.push_back(mesh);
  scene.instances.push_back({0, glm::mat4(1.0f)});
  facet::Material material;
  material.metallic = static_cast<float>(in.byte()) / 255.0f;
  material.roughness = static_cast<float>(in.byte()) / 255.0f;
  // The ray tracer's knobs from what follows (0, the defaults, past the end).
  const std::uint8_t rays = in.byte();
  material.transmission = static_cast<float>(rays & 3) / 3.0f;
  material.ior = 0.5f + static_cast<float>(in.byte()) / 64.0f;
  scene.materials.push_back(material);
  scene.meshes[0].material = 0;
  s.ray.depth = 1 + (rays >> 2) % 6;
  s.ray.samples = 1 + ((rays >> 5) & 3);
  s.ray.gloss = s.ray.translucency = (rays >> 7) & 1;
  s.camera.aperture = static_cast<float>(in.byte()) / 64.0f;
  s.lights[0].radius = static_cast<float>(in.byte()) / 32.0f;

  try {
    const facet::FrameInputs frame = facet::buildFrameInputs(scene, s);
    (void)facet::makeCpuRenderer(1)->render(scene, frame);
    facet::FrameInputs area = frame;
    area.areaAveraged = true;
    (void)facet::makeCpuRenderer(1)->render(scene, area);
  } catch (const facet::Error&) {
  }
  try {
    const facet::FrameInputs frame = facet::buildFrameInputs(scene, s);
    (void)facet::makeRayRenderer(1)->render(scene, frame);
  } catch (const facet::Error&) {
  }
  return 0;
}
