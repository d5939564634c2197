#include "scene/environment_map.h"

#include <cmath>
#include <numbers>

#include <glm/vec3.hpp>

#include "common/error.h"
#include "image/mipmap.h"
#include "image/png.h"
#include "image/srgb.h"

namespace facet {
namespace {

// The direction through face coordinates (a, b) = (sc/ma, tc/ma) of `face`:
// OpenGL's (sc, tc, ma) table (PIPELINE.md, "Textures") solved for D with |ma| = 1.
glm::dvec3 faceDirection(int face, double a, double b) {
  switch (face) {
    case 0: return {1.0, -b, -a};
    case 1: return {-1.0, -b, a};
    case 2: return {a, 1.0, b};
    case 3: return {a, -1.0, -b};
    case 4: return {a, -b, 1.0};
    default: return {-a, -b, -1.0};
  }
}

// Each face's mip chain (image/mipmap.h), laid side by side level by level.
std::vector<Image> stripMips(const Image& strip) {
  const int n = strip.height();
  std::vector<std::vector<Image>> faces(6);
  for (int f = 0; f < 6; ++f) {
    Image face(n, n);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) face.at(x, y) = strip.at(f * n + x, y);
    faces[static_cast<std::size_t>(f)] = mipLevels(face, TexelEncoding::Srgb);
  }
  std::vector<Image> levels;
  for (std::size_t k = 0; k < faces[0].size(); ++k) {
    const int m = faces[0][k].height();
    Image level(6 * m, m);
    for (int f = 0; f < 6; ++f)
      for (int y = 0; y < m; ++y)
        for (int x = 0; x < m; ++x) level.at(f * m + x, y) = faces[static_cast<std::size_t>(f)][k].at(x, y);
    levels.push_back(std::move(level));
  }
  return levels;
}

// E(N)/π from the first nine spherical harmonics of the map (Ramamoorthi and
// Hanrahan 2001), as the coefficients of EnvironmentMap::irradiance.
std::array<glm::vec3, 9> irradianceOf(const Image& strip) {
  const int n = strip.height();
  const double pi = std::numbers::pi;
  const double y00 = 0.5 / std::sqrt(pi), y1 = std::sqrt(3.0 / (4.0 * pi)), y2 = std::sqrt(15.0 / (4.0 * pi));
  const double y20 = std::sqrt(5.0 / (16.0 * pi)), y22 = std::sqrt(15.0 / (16.0 * pi));
  const float* decoded = srgbTables().decoded.data();
  std::array<glm::dvec3, 9> L{};  // L00, L1-1, L10, L11, L2-2, L2-1, L20, L21, L22
  double weights = 0.0;
  for (int f = 0; f < 6; ++f)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const double a = 2.0 * (x + 0.5) / n - 1.0, b = 2.0 * (1.0 - (y + 0.5) / n) - 1.0;
        const double r2 = 1.0 + a * a + b * b;
        const double dw = (4.0 / (static_cast<double>(n) * n)) / (r2 * std::sqrt(r2));
        const glm::dvec3 d = faceDirection(f, a, b) / std::sqrt(r2);
        const Rgba8 c = strip.at(f * n + x, y);
        const glm::dvec3 radiance(decoded[c.r], decoded[c.g], decoded[c.b]);
        const double basis[9] = {y00,           y1 * d.y, y1 * d.z, y1 * d.x, y2 * d.x * d.y, y2 * d.y * d.z, y20 * (3.0 * d.z * d.z - 1.0),
                                 y2 * d.x * d.z, y22 * (d.x * d.x - d.y * d.y)};
        for (int k = 0; k < 9; ++k) L[static_cast<std::size_t>(k)] += radiance * (basis[k] * dw);
        weights += dw;
      }
  for (glm::dvec3& l : L) l *= 4.0 * pi / weights;
  // E/π = Σ (Â_l/π)·L_lm·Y_lm(N) with Â_0 = π, Â_1 = 2π/3, Â_2 = π/4, collected by monomial.
  const double a1 = 2.0 / 3.0, a2 = 0.25;
  const glm::dvec3 k[9] = {y00 * L[0] - a2 * y20 * L[6], a1 * y1 * L[3], a1 * y1 * L[1],      a1 * y1 * L[2],     a2 * y2 * L[4],
                           a2 * y2 * L[5],              a2 * y2 * L[7], a2 * y22 * L[8], a2 * 3.0 * y20 * L[6]};
  std::array<glm::vec3, 9> out{};
  for (int i = 0; i < 9; ++i) out[static_cast<std::size_t>(i)] = glm::vec3(k[i]);
  return out;
}

}  // namespace

EnvironmentMap environmentMapOf(Image strip, const std::string& path) {
  const int w = strip.width(), h = strip.height();
  if (h < 1 || w != 6 * h)
    throw Error(path + ": " + std::to_string(w) + "x" + std::to_string(h) +
                " is not a cube map: six square faces side by side, 6N x N, in the order +x -x +y -y +z -z");
  EnvironmentMap map;
  map.path = path;
  map.faces = std::move(strip);
  map.mips = stripMips(map.faces);
  map.irradiance = irradianceOf(map.faces);
  return map;
}

EnvironmentMap loadEnvironmentMap(const std::string& path) { return environmentMapOf(readPng(path), path); }

}  // namespace facet
