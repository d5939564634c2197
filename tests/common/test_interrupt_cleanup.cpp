// SIGINT, SIGTERM and SIGHUP remove the temporary paths guarded at that
// moment, then end the process as the signal would have. Each case runs in a
// child process: the handler ends it.
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include <doctest/doctest.h>

#include "common/interrupt_cleanup.h"
#include "scratch_folder.h"

using namespace facet;
using namespace facet::test;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) { return scratchFolder("interrupt", name); }

// Runs `body` in a child whose `signal` starts at `action` (the test runner
// handles some signals itself), and returns its wait status.
template <typename Body>
int inChild(int signal, void (*action)(int), Body body) {
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    std::signal(signal, action);
    body();
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

}  // namespace

TEST_CASE("a signal removes the guarded file and folder, keeps released ones, and ends the process by the same signal") {
  for (const int signal : {SIGTERM, SIGINT, SIGHUP}) {
    CAPTURE(signal);
    const fs::path dir = scratch("signal" + std::to_string(signal));
    const int status = inChild(signal, SIG_DFL, [&] {
      std::ofstream(dir / ".out.png.abc123") << "partial";
      fs::create_directories(dir / ".report.xyz" / "images");
      for (int i = 0; i < 300; ++i) std::ofstream(dir / ".report.xyz" / "images" / (std::to_string(i) + ".png")) << i;  // more than one getdents64 read
      std::ofstream(dir / ".report.xyz" / "index.html") << "page";
      std::ofstream(dir / "kept.png") << "done";
      const InterruptCleanup file((dir / ".out.png.abc123").string(), InterruptCleanup::Kind::File);
      const InterruptCleanup folder((dir / ".report.xyz").string(), InterruptCleanup::Kind::Folder);
      InterruptCleanup released((dir / "kept.png").string(), InterruptCleanup::Kind::File);
      released.release();
      ::raise(signal);
      ::_exit(7);  // not reached when the handler re-raises
    });
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == signal);
    CHECK(!fs::exists(dir / ".out.png.abc123"));
    CHECK(!fs::exists(dir / ".report.xyz"));
    CHECK(fs::exists(dir / "kept.png"));
    fs::remove_all(dir);
  }
}

TEST_CASE("a signal the program ignores stays ignored: the guard installs nothing over it") {
  const fs::path dir = scratch("ignored");
  const int status = inChild(SIGTERM, SIG_IGN, [&] {
    std::ofstream(dir / ".tmp") << "partial";
    const InterruptCleanup file((dir / ".tmp").string(), InterruptCleanup::Kind::File);
    ::raise(SIGTERM);
  });
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(fs::exists(dir / ".tmp"));
  fs::remove_all(dir);
}
