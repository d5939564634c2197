#pragma once
// Every limit and budget of facet, each written once: the largest input it
// reads and the most work or memory one request may ask for. The settings'
// field table, the command line, the loaders, the frame checks and the
// backends read them here; a limit that must equal another is written as it.
#include <cstddef>
#include <cstdint>

namespace facet {

// [SECTION] Images and frames
inline constexpr int kMaxImageSide = 16384;       // pixels, each side (llvmpipe's largest render target)
inline constexpr int kMaxTextureSide = kMaxImageSide;  // a glTF texture's width or height (llvmpipe's largest texture)
inline constexpr int kMinShadowMapSize = 16;      // S
inline constexpr int kMaxShadowMapSize = 8192;    // S
inline constexpr int kMaxPcfRadius = 8;           // r
inline constexpr std::size_t kMaxLights = 8;      // lights a frame shades; a scene's others are dropped with a warning
inline constexpr int kMaxSamplesPerSide = 4;      // anti-aliasing's samples: 1, 4, 9 or 16
// Area-weighted averaging: more cells than this in one pixel is refused: the
// scene is too fine for the image size (each cell is shaded once per surface it holds).
inline constexpr std::size_t kMaxAreaCells = 4096;
// Vertices a frame draws over all its instances: the CPU backend refers to
// them with 31 bits (the top bit marks a vertex the clipper made).
inline constexpr std::size_t kMaxFrameVertices = std::size_t{1} << 31;
inline constexpr int kMaxDisplacementSubdivisions = 6;  // each triangle split into 4^k

// [SECTION] Memory
// Priced before anything is allocated (scene/memory_budget.h), so that a
// small file cannot take gigabytes. The scene budget holds what the glTF
// loader keeps of a scene: vertices, normals, texture coordinates, indices
// and decoded textures (from each image's header, before decoding). The
// frame budget holds what a frame works in: the vertex and triangle buffers
// of every instance (the CPU backend's, the larger) and the shadow maps (S²
// floats per face, six faces per point light; 8 point lights at the default
// S = 2048 take 768 MiB, so the defaults fit). A file or frame that needs
// more is refused with a line naming what needs it.
inline constexpr std::uint64_t kSceneMemoryBudget = std::uint64_t{1} << 30;   // bytes
inline constexpr std::uint64_t kFrameMemoryBudget = std::uint64_t{1} << 30;   // bytes

// [SECTION] Scenes
// The largest world coordinate a scene may place a vertex, light or camera
// at: the pipeline squares distances in float (the projection's N·F, the
// attenuation's d²), which overflows past 1.8e19. Beyond it the loader
// drops what it placed there, with a warning.
inline constexpr float kMaxWorldCoordinate = 1e18f;
// glTF: beyond these a file is refused with a message instead of a huge
// allocation or a deep recursion.
inline constexpr std::uint64_t kMaxGltfFileBytes = 1ull << 30;  // .gltf/.glb and each external buffer
inline constexpr int kMaxGltfJsonDepth = 64;                     // glTF needs about 8
inline constexpr int kMaxGltfNodeDepth = 256;                    // node hierarchy
inline constexpr std::uint64_t kMaxAccessorCount = 1ull << 28;   // elements of one accessor
// PNG: checked from the header before anything is decoded: the largest image
// facet renders. Each side at most kMaxImageSide, and at most
// kMaxPngDecodedBytes for the RGBA samples at the file's bit depth (4 bytes
// a pixel, 8 for 16-bit files), the largest buffer the decoder builds: a
// 16384x16384 8-bit PNG fits, a 16-bit one up to 2^27 pixels.
inline constexpr std::uint64_t kMaxPngDecodedBytes = 4ull * kMaxImageSide * kMaxImageSide;  // 1 GiB
inline constexpr std::uint64_t kMaxPngFileBytes = 512ull << 20;
// A file name: Linux's PATH_MAX, for a name a setting holds and for the
// paths the interrupt handler removes.
inline constexpr std::size_t kMaxPathBytes = 4096;
inline constexpr std::size_t kMaxSettingsPathBytes = kMaxPathBytes;

// [SECTION] Settings and jobs
// The deepest valid settings nest 4 levels (lights, a light, its position);
// a few more leave room for a helpful "expected ..." message.
inline constexpr std::size_t kMaxSettingsDepth = 8;
inline constexpr std::uint64_t kMaxSettingsFileBytes = 16ull << 20;  // a settings file is a few kB
// A job file is a list of short lines; this bounds a mistaken huge file.
inline constexpr std::uint64_t kMaxJobFileBytes = 64ull << 20;
// A job nests a settings object, whose deepest keys sit 4 levels down.
inline constexpr std::size_t kMaxJobDepth = 10;
// A file's bytes count toward a batch job's inputs hash; a glTF or a map is far below this.
inline constexpr std::uint64_t kMaxHashedFileBytes = 2ull << 30;
// A JUnit report that batch --merge joins: a few hundred bytes a job.
inline constexpr std::uint64_t kMaxReportFileBytes = 1ull << 30;
// What the command line may ask for at once: worker threads of a frame
// (render --threads, bench --threads) and batch jobs (batch --jobs).
inline constexpr int kMaxThreads = 256;
inline constexpr int kMaxParallelJobs = 256;
// The viewer's scripted runs: frames view --screenshot draws first, or view --bench-orbit times.
inline constexpr int kMaxViewerFrames = 100000;

// [SECTION] Ray tracing
inline constexpr int kMaxRayDepth = 16;     // levels of the ray tree; the tree doubles with each
inline constexpr int kMaxRaySamples = 4096; // paths per pixel
// Motion blur places the scene at most this many times across the shutter (a BVH each).
inline constexpr int kMaxShutterSlices = 16;
// The most primitives (triangles and spheres) one BVH holds: indices, node
// offsets (at most 2·count - 1 nodes) and slots must fit its 32-bit fields.
inline constexpr std::size_t kMaxTracedPrimitives = (std::size_t{1} << 31) - 1;

// [SECTION] Particles and volumes
// The emitters of the settings, particles.N.* (the scene's, from glTF node extras, come on top).
inline constexpr std::size_t kMaxEmitters = 16;
inline constexpr std::uint64_t kMaxParticles = 4'000'000;  // alive at once, over every emitter of a frame
inline constexpr double kMaxStepsPerParticle = 1e7;        // lifetime / step: a particle's cost is bounded
// The integration steps of one emitter's frame, Σ age / step over its live
// particles: the product of the two limits above would be hours of work.
inline constexpr double kMaxParticleSteps = 1e10;
// The texels the shadow pass writes for sprites (splats, particles), Σ over
// sprites, shadowed lights and faces of the map area each quad covers: every
// one is a masked fragment in both backends, so this is the pass's time.
// nibabel's MRI splatted at the defaults takes 1.44e8 (docs/performance.md).
inline constexpr double kMaxShadowSpriteTexels = 5e8;
// A volume's box, (samples - 1)·spacing along each axis in the file's units:
// past this its corners, squared in ray and camera arithmetic, leave float's
// range (1e9² is 1e18, far below 3.4e38).
inline constexpr double kMaxVolumeExtent = 1e9;
// The largest spacing over the smallest: the ray caster steps by a share of
// the smallest, so a ray along the widest axis takes this many times more
// steps than the samples it crosses (real scans stay under 20).
inline constexpr double kMaxVolumeSpacingRatio = 1000.0;
inline constexpr int kMinMarschnerLobbResolution = 2;      // builtin:marschner-lobb's samples along each axis
inline constexpr int kMaxMarschnerLobbResolution = 512;
// teem grows its line buffer to fit any line, and a header has no length
// field: a NRRD header is looked at first and refused past this (real ones are < 4 kB).
inline constexpr std::size_t kMaxNrrdHeaderBytes = std::size_t{1} << 20;

}  // namespace facet
