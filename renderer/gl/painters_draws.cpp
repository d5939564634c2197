#include "gl/painters_draws.h"

#include <algorithm>
#include <cstdint>
#include <string>

#include "common/error.h"

namespace facet::gl {

void PaintersDraws::prepare(const GlFunctions& gl, const Scene& scene, const FrameInputs& frame, const std::vector<std::uint32_t>& order) {
  const std::vector<std::size_t> firstTriangle = firstTriangles(scene, frame);
  std::vector<std::uint32_t> indices, triangles;
  indices.reserve(3 * order.size());
  runs_.clear();
  for (std::size_t position = 0; position < order.size(); ++position) {
    const std::uint32_t triangle = order[position];
    if (triangle >= firstTriangle.back())
      throw Error("the frame's draw order names triangle " + std::to_string(triangle) + "; the frame has " + std::to_string(firstTriangle.back()));
    const std::size_t instance = instanceOfTriangle(firstTriangle, triangle);
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(frame.instances[instance].mesh)];
    const std::size_t t = 3 * (triangle - firstTriangle[instance]);
    indices.insert(indices.end(), {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]});
    triangles.push_back(triangle);
    if (runs_.empty() || runs_.back().instance != instance) runs_.push_back({instance, static_cast<GLsizei>(position), 0});
    ++runs_.back().count;
  }
  // Storage is immutable: new buffers each frame (at least one element, so that something valid is bound).
  const auto upload = [&](const std::vector<std::uint32_t>& data) {
    GlObject buffer = createBuffer(gl);
    const std::uint32_t none = 0;
    gl.NamedBufferStorage(buffer.id(), static_cast<GLsizeiptr>(std::max<std::size_t>(data.size(), 1) * sizeof(std::uint32_t)),
                            data.empty() ? &none : data.data(), 0);
    return buffer;
  };
  indices_ = upload(indices);
  triangles_ = upload(triangles);
  for (PainterRun& run : runs_) run.indices = indices_.id();
}

}  // namespace facet::gl
