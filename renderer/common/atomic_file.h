#pragma once
#include <cstdint>
#include <span>
#include <string>

namespace facet {

// Writes `bytes` to `path` atomically: into a temporary file beside it, then
// renamed over it, so a failed run never leaves a partial file at `path`.
// Throws facet::Error naming the path on failure.
void writeFileAtomically(const std::string& path, std::span<const std::uint8_t> bytes);

// Reads a whole file; throws facet::Error naming the path when it cannot, when
// it is not a regular file, or when it is larger than maxBytes.
std::string readFile(const std::string& path, std::uint64_t maxBytes);

}  // namespace facet
