#pragma once
// Temporary files and folders that must not outlive an interrupted run: while
// a guard holds a path, SIGINT, SIGTERM or SIGHUP removes it, then the signal
// ends the process with its default action (as if no handler were there).
#include <string>

namespace facet {

class InterruptCleanup {
 public:
  enum class Kind { File, Folder };

  // Holds `path` (removed as a file, or as a folder with everything in it)
  // until release() or destruction. The first guard installs the handler for
  // each of the three signals whose action is still the default; a signal a
  // program handles or ignores itself is left alone. A path longer than the
  // handler's fixed buffer, or more paths at once than it has slots, goes
  // unguarded: the run works, an interrupt may leave the path behind.
  InterruptCleanup(const std::string& path, Kind kind);
  ~InterruptCleanup();
  InterruptCleanup(const InterruptCleanup&) = delete;
  InterruptCleanup& operator=(const InterruptCleanup&) = delete;

  // The path is no longer temporary (renamed into place) or already removed.
  void release();

 private:
  int slot_ = -1;
};

}  // namespace facet
