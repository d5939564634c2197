// The frame's large buffers ask the kernel for 2 MiB pages.
#include <doctest/doctest.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "common/large_pages.h"

using namespace facet;

namespace {

// The VmFlags of the mapping of /proc/self/smaps that holds `p`, or "" where none does.
std::string vmFlagsAt(const void* p) {
  std::ifstream smaps("/proc/self/smaps");
  const auto at = reinterpret_cast<std::uintptr_t>(p);
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    unsigned long long begin = 0, end = 0;
    if (std::sscanf(line.c_str(), "%llx-%llx ", &begin, &end) == 2 && line.find(':') > line.find(' ')) inside = begin <= at && at < end;
    else if (inside && line.rfind("VmFlags:", 0) == 0) return line;
  }
  return "";
}

}  // namespace

TEST_CASE("a buffer of 2 MiB or more starts on a 2 MiB boundary and is advised for large pages") {
  LargeVector<float> shadowMap(std::size_t{2048} * 2048, 1.0f);
  CHECK(reinterpret_cast<std::uintptr_t>(shadowMap.data()) % kLargePageBytes == 0);
  CHECK(shadowMap[2048 * 2048 - 1] == 1.0f);
  if (!std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled")) {
    MESSAGE("this kernel has no transparent huge pages: the advice is not checked");
    return;
  }
  const std::string flags = vmFlagsAt(shadowMap.data());
  INFO("VmFlags of the buffer's mapping: " << flags);
  CHECK(flags.find(" hg") != std::string::npos);  // MADV_HUGEPAGE
}

TEST_CASE("a small buffer is an ordinary allocation, and growing past 2 MiB keeps the values") {
  LargeVector<int> values;
  for (int i = 0; i < 1 << 20; ++i) values.push_back(i);  // 4 MiB, through every capacity below it
  bool kept = true;
  for (int i = 0; i < 1 << 20; ++i) kept = kept && values[static_cast<std::size_t>(i)] == i;
  CHECK(kept);
  const std::string flags = vmFlagsAt(LargeVector<int>(16).data());
  CHECK(flags.find(" hg") == std::string::npos);
}
