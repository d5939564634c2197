#pragma once
// Output folders that are complete or absent: written under a temporary name
// beside their place and renamed into it as a whole.
#include <optional>
#include <string>
#include <vector>

#include "common/interrupt_cleanup.h"

namespace facet {

// Checks, before any work, that `path` can become an output folder: not
// empty, not ".", ".." or "/" (a name of its own, that a rename can take),
// not an existing file, not one of `inputs` (device and inode), and its
// nearest existing parent is a writable folder. Missing parents are fine:
// StagedFolder creates them. Whether an existing folder may be replaced is
// the caller's rule. Throws facet::Error naming the path.
void checkOutputFolder(const std::string& path, const std::vector<std::string>& inputs);

// A new, empty folder .NAME.XXXXXX beside `destination` (same file system,
// mode 0777 less the umask), removed with everything in it on destruction
// and on SIGINT/SIGTERM/SIGHUP unless commit() has put it in its place.
class StagedFolder {
 public:
  // Creates the missing parents of `destination` (removed again when the
  // folder is dropped), then the folder; throws facet::Error naming
  // `destination` when it cannot.
  explicit StagedFolder(const std::string& destination);
  ~StagedFolder();
  StagedFolder(const StagedFolder&) = delete;
  StagedFolder& operator=(const StagedFolder&) = delete;

  const std::string& path() const { return path_; }  // where to write, until commit()

  // Flushes the folder's entries to disk and renames it to `destination`; a
  // folder already there is swapped out in the same step and then removed,
  // so `destination` is the old folder or the new one at every moment.
  void commit();

 private:
  void removeCreatedParents();

  std::string destination_;
  std::string path_;
  std::vector<std::string> createdParents_;  // deepest last
  std::optional<InterruptCleanup> guard_;
  bool committed_ = false;
};

}  // namespace facet
