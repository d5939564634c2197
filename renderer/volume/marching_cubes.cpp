// Marching cubes: the iso-surface of a volume as a welded, oriented triangle mesh, slab by slab.
#include "volume/marching_cubes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <exception>
#include <limits>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "common/error.h"

namespace facet {
namespace {

// ---------------------------------------------------------------------------
// The cell's topology. Corner c sits at sample offset (c & 1, c >> 1 & 1,
// c >> 2 & 1), so bit c of a case is corner c's inside flag. Edge e runs
// along axis a = e / 4 from the corner with bit a clear to the one with it
// set; its two other coordinates are the bits of e % 4, along axis a + 1
// (bit 0) and axis a + 2 (bit 1), modulo 3.

constexpr int kEdges = 12, kFaces = 6, kCases = 256;

constexpr int edgeCorner(int edge, int end) {
  const int a = edge / 4, w = edge % 4, u = (a + 1) % 3, v = (a + 2) % 3;
  return (end << a) | ((w & 1) << u) | ((w >> 1) << v);
}

// The edge between two corners that differ in one coordinate.
constexpr int edgeBetween(int c0, int c1) {
  const int along = c0 ^ c1;
  const int a = along == 1 ? 0 : along == 2 ? 1 : 2, u = (a + 1) % 3, v = (a + 2) % 3;
  return 4 * a + ((c0 >> u) & 1) + 2 * ((c0 >> v) & 1);
}

// Face f is the cell's side where coordinate f / 2 is f % 2; its corners in
// counter-clockwise order seen from outside the cell.
constexpr std::array<int, 4> faceCorners(int face) {
  const int a = face / 2, side = face % 2, u = (a + 1) % 3, v = (a + 2) % 3;
  // (0,0) (1,0) (1,1) (0,1) in (u, v) turns counter-clockwise about +a, as u × v = a;
  // the side facing −a takes them in reverse.
  constexpr int uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::array<int, 4> corners{};
  for (int i = 0; i < 4; ++i) {
    const int k = side == 1 ? i : (4 - i) % 4;
    corners[static_cast<std::size_t>(i)] = (side << a) | (uv[k][0] << u) | (uv[k][1] << v);
  }
  return corners;
}

constexpr bool onFace(int edge, int face) {
  const std::array<int, 4> q = faceCorners(face);
  for (int i = 0; i < 4; ++i)
    if (edgeBetween(q[static_cast<std::size_t>(i)], q[static_cast<std::size_t>((i + 1) % 4)]) == edge) return true;
  return false;
}

constexpr bool shareFace(int e0, int e1) {
  for (int f = 0; f < kFaces; ++f)
    if (onFace(e0, f) && onFace(e1, f)) return true;
  return false;
}

// ---------------------------------------------------------------------------
// The case table, derived from the topology above rather than copied.
//
// On each face the crossed edges pair up into segments, each running from
// the edge where a counter-clockwise walk around the face (seen from
// outside the cell) enters a run of inside corners to the edge where it
// leaves that run, so the inside lies to the segment's right seen from
// outside. Each crossed edge of the cell is entered on one of its two faces
// and left on the other, so the segments join into closed polygons, one per
// sheet of surface in the cell, each counter-clockwise seen from the
// outside (lower values); a fan triangulates each.
//
// Ambiguous faces (inside corners on one diagonal, outside corners on the
// other) take the rule "separate the inside corners": each inside corner's
// run is that corner alone. The rule reads the face's four flags and
// nothing else, so the two cells sharing a face cut it by the same two
// segments and the surface has no holes. Lorensen and Cline's table of 15
// cases under complementary symmetry leaves holes: the complement of a
// case separates the outside corners instead, so a face shared by a cell
// with few inside corners and one with many can be cut two different ways.
// The asymptotic decider would follow the trilinear interpolant better,
// but needs the four values per face and per cell; a fixed rule keeps the
// whole decision in a 256-entry table.
//
// A fan must not draw a diagonal between two vertices of one ambiguous face:
// the neighbour across that face could draw the same diagonal, and the edge
// would then have four triangles. The fan's apex is the first polygon vertex
// whose diagonals avoid that; the table is built at compile time, and the
// build fails if a polygon had no such apex.

constexpr int kMaxCaseTriangles = 5;  // the most any case needs: buildCaseTable stops the build if not

struct CaseTable {
  std::array<std::uint8_t, kCases> triangleCount{};
  std::array<std::array<std::uint8_t, 3 * kMaxCaseTriangles>, kCases> edges{};  // three per triangle
};

constexpr CaseTable buildCaseTable() {
  CaseTable table{};
  for (int c = 0; c < kCases; ++c) {
    const auto inside = [c](int corner) { return ((c >> corner) & 1) != 0; };
    std::array<int, kEdges> next{};
    next.fill(-1);
    for (int f = 0; f < kFaces; ++f) {
      const std::array<int, 4> q = faceCorners(f);
      const auto at = [&q](int i) { return q[static_cast<std::size_t>((i + 4) % 4)]; };
      for (int i = 0; i < 4; ++i) {
        if (!inside(at(i)) || inside(at(i - 1))) continue;  // the walk enters a run at corner i
        int last = i;
        while (inside(at(last + 1))) ++last;  // ends: corner i − 1 is outside
        const int entered = edgeBetween(at(i - 1), at(i)), left = edgeBetween(at(last), at(last + 1));
        if (next[static_cast<std::size_t>(entered)] != -1) throw "an edge entered on two faces";
        next[static_cast<std::size_t>(entered)] = left;
      }
    }
    std::array<bool, kEdges> walked{};
    int count = 0;
    for (int start = 0; start < kEdges; ++start) {
      if (next[static_cast<std::size_t>(start)] < 0 || walked[static_cast<std::size_t>(start)]) continue;
      std::array<int, kEdges> polygon{};
      int n = 0;
      for (int e = start; !walked[static_cast<std::size_t>(e)]; e = next[static_cast<std::size_t>(e)]) {
        if (e < 0) throw "an edge left but never entered";
        walked[static_cast<std::size_t>(e)] = true;
        polygon[static_cast<std::size_t>(n++)] = e;
      }
      const auto vertex = [&polygon, n](int i) { return polygon[static_cast<std::size_t>(i % n)]; };
      int apex = -1;
      for (int a = 0; a < n && apex < 0; ++a) {
        bool clear = true;
        for (int d = 2; d <= n - 2; ++d) clear = clear && !shareFace(vertex(a), vertex(a + d));
        if (clear) apex = a;
      }
      if (apex < 0) throw "no fan apex avoids the ambiguous faces";
      for (int d = 1; d + 1 < n; ++d) {
        if (count == kMaxCaseTriangles) throw "more triangles than kMaxCaseTriangles";
        auto& out = table.edges[static_cast<std::size_t>(c)];
        out[static_cast<std::size_t>(3 * count)] = static_cast<std::uint8_t>(vertex(apex));
        out[static_cast<std::size_t>(3 * count + 1)] = static_cast<std::uint8_t>(vertex(apex + d));
        out[static_cast<std::size_t>(3 * count + 2)] = static_cast<std::uint8_t>(vertex(apex + d + 1));
        ++count;
      }
    }
    table.triangleCount[static_cast<std::size_t>(c)] = static_cast<std::uint8_t>(count);
  }
  return table;
}

constexpr CaseTable kCaseTable = buildCaseTable();

static_assert(kCaseTable.triangleCount[0] == 0 && kCaseTable.triangleCount[255] == 0);
static_assert(kCaseTable.triangleCount[1] == 1 && kCaseTable.triangleCount[254] == 1);
static_assert(kCaseTable.triangleCount[0b00001001] == 2, "two inside corners across a face stay apart");
static_assert(kCaseTable.triangleCount[0b11110110] == 4, "the complement joins its two outside corners: one hexagon");

// ---------------------------------------------------------------------------
// Extraction. Cells are processed a slab (two neighbouring slices) at a
// time; the vertex ids of a slice's crossed edges (along x and y) are kept
// for the two slices of the slab, those of the edges between them (along z)
// for the slab. Vertices are made in one fixed order: slice 0's x edges,
// its y edges, slab 0's z edges, slice 1's x edges, ... ; triangles in cell
// order (x fastest, then y, then z). Threads each take a range of slabs and
// number their vertices from 0; the ranges are concatenated in order, so
// the mesh is the same whatever the number of threads.

// The volume and iso value as the walk reads them, with the strides and edge counts of a slice.
struct Field {
  const Volume& volume;
  float iso;
  int nx, ny, nz;
  std::size_t strideY, strideZ;
  std::size_t xEdges, sliceEdges;  // per slice: (nx − 1)·ny along x, then nx·(ny − 1) along y

  Field(const Volume& v, float isoValue)
      : volume(v),
        iso(isoValue),
        nx(v.size.x),
        ny(v.size.y),
        nz(v.size.z),
        strideY(static_cast<std::size_t>(nx)),
        strideZ(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny)),
        xEdges(static_cast<std::size_t>(nx - 1) * static_cast<std::size_t>(ny)),
        sliceEdges(xEdges + static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny - 1)) {}

  float value(std::size_t index) const { return volume.values[index]; }
};

// The unit vector along v, or 0 where v has no direction (zero, or not
// finite). Tiny and huge vectors are scaled first, so that their squared
// length neither underflows nor overflows.
glm::vec3 direction(glm::vec3 v) {
  const float lengthSquared = glm::dot(v, v);
  if (lengthSquared > 1e-30f && lengthSquared < 1e30f) return v / std::sqrt(lengthSquared);
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return glm::vec3(0.0f);
  const float largest = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  if (largest == 0.0f) return glm::vec3(0.0f);
  return glm::normalize(v / largest);
}

// visit(i), in increasing i, for each i in [0, count) where a[i] and b[i]
// differ, comparing eight at a time: most of a slice is far from the surface.
template <typename Visit>
void forEachDifference(const std::uint8_t* a, const std::uint8_t* b, int count, const Visit& visit) {
  int i = 0;
  for (; i + 8 <= count; i += 8) {
    std::uint64_t wordA = 0, wordB = 0;
    std::memcpy(&wordA, a + i, 8);
    std::memcpy(&wordB, b + i, 8);
    if (wordA == wordB) continue;
    for (int m = i; m < i + 8; ++m)
      if (a[m] != b[m]) visit(m);
  }
  for (; i < count; ++i)
    if (a[i] != b[i]) visit(i);
}

// One range of slabs' share of the mesh.
struct Part {
  std::vector<glm::vec3> positions, normals;
  std::vector<std::uint32_t> indices;  // into positions, except the borrowed entries
  // Entries of indices that name an edge of the range's top slice when the
  // next range makes that slice's vertices: they hold the edge's number in
  // the slice until the parts are joined.
  std::vector<std::size_t> borrowed;
  std::vector<std::uint32_t> firstSliceIds;  // the ids of the range's first slice's edges, for the range below
  bool unsetNormals = false;
};

class SlabWalker {
 public:
  SlabWalker(const Field& field, Part& part) : field_(field), part_(part) {}

  // Slabs [k0, k1); the vertices of slice k1 too when ownsTop.
  void run(int k0, int k1, bool ownsTop) {
    const Field& f = field_;
    const std::size_t samples = f.strideZ, quads = static_cast<std::size_t>(f.nx - 1) * static_cast<std::size_t>(f.ny - 1);
    std::vector<std::uint8_t> insideBottom(samples), insideTop(samples), quadBottom(quads), quadTop(quads);
    std::vector<std::uint32_t> bottom(f.sliceEdges), top(f.sliceEdges), between(samples);
    // Room for a surface crossing each slice a few times (about two
    // triangles per vertex on a closed surface); the arrays grow past it if they must.
    const std::size_t guess = 2 * (static_cast<std::size_t>(f.nx) + static_cast<std::size_t>(f.ny)) * static_cast<std::size_t>(k1 - k0);
    part_.positions.reserve(guess);
    part_.normals.reserve(guess);
    part_.indices.reserve(6 * guess);

    classify(k0, insideBottom, quadBottom);
    sliceVertices(k0, insideBottom, bottom);
    part_.firstSliceIds = bottom;
    for (int k = k0; k < k1; ++k) {
      classify(k + 1, insideTop, quadTop);
      betweenVertices(k, insideBottom, insideTop, between);
      const bool borrowing = k + 1 == k1 && !ownsTop;
      if (borrowing)
        for (std::size_t s = 0; s < f.sliceEdges; ++s) top[s] = static_cast<std::uint32_t>(s);
      else
        sliceVertices(k + 1, insideTop, top);
      cells(quadBottom, quadTop, bottom, top, between, borrowing);
      std::swap(insideBottom, insideTop);
      std::swap(quadBottom, quadTop);
      std::swap(bottom, top);
    }
  }

 private:
  // inside: value ≥ iso per sample of slice k; quad: the 4 inside bits of
  // each square of the slice, as the low (or high) half of a case.
  void classify(int k, std::vector<std::uint8_t>& inside, std::vector<std::uint8_t>& quad) const {
    // Locals, as a store through a uint8_t pointer may alias anything (and would keep the loops from vectorizing).
    const float iso = field_.iso;
    const int nx = field_.nx, ny = field_.ny;
    const std::size_t samples = field_.strideZ;
    const float* slice = field_.volume.values.data() + static_cast<std::size_t>(k) * samples;
    std::uint8_t* flags = inside.data();
    for (std::size_t s = 0; s < samples; ++s) flags[s] = slice[s] >= iso;
    std::uint8_t* q = quad.data();
    for (int j = 0; j + 1 < ny; ++j) {
      const std::uint8_t* row = flags + static_cast<std::size_t>(j) * static_cast<std::size_t>(nx);
      const std::uint8_t* above = row + nx;
      for (int i = 0; i + 1 < nx; ++i)
        q[i] = static_cast<std::uint8_t>(row[i] | row[i + 1] << 1 | above[i] << 2 | above[i + 1] << 3);
      q += nx - 1;
    }
  }

  void sliceVertices(int k, const std::vector<std::uint8_t>& inside, std::vector<std::uint32_t>& ids) {
    const int nx = field_.nx, ny = field_.ny;
    for (int j = 0; j < ny; ++j) {
      const std::uint8_t* row = inside.data() + static_cast<std::size_t>(j) * static_cast<std::size_t>(nx);
      std::uint32_t* out = ids.data() + static_cast<std::size_t>(j) * static_cast<std::size_t>(nx - 1);
      forEachDifference(row, row + 1, nx - 1, [&](int i) { out[i] = addVertex(i, j, k, 0); });
    }
    for (int j = 0; j + 1 < ny; ++j) {
      const std::uint8_t* row = inside.data() + static_cast<std::size_t>(j) * static_cast<std::size_t>(nx);
      std::uint32_t* out = ids.data() + field_.xEdges + static_cast<std::size_t>(j) * static_cast<std::size_t>(nx);
      forEachDifference(row, row + nx, nx, [&](int i) { out[i] = addVertex(i, j, k, 1); });
    }
  }

  // The edges along z from slice k to slice k + 1.
  void betweenVertices(int k, const std::vector<std::uint8_t>& below, const std::vector<std::uint8_t>& above, std::vector<std::uint32_t>& ids) {
    const int nx = field_.nx, ny = field_.ny;
    for (int j = 0; j < ny; ++j) {
      const std::size_t row = static_cast<std::size_t>(j) * static_cast<std::size_t>(nx);
      std::uint32_t* out = ids.data() + row;
      forEachDifference(below.data() + row, above.data() + row, nx, [&](int i) { out[i] = addVertex(i, j, k, 2); });
    }
  }

  // The vertex where the edge from sample (i, j, k) one step along `axis` crosses iso.
  std::uint32_t addVertex(int i, int j, int k, int axis) {
    const Field& f = field_;
    const std::size_t at = f.volume.index(i, j, k);
    const std::size_t step = axis == 0 ? 1 : axis == 1 ? f.strideY : f.strideZ;
    const float f0 = f.value(at), f1 = f.value(at + step);
    // In [0, 1], as exactly one end is ≥ iso; in double, so that no two
    // finite samples overflow their difference. Where one end is not
    // finite, the limit: the vertex sits at the other end (midway where neither is).
    double t = (static_cast<double>(f.iso) - f0) / (static_cast<double>(f1) - f0);
    if (!(t >= 0.0 && t <= 1.0)) t = std::isfinite(f0) == std::isfinite(f1) ? 0.5 : std::isfinite(f0) ? 0.0 : 1.0;
    glm::ivec3 end{i, j, k};
    glm::vec3 grid{static_cast<float>(i), static_cast<float>(j), static_cast<float>(k)};
    ++end[axis];
    const auto along = static_cast<float>(t);
    grid[axis] += along;  // the lerp of the two ends' positions, written so that t = 0 and 1 land on the samples exactly
    const glm::vec3 g0 = sampleGradient(f.volume, i, j, k), g1 = sampleGradient(f.volume, end.x, end.y, end.z);
    // Down the gradient: outside. 0 where it has no direction; the faces decide once the mesh is whole.
    const glm::vec3 normal = -direction(g0 + along * (g1 - g0));
    part_.unsetNormals = part_.unsetNormals || normal == glm::vec3(0.0f);
    part_.positions.push_back(grid * f.volume.spacing);
    part_.normals.push_back(normal);
    return static_cast<std::uint32_t>(part_.positions.size() - 1);
  }

  void cells(const std::vector<std::uint8_t>& quadBottom, const std::vector<std::uint8_t>& quadTop, const std::vector<std::uint32_t>& bottom,
             const std::vector<std::uint32_t>& top, const std::vector<std::uint32_t>& between, bool borrowing) {
    const Field& f = field_;
    // Where edge e of cell (i, j) keeps its id: which array, and the offset
    // from the cell's base index in it (x: j·(nx − 1) + i; y, z: j·nx + i).
    std::array<const std::uint32_t*, kEdges> source{};
    std::array<std::size_t, kEdges> offset{};
    std::array<bool, kEdges> fromTop{};
    for (int e = 0; e < kEdges; ++e) {
      const int c = edgeCorner(e, 0), dx = c & 1, dy = (c >> 1) & 1, dz = (c >> 2) & 1;
      const auto u = static_cast<std::size_t>(e);
      if (e < 8) {
        source[u] = dz ? top.data() : bottom.data();
        fromTop[u] = dz != 0;
        offset[u] = e < 4 ? static_cast<std::size_t>(dy) * static_cast<std::size_t>(f.nx - 1) : f.xEdges + static_cast<std::size_t>(dx);
      } else {
        source[u] = between.data();
        offset[u] = static_cast<std::size_t>(dy) * f.strideY + static_cast<std::size_t>(dx);
      }
    }
    const int nx = f.nx, ny = f.ny, rowCells = nx - 1;
    const auto cell = [&](int i, int j, int c) {
      const int count = kCaseTable.triangleCount[static_cast<std::size_t>(c)];
      const std::size_t baseX = static_cast<std::size_t>(j) * static_cast<std::size_t>(rowCells) + static_cast<std::size_t>(i);
      const std::size_t baseYZ = static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i);
      const auto& edges = kCaseTable.edges[static_cast<std::size_t>(c)];
      for (int m = 0; m < 3 * count; ++m) {
        const std::size_t e = edges[static_cast<std::size_t>(m)];
        if (borrowing && fromTop[e]) part_.borrowed.push_back(part_.indices.size());
        part_.indices.push_back(source[e][(e < 4 ? baseX : baseYZ) + offset[e]]);
      }
    };
    // Eight cells at a time are skipped when all eight are wholly outside or wholly inside.
    constexpr std::uint64_t kAllInside = 0x0F0F0F0F0F0F0F0Full;
    for (int j = 0; j + 1 < ny; ++j) {
      const std::uint8_t* below = quadBottom.data() + static_cast<std::size_t>(j) * static_cast<std::size_t>(rowCells);
      const std::uint8_t* above = quadTop.data() + static_cast<std::size_t>(j) * static_cast<std::size_t>(rowCells);
      int i = 0;
      for (; i + 8 <= rowCells; i += 8) {
        std::uint64_t wordBelow = 0, wordAbove = 0;
        std::memcpy(&wordBelow, below + i, 8);
        std::memcpy(&wordAbove, above + i, 8);
        if (wordBelow == wordAbove && (wordBelow == 0 || wordBelow == kAllInside)) continue;
        for (int m = i; m < i + 8; ++m) {
          const int c = below[m] | above[m] << 4;
          if (c != 0 && c != 255) cell(m, j, c);
        }
      }
      for (; i < rowCells; ++i) {
        const int c = below[i] | above[i] << 4;
        if (c != 0 && c != 255) cell(i, j, c);
      }
    }
  }

  const Field& field_;
  Part& part_;
};

// Vertices whose gradient had no direction take the area-weighted normal of
// their triangles, or +z where those have no area either.
void fillUnsetNormals(Mesh& mesh) {
  std::vector<char> unset(mesh.normals.size());
  for (std::size_t v = 0; v < mesh.normals.size(); ++v) unset[v] = mesh.normals[v] == glm::vec3(0.0f);
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    if (!unset[a] && !unset[b] && !unset[c]) continue;
    const glm::vec3 area = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    for (std::uint32_t v : {a, b, c})
      if (unset[v]) mesh.normals[v] += area;
  }
  for (std::size_t v = 0; v < mesh.normals.size(); ++v) {
    if (!unset[v]) continue;
    const glm::vec3 n = direction(mesh.normals[v]);
    mesh.normals[v] = n == glm::vec3(0.0f) ? glm::vec3(0.0f, 0.0f, 1.0f) : n;
  }
}

// Enough slabs per thread that starting it pays.
constexpr int kMinSlabsPerThread = 16;

// job(0) .. job(count − 1), job(0) on this thread.
template <typename Job>
void onThreads(int count, const Job& job) {
  std::vector<std::jthread> workers;
  for (int t = 1; t < count; ++t) workers.emplace_back(job, t);
  job(0);
}

}  // namespace

Mesh marchingCubes(const Volume& volume, float isoValue) {
  Mesh mesh;
  mesh.name = "isosurface";
  if (volume.size.x < 2 || volume.size.y < 2 || volume.size.z < 2 || volume.values.size() != volume.sampleCount()) return mesh;
  const Field field(volume, isoValue);
  const int slabs = field.nz - 1;
  const int hardware = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const int threads = std::clamp(slabs / kMinSlabsPerThread, 1, hardware);
  std::vector<Part> parts(static_cast<std::size_t>(threads));
  const auto tooMany = [&volume](std::size_t vertices) {
    if (vertices > std::numeric_limits<std::uint32_t>::max())
      throw Error("marching cubes on " + volume.source + ": too many vertices for 32-bit indices");
  };

  if (threads == 1) {
    Part& part = parts[0];
    SlabWalker(field, part).run(0, slabs, true);
    tooMany(part.positions.size());
    mesh.positions = std::move(part.positions);
    mesh.normals = std::move(part.normals);
    mesh.indices = std::move(part.indices);
    if (part.unsetNormals) fillUnsetNormals(mesh);
    return mesh;
  }

  // Each thread walks its range of slabs; then, with every part's size
  // known, each copies its part into place, numbering its vertices after
  // those of the ranges below.
  std::vector<std::exception_ptr> failures(parts.size());
  onThreads(threads, [&](int t) {
    try {
      const auto range = [&](int r) { return static_cast<int>(static_cast<long long>(slabs) * r / threads); };
      SlabWalker(field, parts[static_cast<std::size_t>(t)]).run(range(t), range(t + 1), t + 1 == threads);
    } catch (...) {
      failures[static_cast<std::size_t>(t)] = std::current_exception();
    }
  });
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);
  std::vector<std::size_t> firstVertex(parts.size() + 1), firstIndex(parts.size() + 1);
  for (std::size_t t = 0; t < parts.size(); ++t) {
    firstVertex[t + 1] = firstVertex[t] + parts[t].positions.size();
    firstIndex[t + 1] = firstIndex[t] + parts[t].indices.size();
  }
  tooMany(firstVertex.back());
  mesh.positions.resize(firstVertex.back());
  mesh.normals.resize(firstVertex.back());
  mesh.indices.resize(firstIndex.back());
  onThreads(threads, [&](int t) {
    const auto u = static_cast<std::size_t>(t);
    const Part& part = parts[u];
    std::copy(part.positions.begin(), part.positions.end(), mesh.positions.begin() + static_cast<std::ptrdiff_t>(firstVertex[u]));
    std::copy(part.normals.begin(), part.normals.end(), mesh.normals.begin() + static_cast<std::ptrdiff_t>(firstVertex[u]));
    std::uint32_t* out = mesh.indices.data() + firstIndex[u];
    const auto base = static_cast<std::uint32_t>(firstVertex[u]);
    for (std::size_t m = 0; m < part.indices.size(); ++m) out[m] = part.indices[m] + base;
    if (part.borrowed.empty()) return;
    const Part& above = parts[u + 1];
    const auto aboveBase = static_cast<std::uint32_t>(firstVertex[u + 1]);
    for (std::size_t m : part.borrowed) out[m] = aboveBase + above.firstSliceIds[part.indices[m]];
  });
  if (std::any_of(parts.begin(), parts.end(), [](const Part& p) { return p.unsetNormals; })) fillUnsetNormals(mesh);
  return mesh;
}

}  // namespace facet
