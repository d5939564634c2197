#pragma once
// Volume readers (renderer/PIPELINE.md, "Volume data"). Each
// throws facet::Error with one line naming the file and the problem (a
// truncated file, dimensions that do not match the data, an unsupported
// sample type), and prices the samples against kSceneMemoryBudget before
// allocating them.
#include <string>

#include "scene/volume.h"
#include "vocabulary/limits.h"

namespace facet {

// "builtin:marschner-lobb" (at `resolution`³ samples), a NRRD file (.nrrd,
// .nhdr, read by teem), or a NIfTI-1 file (.nii, .nii.gz, read by nifti2).
Volume loadVolume(const std::string& path, int resolution);

// NRRD: scalar 8- and 16-bit integers (signed or not) and 32-bit float, 3
// axes, spacing from the header (1 where it gives none).
Volume readNrrd(const std::string& path);

// NIfTI-1: scalar 8- and 16-bit integers and 32-bit float (scl_slope and
// scl_inter applied when the slope is set), 3 dimensions (or 4 with one
// volume), spacing from pixdim.
Volume readNifti(const std::string& path);

// Marschner and Lobb's test signal (1994) on [-1, 1]³ sampled at
// resolution³ points (spacing 2/(resolution − 1)):
//   ρ(x, y, z) = (1 − sin(πz/2) + α(1 + ρ_r(√(x² + y²)))) / (2(1 + α)),
//   ρ_r(r) = cos(2π f_M cos(πr/2)), with f_M = 6 and α = 0.25;
// values in [0, 1], the iso-surface of interest at 0.5.
Volume makeMarschnerLobb(int resolution);
float marschnerLobb(float x, float y, float z);  // ρ at one point

}  // namespace facet
