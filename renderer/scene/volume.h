#pragma once
// A scalar volume on a regular grid (the course's voxels), as every reader
// produces it and the three volume renderers (ray casting, splatting,
// marching cubes) consume it (renderer/PIPELINE.md, "Volume rendering").
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace facet {

struct Volume {
  std::string source;             // the file it was read from, or "builtin:marschner-lobb"
  glm::ivec3 size{0};             // samples along x, y, z, each >= 2
  glm::vec3 spacing{1.0f};        // distance between neighbouring samples along x, y, z (the file's units), each > 0
  std::vector<float> values;      // size.x·size.y·size.z samples, x fastest, then y, then z
  float minValue = 0.0f, maxValue = 0.0f;  // over values (finite ones)

  std::size_t index(int x, int y, int z) const {
    return (static_cast<std::size_t>(z) * static_cast<std::size_t>(size.y) + static_cast<std::size_t>(y)) * static_cast<std::size_t>(size.x) +
           static_cast<std::size_t>(x);
  }
  float at(int x, int y, int z) const { return values[index(x, y, z)]; }
  std::size_t sampleCount() const {
    return static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y) * static_cast<std::size_t>(size.z);
  }
  // The model-space box the samples span: sample (i, j, k) sits at (i, j, k)·spacing, so the box is [0, extent].
  glm::vec3 extent() const { return glm::vec3(size - 1) * spacing; }
  bool empty() const { return values.empty(); }
};

// What a volume's name says it is: builtin:marschner-lobb, or a NRRD (.nrrd,
// .nhdr) or NIfTI-1 (.nii, .nii.gz) file by its extension, in any case
// (HEAD.NII is as much NIfTI as head.nii); the readers are volume/load_volume.h's.
enum class VolumeFormat { None, MarschnerLobb, Nrrd, Nifti };
VolumeFormat volumeFormatOf(const std::string& path);
inline bool isVolumeName(const std::string& path) { return volumeFormatOf(path) != VolumeFormat::None; }

// The course's trilinear interpolation of the 8 samples around the
// model-space point p (clamped to the box): along x, then y, then z, each
// lerp a + t·(b − a) rounded once.
float trilinear(const Volume& volume, glm::vec3 p);

// The gradient at sample (x, y, z) by central differences (one-sided at the
// border), per model-space unit.
glm::vec3 sampleGradient(const Volume& volume, int x, int y, int z);

// Sets minValue and maxValue from values (0 and 0 when none is finite).
void updateRange(Volume& volume);

}  // namespace facet
