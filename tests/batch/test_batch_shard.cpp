// --shard I/N: N slices that cover every job exactly once, and the values refused.
#include <doctest/doctest.h>

#include <vector>

#include "batch_shard.h"
#include "common/error.h"

namespace facet {

TEST_CASE("N shards cover every job exactly once") {
  constexpr std::size_t kJobs = 20;
  for (const std::size_t n : {1u, 2u, 3u, 7u, 20u, 25u}) {
    std::vector<int> seen(kJobs, 0);
    std::vector<std::size_t> sizes(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      const Shard shard = parseShard(std::to_string(i) + "/" + std::to_string(n));
      for (std::size_t k = 0; k < kJobs; ++k)
        if (inShard(k, shard)) ++seen[k], ++sizes[i];
    }
    for (std::size_t k = 0; k < kJobs; ++k) CHECK_MESSAGE(seen[k] == 1, "job ", k, " with N = ", n);
    for (std::size_t i = 0; i < n; ++i) CHECK(sizes[i] + 1 >= kJobs / n);  // balanced: within one of each other
  }
}

TEST_CASE("--shard refuses what is not I/N with 0 <= I < N") {
  for (const char* bad : {"0/0", "5/3", "3/3", "a/b", "1", "-1/3", "1/-3", "", "/", "1/", "/2", " 1/2", "1/2x"})
    CHECK_THROWS_AS(parseShard(bad), UsageError);
  CHECK(parseShard("2/3").index == 2);
  CHECK(parseShard("2/3").count == 3);
}

}  // namespace facet
