#include "scene/memory_budget.h"

#include <cstdio>
#include <utility>

#include "common/error.h"

namespace facet {

std::string byteCount(std::uint64_t bytes) {
  constexpr std::uint64_t kMiB = std::uint64_t{1} << 20, kGiB = std::uint64_t{1} << 30;
  if (bytes >= kGiB && bytes % kGiB == 0 && bytes <= 1024 * kGiB) return std::to_string(bytes / kGiB) + " GiB";
  if (bytes >= kMiB && bytes % kMiB == 0 && bytes < kGiB) return std::to_string(bytes / kMiB) + " MiB";
  if (bytes < 1000) return std::to_string(bytes) + " bytes";
  static const char* const kUnits[] = {"kB", "MB", "GB", "TB", "PB", "EB"};
  double value = static_cast<double>(bytes);
  int unit = -1;
  while (value >= 999.5 && unit < 5) value /= 1000.0, ++unit;
  char text[32];
  std::snprintf(text, sizeof text, value >= 99.95 ? "%.0f %s" : value >= 9.995 ? "%.1f %s" : "%.2f %s", value, kUnits[unit]);
  return text;
}

MemoryBudget::MemoryBudget(std::uint64_t limit, std::string name) : limit_(limit), name_(std::move(name)) {}

void MemoryBudget::charge(std::uint64_t bytes, const std::string& what) {
  if (fits(bytes)) {
    used_ += bytes;
    return;
  }
  std::string message = what + " need " + byteCount(bytes) + ",";
  if (used_ > 0 && bytes <= limit_) message += " which with the " + byteCount(used_) + " counted before is";
  throw Error(message + " more than the " + name_ + " of " + byteCount(limit_));
}

std::uint64_t instanceFrameBytes(std::uint64_t vertices, std::uint64_t triangles) {
  return vertices * kFrameBytesPerVertex + triangles * kFrameBytesPerTriangle;  // both below 2^40: no overflow
}

std::uint64_t shadowMapBytes(int mapSize, int faces) {
  if (mapSize <= 0 || faces <= 0) return 0;
  return static_cast<std::uint64_t>(mapSize) * static_cast<std::uint64_t>(mapSize) * static_cast<std::uint64_t>(faces) * sizeof(float);
}

}  // namespace facet
