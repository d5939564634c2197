#pragma once
// Pass 2's lines and points: every instance's segments, then its points,
// drawn after all triangles, unlit (O_d times COLOR_0), through the
// z-buffer (LESS) and into the image (renderer/PIPELINE.md, "Rasterization",
// "Lines and points"). The fast renderer draws them tile by tile, the
// reference over the whole image; both set them up here.
#include <vector>

#include <glm/vec3.hpp>

#include "cpu/clipper.h"
#include "cpu/frame_buffers.h"
#include "cpu/line_raster.h"
#include "cpu/tile_pixels.h"
#include "image/color_buffer.h"
#include "pipeline/frame_inputs.h"
#include "scene/scene.h"

namespace facet::cpu {

// Appends segment a → b: clip vertices with their colour (RGB) as varyings
// 0-2, and their window vertices. Clipped as clipSegment does; nothing when
// a coordinate is not finite or nothing is left.
void addSegment(const ClipVertex& a, const ClipVertex& b, const WindowVertex& windowA, const WindowVertex& windowB, const FrameInputs& frame,
                glm::vec3 baseColor, std::vector<DrawnLine>& out);

// Appends a point; nothing when it is outside the view volume (draw's clip_point) or not finite.
void addPoint(const ClipVertex& v, const WindowVertex& window, const FrameInputs& frame, glm::vec3 baseColor, std::vector<DrawnLine>& out);

// The segments and points of every instance from the lit pass's packed
// window vertices (colour at varying `colorVarying`), in drawing order.
void setUpLines(const Scene& scene, const FrameInputs& frame, const PassVertices& vertices, int colorVarying, std::vector<DrawnLine>& out);

// Draws the lines that cover pixels of rectangle `r` into the colour buffer, against
// the z-buffer `depth` (pixel (r.x0, r.y0) first, `depthStride` per row);
// null: the painter's algorithm, no depth test, each fragment over the last.
void drawLines(const FrameInputs& frame, const std::vector<DrawnLine>& lines, const TileRect& r, float* depth, int depthStride, const TilePixels& color);

}  // namespace facet::cpu
