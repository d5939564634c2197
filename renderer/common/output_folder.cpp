#include "common/output_folder.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "common/atomic_file.h"
#include "common/error.h"

namespace facet {
namespace {

namespace fs = std::filesystem;

// "report///" -> "report"; "/" stays "/".
std::string withoutTrailingSlashes(const std::string& path) {
  std::string out = path;
  while (out.size() > 1 && out.back() == '/') out.pop_back();
  return out;
}

std::string lastComponent(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// The existing input `input` inside the folder `folder` (it or a folder above
// it is `folder`): replacing the folder would delete the input.
bool isInside(const std::string& input, const struct stat& folder) {
  std::error_code ec;
  fs::path at = fs::canonical(input, ec);
  if (ec) return false;
  for (;;) {
    struct stat st {};
    if (::stat(at.c_str(), &st) == 0 && st.st_dev == folder.st_dev && st.st_ino == folder.st_ino) return true;
    if (!at.has_relative_path()) return false;
    at = at.parent_path();
  }
}

std::string randomSuffix() {
  static constexpr char kLetters[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  std::random_device random;
  std::string suffix(6, 'x');
  for (char& c : suffix) c = kLetters[random() % (sizeof kLetters - 1)];
  return suffix;
}

void syncFolder(const std::string& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;  // nothing to flush where the folder cannot be opened; rename reports real trouble
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

void checkOutputFolder(const std::string& path, const std::vector<std::string>& inputs) {
  if (path.empty()) throw Error("an empty folder name");
  const std::string shown = shownPath(path);
  const std::string name = withoutTrailingSlashes(path);
  const std::string last = lastComponent(name);
  const char* why = name == "/" ? "is the root folder" : name == "." ? "is the current folder" : name == ".." ? "is the parent folder"
                  : (last == "." || last == "..") ? "ends in '.' or '..'" : nullptr;
  if (why) throw Error(shown + ": " + why + "; give the output a folder of its own, such as report/");
  struct stat st {};
  if (::stat(name.c_str(), &st) == 0) {
    if (!S_ISDIR(st.st_mode)) throw Error(shown + ": exists and is not a folder");
    if (const std::string same = sameFileAsInput(name, inputs); !same.empty()) throw Error(same);
    for (const std::string& input : inputs)
      if (!input.empty() && isInside(input, st))
        throw Error(shown + ": holds the input " + shownPath(input) + "; write the output elsewhere");
  } else if (errno != ENOENT) {
    throw Error(shown + ": " + describeErrno(errno));
  }
  checkCanCreateIn(folderOf(followLinks(name)), path, MissingFolders::Created);
}

StagedFolder::StagedFolder(const std::string& destination) : destination_(followLinks(withoutTrailingSlashes(destination))) {
  const std::string shown = shownPath(destination);
  const std::string parent = folderOf(destination_);
  std::error_code ec;
  for (std::string missing = parent; !fs::exists(fs::symlink_status(missing, ec)) && folderOf(missing) != missing; missing = folderOf(missing))
    createdParents_.insert(createdParents_.begin(), missing);
  fs::create_directories(parent, ec);
  if (ec) {
    removeCreatedParents();
    throw Error(shown + ": cannot create the folder " + shownPath(parent) + " (" + ec.message() + ")");
  }
  const std::string name = lastComponent(destination_);
  for (int attempt = 0; attempt < 100; ++attempt) {
    path_ = parent + "/." + name + "." + randomSuffix();
    guard_.emplace(path_, InterruptCleanup::Kind::Folder);
    if (::mkdir(path_.c_str(), 0777) == 0) break;  // 0777: the kernel applies the umask
    const int error = errno;
    guard_.reset();
    path_.clear();
    if (error != EEXIST) {
      removeCreatedParents();
      throw Error(shown + ": cannot create a folder in " + shownPath(parent) + " (" + std::strerror(error) + ")");
    }
  }
  if (path_.empty()) {
    removeCreatedParents();
    throw Error(shown + ": cannot create a temporary folder in " + shownPath(parent));
  }
  struct stat old {};
  if (::stat(destination_.c_str(), &old) == 0 && S_ISDIR(old.st_mode)) ::chmod(path_.c_str(), old.st_mode & 07777);  // keep the old folder's mode
}

StagedFolder::~StagedFolder() {
  if (committed_ || path_.empty()) return;
  std::error_code ec;
  fs::remove_all(path_, ec);  // nothing more to do if it fails: the guard's name shows what it was
  removeCreatedParents();
}

void StagedFolder::removeCreatedParents() {
  // Deepest first, and only while empty: another run may have put something there meanwhile.
  for (auto it = createdParents_.rbegin(); it != createdParents_.rend(); ++it)
    if (::rmdir(it->c_str()) != 0) break;
  createdParents_.clear();
}

void StagedFolder::commit() {
  const std::string shown = shownPath(destination_);
  syncFolder(path_);
  struct stat old {};
  if (::lstat(destination_.c_str(), &old) != 0) {
    if (::rename(path_.c_str(), destination_.c_str()) != 0)
      throw Error(shown + ": cannot put the folder in place (" + std::strerror(errno) + ")");
  } else {
    if (!S_ISDIR(old.st_mode)) throw Error(shown + ": exists and is not a folder");
    // One step: the old folder moves to the temporary name, the new one into place.
    if (::renameat2(AT_FDCWD, path_.c_str(), AT_FDCWD, destination_.c_str(), RENAME_EXCHANGE) != 0) {
      if (errno != EINVAL && errno != ENOSYS) throw Error(shown + ": cannot replace the folder (" + std::strerror(errno) + ")");
      // A file system without the exchange: the old folder steps aside first.
      const std::string aside = folderOf(destination_) + "/." + lastComponent(destination_) + ".old." + randomSuffix();
      if (::rename(destination_.c_str(), aside.c_str()) != 0)
        throw Error(shown + ": cannot replace the folder (" + std::strerror(errno) + ")");
      if (::rename(path_.c_str(), destination_.c_str()) != 0) {
        const int error = errno;
        ::rename(aside.c_str(), destination_.c_str());
        throw Error(shown + ": cannot replace the folder (" + std::strerror(error) + ")");
      }
      // Guarded only now: until the new folder is in place the old one is kept.
      const InterruptCleanup asideGuard(aside, InterruptCleanup::Kind::Folder);
      std::error_code ec;
      fs::remove_all(aside, ec);
    } else {
      std::error_code ec;
      fs::remove_all(path_, ec);  // the old folder, now under the temporary name (still guarded)
    }
  }
  committed_ = true;
  guard_.reset();
  syncFolder(folderOf(destination_));
}

}  // namespace facet
