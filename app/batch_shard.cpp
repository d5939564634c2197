#include "batch_shard.h"

#include "common/error.h"
#include "common/quote.h"

namespace facet {
namespace {

// A whole number of at most 9 digits (no sign, no space), or false.
bool wholeNumber(const std::string& text, std::size_t& value) {
  if (text.empty() || text.size() > 9 || text.find_first_not_of("0123456789") != std::string::npos) return false;
  value = std::stoul(text);
  return true;
}

}  // namespace

Shard parseShard(const std::string& text) {
  const std::size_t slash = text.find('/');
  Shard shard;
  const auto digitsOnly = [](const std::string& part) { return !part.empty() && part.find_first_not_of("0123456789") == std::string::npos; };
  if (slash == std::string::npos || !digitsOnly(text.substr(0, slash)) || !digitsOnly(text.substr(slash + 1)))
    throw UsageError("--shard " + quoteInput(text) + ": expected I/N, whole numbers, e.g. 0/4 (the first of 4 shards)");
  if (!wholeNumber(text.substr(0, slash), shard.index) || !wholeNumber(text.substr(slash + 1), shard.count))
    throw UsageError("--shard " + quoteInput(text) + ": at most 999999999 shards");
  if (shard.count == 0) throw UsageError("--shard " + quoteInput(text) + ": N must be at least 1");
  if (shard.index >= shard.count)
    throw UsageError("--shard " + quoteInput(text) + ": I must be in [0, " + std::to_string(shard.count - 1) + "] (shards count from 0, as JOB_COMPLETION_INDEX)");
  return shard;
}

bool inShard(std::size_t k, const Shard& shard) { return k % shard.count == shard.index; }

}  // namespace facet
