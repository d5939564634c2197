#include "pipeline/shadow_pass_key.h"

#include <cstring>
#include <type_traits>

namespace facet {
namespace {

// Calls bytes(pointer, size) for each value pass 1 reads, in a fixed order.
// Floats compare by their bits, so a key never calls two different frames
// equal (-0 and +0 differ, which at worst redraws a map that had not changed).
template <class Bytes>
void visitShadowInputs(const FrameInputs& frame, Bytes&& bytes) {
  const auto add = [&](const auto& value) {
    static_assert(std::is_trivially_copyable_v<std::remove_cvref_t<decltype(value)>>);
    bytes(&value, sizeof value);
  };
  add(frame.shadowLayerCount);
  add(frame.shadows.mapSize);
  for (const FrameLight& light : frame.lights) {
    add(light.hasShadowMap);
    if (!light.hasShadowMap) continue;
    add(light.shadowLayer);
    add(light.frustum.faceCount);
    for (int face = 0; face < light.frustum.faceCount; ++face) add(light.frustum.clipFromWorld[static_cast<std::size_t>(face)]);
  }
  for (const FrameInstance& instance : frame.instances) {
    add(instance.mesh);
    add(instance.material);
    add(instance.worldFromModel);
  }
  for (const CourseMaterial& m : frame.materials) {
    add(m.castsShadow);
    add(m.masked);
    add(m.blended);
    add(m.alphaCutoff);
    add(m.baseAlpha);
    add(m.baseColorTexture);
    add(m.baseColorSampler.mag);
    add(m.baseColorSampler.min);
    add(m.baseColorSampler.wrapS);
    add(m.baseColorSampler.wrapT);
    add(m.baseColorSet);
    add(m.uvRow0);
    add(m.uvRow1);
  }
}

}  // namespace

ShadowPassKey::ShadowPassKey(const Scene& scene, const FrameInputs& frame) : scene_(scene.identity.token()) {
  visitShadowInputs(frame, [&](const void* value, std::size_t size) { inputs_.append(static_cast<const char*>(value), size); });
}

// Compared in place, value by value: a frame that keeps its maps allocates nothing.
bool ShadowPassKey::matches(const Scene& scene, const FrameInputs& frame) const {
  if (!scene.identity.is(scene_)) return false;
  std::size_t at = 0;
  bool same = true;
  visitShadowInputs(frame, [&](const void* value, std::size_t size) {
    same = same && at + size <= inputs_.size() && std::memcmp(inputs_.data() + at, value, size) == 0;
    at += size;
  });
  return same && at == inputs_.size();
}

std::string shadowPassName(const FrameInputs& frame, bool kept) {
  return "shadow pass (" + std::to_string(frame.shadowLayerCount) + (frame.shadowLayerCount == 1 ? " map" : " maps") + (kept ? " kept)" : ")");
}

}  // namespace facet
