#pragma once
// The words every layer shares for the pipeline's choices: each enum of the
// settings with the names the settings, the command line and the viewer
// show for it (a table indexed by the enum, checked against its Count).
// Value types only: no layer below the settings needs more of them.
#include <array>
#include <string_view>

namespace facet {

enum class ProjectionKind { Perspective, Parallel, Count };
enum class ShadingMode { Flat, Gouraud, Phong, Pbr, Count };
// Phong and pbr interpolate the world position and normal and light each pixel.
constexpr bool interpolatesNormals(ShadingMode mode) { return mode == ShadingMode::Phong || mode == ShadingMode::Pbr; }
inline constexpr std::array<std::string_view, static_cast<int>(ShadingMode::Count)> kShadingModeNames = {"flat", "gouraud", "phong", "pbr"};

enum class SpecularModel { Phong, BlinnPhong, Count };
inline constexpr std::array<std::string_view, static_cast<int>(SpecularModel::Count)> kSpecularModelNames = {"phong", "blinn-phong"};

inline constexpr std::array<std::string_view, static_cast<int>(ProjectionKind::Count)> kProjectionKindNames = {"perspective", "parallel"};

// auto: the scene's own (its first camera / its lights), or, when it has none,
// fitted to the scene's bounding sphere. manual: exactly the values written here.
enum class Source { Auto, Manual, Count };
inline constexpr std::array<std::string_view, static_cast<int>(Source::Count)> kSourceNames = {"auto", "manual"};

// auto: each texture's glTF sampler (REPEAT, bilinear and trilinear where
// the file gives none); nearest, bilinear, trilinear: that filter for every
// texture, magnified and minified (wraps stay the sampler's).
enum class TextureFilter { Auto, Nearest, Bilinear, Trilinear, Count };
inline constexpr std::array<std::string_view, static_cast<int>(TextureFilter::Count)> kTextureFilterNames = {"auto", "nearest", "bilinear",
                                                                                                            "trilinear"};

// The course's procedural mapping (renderer/PIPELINE.md, "Textures"): a
// pattern of the model-space surface point in place of every base colour texture.
enum class Procedural { None, Checker, Noise, Count };
inline constexpr std::array<std::string_view, static_cast<int>(Procedural::Count)> kProceduralNames = {"none", "checker", "noise"};

enum class FogMode { None, Linear, Exponential, Exponential2, Count };
inline constexpr std::array<std::string_view, static_cast<int>(FogMode::Count)> kFogModeNames = {"none", "linear", "exponential", "exponential2"};

// Hidden-surface removal (renderer/PIPELINE.md, "Hidden-surface
// removal"): the z-buffer; the painter's algorithm (triangles sorted by their
// farthest eye depth, drawn back to front with no depth buffer); or the
// scanline z-buffer (CPU backend: one row of depth at a time, the z-buffer's image).
enum class HiddenSurface { ZBuffer, Painter, Scanline, Count };
inline constexpr std::array<std::string_view, static_cast<int>(HiddenSurface::Count)> kHiddenSurfaceNames = {"zbuffer", "painter", "scanline"};

// Transparency (renderer/PIPELINE.md, "Transparency"): the
// course's two blending equations, straight
//   C_o = (C_f α_f + C_b α_b (1 − α_f)) / α_o,  α_o = α_f + α_b (1 − α_f)
// and premultiplied C_o = C_f + C_b (1 − α_f) (the colour buffer holds C·α);
// blended triangles are drawn after the opaque ones, back to front by object
// or by triangle (the painter's key), depth-tested without depth writes.
enum class Blending { Straight, Premultiplied, Count };
inline constexpr std::array<std::string_view, static_cast<int>(Blending::Count)> kBlendingNames = {"straight", "premultiplied"};
enum class TransparencySort { Object, Triangle, Count };
inline constexpr std::array<std::string_view, static_cast<int>(TransparencySort::Count)> kTransparencySortNames = {"object", "triangle"};

// Anti-aliasing (renderer/PIPELINE.md, "Anti-aliasing"): the
// course's supersampling, `samples` = s² sub-pixel positions per pixel on an
// s × s ordered grid, or one jittered position in each grid cell from a
// seeded generator; every sample is a full pass, box-filtered in linear light.
// `area` (the CPU backend's) is the course's area-weighted averaging instead:
// exact coverage of each pixel by each polygon, `samples` playing no part.
enum class SamplePattern { Grid, Jittered, Area, Count };
inline constexpr std::array<std::string_view, static_cast<int>(SamplePattern::Count)> kSamplePatternNames = {"grid", "jittered", "area"};

// Volume rendering (renderer/PIPELINE.md, "Volume rendering"): a scalar volume
// placed in the scene, drawn by the course's v-buffer ray casting,
// splatting, or marching cubes' iso-surface.
enum class VolumeMode { Raycast, Splat, Isosurface, Count };
inline constexpr std::array<std::string_view, static_cast<int>(VolumeMode::Count)> kVolumeModeNames = {"raycast", "splat", "isosurface"};

}  // namespace facet
