#include "common/atomic_file.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>
#include <random>
#include <tuple>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "common/error.h"
#include "common/interrupt_cleanup.h"
#include "common/quote.h"

namespace facet {
namespace {

constexpr int kMaxSymlinks = 40;  // Linux's own limit (ELOOP)

bool isPrintableUtf8(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    const auto b = static_cast<unsigned char>(text[i]);
    if (b < 0x20 || b == 0x7f) return false;
    const std::size_t n = b < 0x80 ? 1 : (b & 0xe0) == 0xc0 ? 2 : (b & 0xf0) == 0xe0 ? 3 : (b & 0xf8) == 0xf0 ? 4 : 0;
    if (n == 0 || (n == 2 && b < 0xc2) || i + n > text.size()) return false;
    for (std::size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(text[i + k]) & 0xc0) != 0x80) return false;
    i += n;
  }
  return true;
}

// What writeFileAtomically and checkOutputFile find at a path.
struct Destination {
  enum Kind { NewFile, RegularFile, Stream } kind = NewFile;
  std::string file;  // NewFile, RegularFile: the file to create or replace (links followed)
  struct stat status {};  // RegularFile, Stream
};

Destination inspect(const std::string& path) {
  if (path.empty()) throw Error("an empty file name");
  const std::string shown = shownPath(path);
  Destination d;
  if (::stat(path.c_str(), &d.status) == 0) {
    const mode_t type = d.status.st_mode & S_IFMT;
    if (type == S_IFDIR) throw Error(shown + ": is a folder; give the name of a file in it");
    if (type == S_IFCHR || type == S_IFIFO) {
      d.kind = Destination::Stream;
      return d;
    }
    if (type != S_IFREG) throw Error(shown + ": is neither a regular file, a character device nor a pipe; refusing to replace it");
    d.kind = Destination::RegularFile;
  } else if (errno != ENOENT) {
    throw Error(shown + ": " + describeErrno(errno));  // a loop of links, a file used as a folder, no permission
  }
  d.file = followLinks(path);
  return d;
}

}  // namespace

std::string folderOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

// Folders on the way need no resolving: a temporary file goes into the same
// folder as the file it replaces, whatever that folder is called.
std::string followLinks(const std::string& path) {
  std::string current = path;
  for (int hops = 0; hops <= kMaxSymlinks; ++hops) {
    struct stat st {};
    if (::lstat(current.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return current;
    std::string target(static_cast<std::size_t>(st.st_size > 0 ? st.st_size : 4096) + 1, '\0');
    const ssize_t n = ::readlink(current.c_str(), target.data(), target.size());
    if (n < 0) throw Error(shownPath(path) + ": cannot read the link (" + std::strerror(errno) + ")");
    target.resize(static_cast<std::size_t>(n));
    current = target.starts_with('/') ? target : folderOf(current) + "/" + target;
  }
  throw Error(shownPath(path) + ": " + describeErrno(ELOOP));
}

void checkCanCreateIn(const std::string& folder, const std::string& output, MissingFolders missing) {
  const std::string shown = shownPath(output);
  std::string existing = folder;
  struct stat st {};
  while (::stat(existing.c_str(), &st) != 0) {
    if (errno != ENOENT) throw Error(shown + ": cannot use the folder " + shownPath(existing) + " (" + std::strerror(errno) + ")");
    if (missing == MissingFolders::Refuse) throw Error(shown + ": the folder " + shownPath(folder) + " does not exist");
    const std::string up = folderOf(existing);
    if (up == existing) break;
    existing = up;
  }
  if (!S_ISDIR(st.st_mode)) throw Error(shown + ": " + shownPath(existing) + " is not a folder");
  if (::access(existing.c_str(), W_OK | X_OK) != 0)
    throw Error(shown + ": cannot create files in " + shownPath(existing) + " (" + std::strerror(errno) + ")");
}

namespace {

void writeAll(int fd, std::span<const std::uint8_t> bytes, const std::string& shown) {
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw Error(shown + ": write failed (" + std::strerror(n < 0 ? errno : EIO) + ")");
    written += static_cast<std::size_t>(n);
  }
}

// A device or a pipe is written where it is: replacing it is never wanted.
void writeStream(const std::string& path, std::span<const std::uint8_t> bytes) {
  const std::string shown = shownPath(path);
  const int fd = ::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) throw Error(shown + ": cannot open for writing (" + std::strerror(errno) + ")");
  try {
    writeAll(fd, bytes, shown);
  } catch (...) {
    ::close(fd);
    throw;
  }
  if (::close(fd) != 0) throw Error(shown + ": write failed (" + std::strerror(errno) + ")");
}

// Creates .NAME.XXXXXX beside `file` with O_EXCL; mode 0666 lets the kernel
// apply the umask (mkstemp's 0600 would not). Registers it for removal on an
// interrupt before it exists, so that no moment leaves it unguarded.
int createTemporary(const std::string& file, std::string& temp, std::optional<InterruptCleanup>& guard, const std::string& shown) {
  const std::string folder = folderOf(file);
  const std::string name = file.substr(file.find_last_of('/') == std::string::npos ? 0 : file.find_last_of('/') + 1);
  static constexpr char kLetters[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  std::random_device random;
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::string suffix(6, 'x');
    for (char& c : suffix) c = kLetters[random() % (sizeof kLetters - 1)];
    temp = folder + "/." + name + "." + suffix;
    guard.emplace(temp, InterruptCleanup::Kind::File);
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) return fd;
    const int error = errno;
    guard.reset();  // the name was someone else's, or nothing was created
    errno = error;
    if (errno == EEXIST) continue;
    if (errno == ENOENT) throw Error(shown + ": the folder " + shownPath(folder) + " does not exist");
    throw Error(shown + ": cannot create a file in " + shownPath(folder) + " (" + std::strerror(errno) + ")");
  }
  throw Error(shown + ": cannot create a temporary file in " + shownPath(folder) + " (" + std::strerror(EEXIST) + ")");
}

}  // namespace

std::string shownPath(std::string_view path) {
  if (path.size() <= 1024 && isPrintableUtf8(path)) return std::string(path);
  return quoteInput(path);
}

std::string quotedPath(std::string_view path) {
  std::string shown = shownPath(path);
  return shown == path ? "'" + shown + "'" : shown;
}

std::string describeErrno(int code) {
  std::string text = std::strerror(code);
  if (!text.empty() && text[0] >= 'A' && text[0] <= 'Z' && !(text.size() > 1 && text[1] >= 'A' && text[1] <= 'Z'))
    text[0] = static_cast<char>(text[0] - 'A' + 'a');
  return text;
}

void writeFileAtomically(const std::string& path, std::string_view text) {
  writeFileAtomically(path, {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
}

void writeFileAtomically(const std::string& path, std::span<const std::uint8_t> bytes) {
  const Destination d = inspect(path);
  if (d.kind == Destination::Stream) return writeStream(path, bytes);
  const std::string shown = shownPath(path);
  std::string temp;
  std::optional<InterruptCleanup> guard;
  const int fd = createTemporary(d.file, temp, guard, shown);
  try {
    writeAll(fd, bytes, shown);
    if (d.kind == Destination::RegularFile) {
      // The replaced file's owner (where this process may set it) and mode;
      // chown first, since it clears set-id bits.
      if (d.status.st_uid != ::geteuid() || d.status.st_gid != ::getegid())
        if (::fchown(fd, d.status.st_uid, d.status.st_gid) != 0) { /* not permitted: the new file is ours */ }
      if (::fchmod(fd, d.status.st_mode & 07777) != 0)
        throw Error(shown + ": cannot keep the file's mode (" + std::strerror(errno) + ")");
    }
    // On disk before the rename: a crash must leave the old file or the new, not an empty one.
    if (::fsync(fd) != 0) throw Error(shown + ": write failed (" + std::strerror(errno) + ")");
  } catch (...) {
    ::close(fd);
    ::unlink(temp.c_str());
    throw;
  }
  if (::close(fd) != 0 || ::rename(temp.c_str(), d.file.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(temp.c_str());
    throw Error(shown + ": cannot write (" + why + ")");
  }
  guard.reset();
  const int folder = ::open(folderOf(d.file).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (folder >= 0) {  // the rename itself on disk; a file system that cannot is no reason to fail
    ::fsync(folder);
    ::close(folder);
  }
}

namespace {

// Who a path is: the file it names when there is one (device and inode,
// whatever the spelling, links or hard links), and its canonical absolute
// name (links in the part that exists followed, . and .. gone) for one
// that is not written yet.
struct FileIdentity {
  bool exists = false;
  dev_t device = 0;
  ino_t inode = 0;
  std::string canonical;
};

FileIdentity identityOf(const std::string& path) {
  FileIdentity id;
  struct stat status {};
  if (::stat(path.c_str(), &status) == 0) id = {true, status.st_dev, status.st_ino, {}};
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
  const std::filesystem::path canonical = ec ? std::filesystem::path(path) : std::filesystem::weakly_canonical(absolute, ec);
  id.canonical = ec ? absolute.lexically_normal().string() : canonical.string();
  return id;
}

bool sameFile(const FileIdentity& a, const FileIdentity& b) {
  if (a.exists && b.exists) return a.device == b.device && a.inode == b.inode;
  return a.canonical == b.canonical;
}

}  // namespace

std::string sameFileAsInput(const std::string& path, const std::vector<std::string>& inputs) {
  if (path.empty()) return {};
  const FileIdentity out = identityOf(path);
  for (const std::string& input : inputs) {
    if (input.empty() || !sameFile(identityOf(input), out)) continue;
    if (input == path) return shownPath(path) + ": is an input of this command; write the output elsewhere";
    return shownPath(path) + ": is the input " + shownPath(input) + " under another name; write the output elsewhere";
  }
  return {};
}

std::string fileIdentityKey(const std::string& path) {
  const FileIdentity id = identityOf(path);
  if (id.exists) return "inode " + std::to_string(id.device) + ":" + std::to_string(id.inode);
  return "name " + id.canonical;
}

void checkDistinctOutputs(const std::vector<NamedOutput>& outputs) {
  std::vector<FileIdentity> ids;
  ids.reserve(outputs.size());
  for (const NamedOutput& output : outputs) ids.push_back(identityOf(output.path));
  // Sorted by name, then each against its neighbours of that name, and the
  // existing ones by inode: n log n for a turntable's thousands of frames.
  std::vector<std::size_t> order(outputs.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  const auto refuse = [&](std::size_t a, std::size_t b) {
    if (a > b) std::swap(a, b);
    const std::string how = outputs[a].option == outputs[b].option ? outputs[a].option + " twice" : outputs[a].option + " and " + outputs[b].option;
    throw Error(shownPath(outputs[b].path) + ": named twice as an output of this command (" + how + "); one would overwrite the other");
  };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return ids[a].canonical < ids[b].canonical; });
  for (std::size_t k = 1; k < order.size(); ++k)
    if (ids[order[k]].canonical == ids[order[k - 1]].canonical) refuse(order[k - 1], order[k]);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::tie(ids[a].exists, ids[a].device, ids[a].inode) < std::tie(ids[b].exists, ids[b].device, ids[b].inode);
  });
  for (std::size_t k = 1; k < order.size(); ++k)
    if (ids[order[k]].exists && sameFile(ids[order[k]], ids[order[k - 1]])) refuse(order[k - 1], order[k]);
}

void checkOutputFile(const std::string& path, const std::vector<std::string>& inputs, MissingFolders missing) {
  const Destination d = inspect(path);
  const std::string shown = shownPath(path);
  if (const std::string same = sameFileAsInput(path, inputs); !same.empty()) throw Error(same);
  if (d.kind == Destination::Stream) {
    if (::access(path.c_str(), W_OK) != 0) throw Error(shown + ": cannot open for writing (" + std::strerror(errno) + ")");
    return;
  }
  if (d.kind == Destination::RegularFile && ::access(d.file.c_str(), W_OK) != 0)
    throw Error(shown + ": cannot write (" + std::strerror(errno) + ")");
  checkCanCreateIn(folderOf(d.file), path, missing);
}

namespace {

// Opens `path` for reading and returns the descriptor and the size of what
// was opened. O_NONBLOCK: a FIFO or a device is not waited on; fstat looks
// at what was opened, not at what the path named a moment before. Throws
// facet::Error naming the path when it cannot be opened or is not a regular
// file.
std::pair<int, std::uint64_t> openRegularFile(const std::string& path, const std::string& shown) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) {
    const int code = errno;
    if (code == ENOENT || code == ENOTDIR) throw Error(shown + ": no such file");
    if (code == EACCES) throw Error(shown + ": cannot open (" + std::strerror(code) + ")");
    throw Error(shown + ": " + describeErrno(code));  // e.g. "too many levels of symbolic links", not "no such file"
  }
  struct stat info {};
  if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
    ::close(fd);
    throw Error(shown + ": not a regular file");
  }
  return {fd, static_cast<std::uint64_t>(info.st_size)};
}

// Up to `most` bytes of the open regular file `fd`, from its start; closes it.
std::string readOpenFile(int fd, std::uint64_t most, const std::string& shown) {
  std::string bytes;
  char chunk[1 << 16];
  while (bytes.size() < most) {
    const auto wanted = static_cast<std::size_t>(std::min<std::uint64_t>(sizeof chunk, most - bytes.size()));
    const ssize_t got = ::read(fd, chunk, wanted);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) {
      const int code = errno;
      ::close(fd);
      throw Error(shown + ": read failed (" + describeErrno(code) + ")");
    }
    if (got == 0) break;
    bytes.append(chunk, static_cast<std::size_t>(got));
  }
  ::close(fd);
  return bytes;
}

}  // namespace

std::string readFile(const std::string& path, std::uint64_t maxBytes) {
  const std::string shown = shownPath(path);
  const auto [fd, size] = openRegularFile(path, shown);
  if (size > maxBytes) {
    ::close(fd);
    throw Error(shown + ": file is " + std::to_string(size) + " bytes, more than the limit of " + std::to_string(maxBytes));
  }
  std::string bytes = readOpenFile(fd, maxBytes + 1, shown);
  if (bytes.size() > maxBytes)  // it grew while read
    throw Error(shown + ": file is more than the limit of " + std::to_string(maxBytes) + " bytes");
  return bytes;
}

std::string readFileStart(const std::string& path, std::uint64_t bytes) {
  const std::string shown = shownPath(path);
  const auto [fd, size] = openRegularFile(path, shown);
  return readOpenFile(fd, std::min(size, bytes), shown);
}

}  // namespace facet
