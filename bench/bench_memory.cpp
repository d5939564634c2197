#include "bench_memory.h"

#include "child_process.h"

namespace facet {

double benchChildPeakMegabytes(const std::vector<std::string>& childArgs) {
  std::vector<std::string> args{selfPath(), "bench"};
  args.insert(args.end(), childArgs.begin(), childArgs.end());
  long kilobytes = 0;
  if (runChild(args, nullptr, &kilobytes) != 0 || kilobytes <= 0) return -1;
  return static_cast<double>(kilobytes) / 1024.0;
}

}  // namespace facet
