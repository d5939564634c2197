#pragma once
// `facet batch --shard I/N`: the I-th of N disjoint slices of a job file, so
// that N machines (a Kubernetes Indexed Job, a Slurm job array, a CI matrix)
// share one job list with no coordination. Job k (0-based, in file order,
// counting job lines only) belongs to shard k mod N: deterministic, every job
// in exactly one shard, and the shards' sizes differ by at most one.
#include <cstddef>
#include <string>

namespace facet {

struct Shard {
  std::size_t index = 0;  // I, in [0, count)
  std::size_t count = 1;  // N >= 1
};

// Parses "I/N" (whole numbers, 0 <= I < N); throws facet::UsageError naming
// --shard and what is wrong ("0/0", "5/3", "a/b").
Shard parseShard(const std::string& text);

// Whether the k-th job (0-based) belongs to `shard`.
bool inShard(std::size_t k, const Shard& shard);

}  // namespace facet
