#pragma once
// The lines `facet render` prints around a frame's passes, which are not the
// frame's own: what the command costs besides drawing. One copy for the
// command that prints them and for the readers that leave them out of a
// frame (viewer/orbit_bench.cpp).

namespace facet {

inline constexpr char kSceneInputsLine[] = "scene and frame inputs";
inline constexpr char kRendererStartupLine[] = "renderer start-up";     // cpu, ray, reference
inline constexpr char kGlStartupLine[] = "context and driver start-up";  // gl
inline constexpr char kPngWriteLine[] = "PNG encode and write";
inline constexpr char kCommandTotalLine[] = "total (command)";

}  // namespace facet
