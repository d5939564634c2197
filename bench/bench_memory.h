#pragma once
// Peak memory of one backend rendering one scene, each in a child process
// (this executable's hidden `bench --child`), so that each figure is that
// backend's own and not what the others left behind.
#include <string>
#include <vector>

namespace facet {

// Runs `facet bench <childArgs>` (the --child spec and its options) and
// returns its peak resident memory in MB (wait4's ru_maxrss), or -1 when
// the child failed. That figure is never below this process's own peak at
// the spawn (child_process.h): call it before this process builds scenes
// or backends, while it is smaller than any child.
double benchChildPeakMegabytes(const std::vector<std::string>& childArgs);

}  // namespace facet
