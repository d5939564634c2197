// Output files: complete or absent, links followed, devices and pipes written
// through (never replaced), modes kept or taken from the umask; the checks a
// command runs on its output before any work; readFile's refusals.
#include <algorithm>
#include <cerrno>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <doctest/doctest.h>

#include "common/atomic_file.h"
#include "common/error.h"
#include "scratch_folder.h"

using namespace facet;
using namespace facet::test;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) { return scratchFolder("common", name); }

void writeText(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

unsigned modeOf(const fs::path& path) {
  struct stat st {};
  REQUIRE(::stat(path.c_str(), &st) == 0);
  return st.st_mode & 07777;
}

bool isCharDevice(const fs::path& path) {
  struct stat st {};
  return ::lstat(path.c_str(), &st) == 0 && S_ISCHR(st.st_mode);
}

// Names in `dir` other than `keep`: temporary files left behind.
std::vector<std::string> othersIn(const fs::path& dir, const std::vector<std::string>& keep) {
  std::vector<std::string> out;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (std::find(keep.begin(), keep.end(), name) == keep.end()) out.push_back(name);
  }
  return out;
}

// A device node of the same driver as /dev/null (1, 3) or /dev/full (1, 7),
// made in `dir` where root may make one: a write that wrongly replaced the
// node would replace this copy, never the machine's. Without root the real
// node is used, which a process without root cannot replace.
std::string deviceLike(const fs::path& dir, const char* real, unsigned minor) {
  const fs::path copy = dir / fs::path(real).filename();
  if (::mknod(copy.c_str(), S_IFCHR | 0666, makedev(1, minor)) == 0) return copy.string();
  return real;
}

struct UmaskScope {
  mode_t old;
  explicit UmaskScope(mode_t mask) : old(::umask(mask)) {}
  ~UmaskScope() { ::umask(old); }
};

std::string messageOf(const std::function<void()>& run) {
  try {
    run();
  } catch (const Error& e) {
    return e.what();
  }
  return "(nothing thrown)";
}

}  // namespace

TEST_CASE("a new output file gets mode 0666 less the umask") {
  const fs::path dir = scratch("umask");
  {
    const UmaskScope mask(027);
    writeFileAtomically((dir / "a.txt").string(), std::string_view("a"));
  }
  CHECK(modeOf(dir / "a.txt") == 0640);
  {
    const UmaskScope mask(002);
    writeFileAtomically((dir / "b.txt").string(), std::string_view("b"));
  }
  CHECK(modeOf(dir / "b.txt") == 0664);
  CHECK(readAll(dir / "b.txt") == "b");
  fs::remove_all(dir);
}

TEST_CASE("a replaced output file keeps its mode and leaves nothing beside it") {
  const fs::path dir = scratch("mode");
  const fs::path file = dir / "out.png";
  writeText(file, "old");
  ::chmod(file.c_str(), 0600);
  writeFileAtomically(file.string(), std::string_view("new"));
  CHECK(readAll(file) == "new");
  CHECK(modeOf(file) == 0600);
  ::chmod(file.c_str(), 0751);
  writeFileAtomically(file.string(), std::string_view("newer"));
  CHECK(modeOf(file) == 0751);
  CHECK(othersIn(dir, {"out.png"}).empty());
  fs::remove_all(dir);
}

TEST_CASE("an output path that is a symbolic link writes the file it points to and keeps the link") {
  const fs::path dir = scratch("symlink");
  fs::create_directories(dir / "real");
  fs::create_directories(dir / "links");
  writeText(dir / "real" / "target.png", "old");
  ::chmod((dir / "real" / "target.png").c_str(), 0640);
  fs::create_symlink("../real/target.png", dir / "links" / "out.png");  // relative to the link's folder
  fs::create_symlink(dir / "links" / "out.png", dir / "chain.png");     // a link to the link

  writeFileAtomically((dir / "chain.png").string(), std::string_view("new"));
  CHECK(fs::is_symlink(dir / "chain.png"));
  CHECK(fs::is_symlink(dir / "links" / "out.png"));
  CHECK(readAll(dir / "real" / "target.png") == "new");
  CHECK(modeOf(dir / "real" / "target.png") == 0640);
  CHECK(othersIn(dir / "real", {"target.png"}).empty());

  SUBCASE("a dangling link creates the file it names") {
    fs::create_symlink("made.png", dir / "dangling.png");
    writeFileAtomically((dir / "dangling.png").string(), std::string_view("made"));
    CHECK(fs::is_symlink(dir / "dangling.png"));
    CHECK(readAll(dir / "made.png") == "made");
  }
  fs::remove_all(dir);
}

TEST_CASE("a character device is written to, never replaced: /dev/null takes the bytes, /dev/full says it is full") {
  const fs::path dir = scratch("devices");
  const std::string null = deviceLike(dir, "/dev/null", 3);
  const std::string full = deviceLike(dir, "/dev/full", 7);
  writeFileAtomically(null, std::string_view("png bytes"));
  REQUIRE(isCharDevice(null));  // a broken build stops here, before the machine's /dev/null
  CHECK(messageOf([&] { writeFileAtomically(full, std::string_view("png bytes")); }) == full + ": write failed (No space left on device)");
  REQUIRE(isCharDevice(full));
  CHECK(othersIn(dir, {"null", "full"}).empty());

  writeFileAtomically("/dev/null", std::string_view("png bytes"));
  CHECK(isCharDevice("/dev/null"));
  CHECK(messageOf([&] { writeFileAtomically("/dev/full", std::string_view("x")); }) == "/dev/full: write failed (No space left on device)");
  CHECK(isCharDevice("/dev/full"));
  fs::remove_all(dir);
}

TEST_CASE("a named pipe is written to, never replaced") {
  const fs::path dir = scratch("fifo");
  const fs::path fifo = dir / "pipe";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  // The reading end first (non-blocking: nothing waits on anything), then a
  // write that fits the pipe's buffer; a build that replaced the pipe
  // leaves the reader with nothing instead of hanging.
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  REQUIRE(reader >= 0);
  writeFileAtomically(fifo.string(), std::string_view("through the pipe"));
  char buffer[64] = {};
  const ssize_t n = ::read(reader, buffer, sizeof buffer);
  ::close(reader);
  CHECK(std::string(buffer, n > 0 ? static_cast<std::size_t>(n) : 0) == "through the pipe");
  CHECK(fs::is_fifo(fifo));
  fs::remove_all(dir);
}

TEST_CASE("a folder as the output file is refused with a message that says so") {
  const fs::path dir = scratch("folder");
  CHECK(messageOf([&] { writeFileAtomically(dir.string(), std::string_view("x")); }) == dir.string() + ": is a folder; give the name of a file in it");
  CHECK(messageOf([&] { writeFileAtomically(".", std::string_view("x")); }) == ".: is a folder; give the name of a file in it");
  CHECK(messageOf([&] { writeFileAtomically("/", std::string_view("x")); }) == "/: is a folder; give the name of a file in it");
  CHECK(messageOf([&] { checkOutputFile(".", {}); }) == ".: is a folder; give the name of a file in it");
  CHECK(messageOf([&] { writeFileAtomically("", std::string_view("x")); }) == "an empty file name");
  CHECK(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST_CASE("a failed write leaves the old file as it was and no temporary file") {
  const fs::path dir = scratch("failed");
  const fs::path file = dir / "out.png";
  writeText(file, "old");
  // The file-size limit makes write() fail (EFBIG) part way, as a full disk would.
  struct rlimit old {};
  ::getrlimit(RLIMIT_FSIZE, &old);
  const auto previous = std::signal(SIGXFSZ, SIG_IGN);
  struct rlimit small = old;
  small.rlim_cur = 1000;
  REQUIRE(::setrlimit(RLIMIT_FSIZE, &small) == 0);
  const std::string message = messageOf([&] { writeFileAtomically(file.string(), std::string(5000, 'x')); });
  ::setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, previous);
  CHECK(message == file.string() + ": write failed (File too large)");
  CHECK(readAll(file) == "old");
  CHECK(othersIn(dir, {"out.png"}).empty());
  fs::remove_all(dir);
}

TEST_CASE("a loop of symbolic links is named as one, when read and when written") {
  const fs::path dir = scratch("loop");
  fs::create_symlink(dir / "b", dir / "a");
  fs::create_symlink(dir / "a", dir / "b");
  const std::string a = (dir / "a").string();
  CHECK(messageOf([&] { readFile(a, 100); }) == a + ": too many levels of symbolic links");
  CHECK(messageOf([&] { writeFileAtomically(a, std::string_view("x")); }) == a + ": too many levels of symbolic links");
  CHECK(messageOf([&] { checkOutputFile(a, {}); }) == a + ": too many levels of symbolic links");
  // readFile's other refusals stay as they were.
  CHECK(messageOf([&] { readFile((dir / "none").string(), 100); }) == (dir / "none").string() + ": no such file");
  CHECK(messageOf([&] { readFile(dir.string(), 100); }) == dir.string() + ": not a regular file");
  writeText(dir / "big", std::string(200, 'x'));
  CHECK(messageOf([&] { readFile((dir / "big").string(), 100); }) == (dir / "big").string() + ": file is 200 bytes, more than the limit of 100");
  CHECK(readFile((dir / "big").string(), 200) == std::string(200, 'x'));
  fs::remove_all(dir);
}

TEST_CASE("a named pipe or a device is refused as an input as opened, without waiting for a writer") {
  const fs::path dir = scratch("read_fifo");
  const fs::path fifo = dir / "pipe";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  // An open that waited for a writer would wait for ever: SIGALRM ends the
  // test binary instead, a failure ctest reports.
  ::alarm(10);
  CHECK(messageOf([&] { readFile(fifo.string(), 100); }) == fifo.string() + ": not a regular file");
  CHECK(messageOf([&] { readFileStart(fifo.string(), 100); }) == fifo.string() + ": not a regular file");
  CHECK(messageOf([&] { readFile("/dev/zero", 100); }) == "/dev/zero: not a regular file");
  ::alarm(0);
  // The start of a regular file, or all of a shorter one.
  writeText(dir / "text", "NRRD0004\ntype: float\n");
  CHECK(readFileStart((dir / "text").string(), 8) == "NRRD0004");
  CHECK(readFileStart((dir / "text").string(), 1000) == "NRRD0004\ntype: float\n");
  fs::remove_all(dir);
}

TEST_CASE("an output that is one of the command's inputs is refused, whatever it is called") {
  const fs::path dir = scratch("inputs");
  fs::create_directories(dir / "sub");
  const std::string scene = (dir / "s.gltf").string();
  writeText(scene, "{}");
  fs::create_symlink(scene, dir / "link.gltf");
  fs::create_hard_link(scene, dir / "hard.gltf");
  const std::vector<std::string> inputs = {"builtin:default", "", scene};

  CHECK(messageOf([&] { checkOutputFile(scene, inputs); }) == scene + ": is an input of this command; write the output elsewhere");
  for (const std::string& other : {(dir / "link.gltf").string(), (dir / "hard.gltf").string(), (dir / "sub" / ".." / "s.gltf").string()})
    CHECK(messageOf([&] { checkOutputFile(other, inputs); }) == other + ": is the input " + scene + " under another name; write the output elsewhere");
  CHECK(messageOf([&] { checkOutputFile((dir / "out.png").string(), inputs); }) == "(nothing thrown)");
  CHECK(readAll(scene) == "{}");
  fs::remove_all(dir);
}

TEST_CASE("an output's folder is checked before any work") {
  const fs::path dir = scratch("check");
  writeText(dir / "file", "");
  const std::string missing = (dir / "no" / "such" / "out.png").string();
  CHECK(messageOf([&] { checkOutputFile(missing, {}); }) == missing + ": the folder " + (dir / "no" / "such").string() + " does not exist");
  CHECK(messageOf([&] { checkOutputFile(missing, {}, MissingFolders::Created); }) == "(nothing thrown)");
  const std::string underFile = (dir / "file" / "out.png").string();
  CHECK(messageOf([&] { checkOutputFile(underFile, {}); }) == underFile + ": not a directory");
  CHECK(messageOf([&] { checkOutputFile((dir / "file" / "a" / "b.png").string(), {}, MissingFolders::Created); }) ==
        (dir / "file" / "a" / "b.png").string() + ": not a directory");
  CHECK(messageOf([&] { checkOutputFile("/dev/null", {}); }) == "(nothing thrown)");
  CHECK(messageOf([&] { checkOutputFile((dir / "new.png").string(), {}); }) == "(nothing thrown)");
  CHECK(othersIn(dir, {"file"}).empty());  // a check writes nothing
  fs::remove_all(dir);
}
