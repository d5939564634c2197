// Output folders: written under a temporary name beside their place, put
// there whole (replacing an older one in one step) or never.
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

#include <doctest/doctest.h>

#include "common/error.h"
#include "common/output_folder.h"
#include "scratch_folder.h"

using namespace facet;
using namespace facet::test;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) { return scratchFolder("folder", name); }

std::string messageOf(const std::function<void()>& run) {
  try {
    run();
  } catch (const Error& e) {
    return e.what();
  }
  return "(nothing thrown)";
}

std::size_t entries(const fs::path& dir) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

}  // namespace

TEST_CASE("a staged folder appears at its place only on commit, and not at all when dropped, nor the parents made for it") {
  const fs::path dir = scratch("staged");
  const fs::path place = dir / "parents" / "made" / "out";
  {
    StagedFolder staged(place.string());
    std::ofstream(fs::path(staged.path()) / "a.txt") << "a";
    CHECK(fs::path(staged.path()).parent_path() == place.parent_path());  // beside it: one file system, one rename
    CHECK(!fs::exists(place));
  }  // dropped, as when a write into it fails
  CHECK(!fs::exists(place));
  CHECK(!fs::exists(dir / "parents"));  // nor the folders made for it
  fs::create_directories(dir / "parents");
  {
    const StagedFolder staged(place.string());
  }
  CHECK(entries(dir / "parents") == 0);  // a folder that was there stays

  {
    const mode_t old = ::umask(027);
    StagedFolder staged(place.string());
    ::umask(old);
    std::ofstream(fs::path(staged.path()) / "a.txt") << "a";
    staged.commit();
  }
  CHECK(readAll(place / "a.txt") == "a");
  struct stat st {};
  REQUIRE(::stat(place.c_str(), &st) == 0);
  CHECK((st.st_mode & 07777) == 0750);  // the umask, not mkdtemp's 0700
  CHECK(entries(place.parent_path()) == 1);
  fs::remove_all(dir);
}

TEST_CASE("a committed folder replaces an older one whole, keeping its mode") {
  const fs::path dir = scratch("replace");
  const fs::path place = dir / "out";
  fs::create_directories(place / "images");
  std::ofstream(place / "images" / "stale.png") << "old";
  std::ofstream(place / "index.html") << "old";
  ::chmod(place.c_str(), 0705);
  {
    StagedFolder staged(place.string());
    std::ofstream(fs::path(staged.path()) / "index.html") << "new";
    CHECK(readAll(place / "index.html") == "old");  // the old one stays until the new one is complete
    staged.commit();
  }
  CHECK(readAll(place / "index.html") == "new");
  CHECK(!fs::exists(place / "images"));  // nothing of the old folder remains in the new
  struct stat st {};
  REQUIRE(::stat(place.c_str(), &st) == 0);
  CHECK((st.st_mode & 07777) == 0705);
  CHECK(entries(dir) == 1);  // the old folder is gone, not left under a temporary name
  fs::remove_all(dir);
}

TEST_CASE("an output folder named '.', '..', '/', a file or one of the inputs is refused before any work") {
  const fs::path dir = scratch("check");
  std::ofstream(dir / "file") << "";
  fs::create_directories(dir / "inputs" / "expected");
  const std::string expected = (dir / "inputs" / "expected").string();
  CHECK(messageOf([] { checkOutputFolder(".", {}); }) == ".: is the current folder; give the output a folder of its own, such as report/");
  CHECK(messageOf([] { checkOutputFolder("./", {}); }) == "./: is the current folder; give the output a folder of its own, such as report/");
  CHECK(messageOf([] { checkOutputFolder("..", {}); }) == "..: is the parent folder; give the output a folder of its own, such as report/");
  CHECK(messageOf([] { checkOutputFolder("/", {}); }) == "/: is the root folder; give the output a folder of its own, such as report/");
  CHECK(messageOf([] { checkOutputFolder("a/..", {}); }) == "a/..: ends in '.' or '..'; give the output a folder of its own, such as report/");
  CHECK(messageOf([] { checkOutputFolder("", {}); }) == "an empty folder name");
  CHECK(messageOf([&] { checkOutputFolder((dir / "file").string(), {}); }) == (dir / "file").string() + ": exists and is not a folder");
  CHECK(messageOf([&] { checkOutputFolder(expected + "/", {expected}); }) == expected + ": is an input of this command; write the output elsewhere");
  CHECK(messageOf([&] { checkOutputFolder(expected + "/../expected", {expected}); }) ==
        expected + "/../expected: is the input " + expected + " under another name; write the output elsewhere");
  CHECK(messageOf([&] { checkOutputFolder((dir / "inputs").string(), {expected}); }) ==
        (dir / "inputs").string() + ": holds the input " + expected + "; write the output elsewhere");
  CHECK(messageOf([&] { checkOutputFolder((dir / "new" / "report").string(), {expected}); }) == "(nothing thrown)");
  CHECK(messageOf([&] { checkOutputFolder((dir / "file" / "report").string(), {}); }) == (dir / "file" / "report").string() + ": not a directory");
  CHECK(!fs::exists(dir / "new"));  // a check creates nothing
  fs::remove_all(dir);
}
