// SIGTERM and SIGINT sent to `facet render` and `facet diff -o report/` at
// many moments, above all while the output is being written: afterwards the
// folder holds no temporary file or folder, and the output is either absent
// or complete (a PNG that decodes to the full size, a report with its page
// and every image).
//   interrupt_outputs FACET WORKDIR
// The moment that matters is found, not guessed: inotify reports the
// temporary name as it is created, and the signal goes out then. Rounds
// at random moments cover the rest (loading, rendering, encoding).
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <sys/inotify.h>
#include <sys/wait.h>
#include <unistd.h>

#include "common/error.h"
#include "image/png.h"

namespace fs = std::filesystem;

namespace {

constexpr int kSide = 1024;  // a PNG of about a megabyte: its write and fsync take a while
constexpr int kReportCases = 40;

struct Run {
  int status = 0;
  bool sawTemporary = false;  // the temporary name appeared before the signal went out
  double seconds = 0;
  double temporaryAt = -1;  // seconds from the start to the temporary name's creation, when it was seen
  double finalAt = -1;      // seconds from the start to the first rename into the watched folder
};

// Runs `args`; sends `signal` when a name starting with `prefix` is created
// in `watched` (after `extraDelay`), or after `delay` when prefix is empty;
// signal 0: never.
Run runAndInterrupt(const std::vector<std::string>& args, const fs::path& watched, const std::string& prefix, int signal,
                    std::chrono::microseconds delay, std::chrono::microseconds extraDelay) {
  const int notify = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (notify < 0 || ::inotify_add_watch(notify, watched.c_str(), IN_CREATE | IN_MOVED_TO) < 0) throw std::runtime_error("inotify failed");
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    // Whatever the test runner ignores, facet starts with the defaults.
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1);
    ::dup2(null, 2);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  Run run;
  bool sent = signal == 0;
  for (;;) {
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) {
      run.status = status;
      break;
    }
    if (!sent && prefix.empty() && std::chrono::steady_clock::now() - start >= delay) {
      ::kill(pid, signal);
      sent = true;
    }
    pollfd p{notify, POLLIN, 0};
    if (::poll(&p, 1, 1) > 0) {
      alignas(inotify_event) char buffer[4096];
      const ssize_t n = ::read(notify, buffer, sizeof buffer);
      for (ssize_t at = 0; at < n;) {
        const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
        const std::string name = event->len > 0 ? event->name : "";
        const double now = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if ((event->mask & IN_MOVED_TO) && run.finalAt < 0) run.finalAt = now;
        const bool matches = (event->mask & IN_CREATE) && !prefix.empty() && name.rfind(prefix, 0) == 0;
        if (matches && run.temporaryAt < 0) run.temporaryAt = now;
        if (!sent && matches) {
          std::this_thread::sleep_for(extraDelay);
          run.sawTemporary = true;
          ::kill(pid, signal);
          sent = true;
        }
        at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
      }
    }
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ::close(notify);
  return run;
}

// Everything in `dir` whose name starts with '.': what an interrupted run left behind.
std::vector<std::string> hidden(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.path().filename().string().starts_with(".")) out.push_back(entry.path().string());
  return out;
}

// How long the uninterrupted diff spent writing its report.
double reportWriting(const Run& run) {
  return run.temporaryAt >= 0 && run.finalAt >= run.temporaryAt ? run.finalAt - run.temporaryAt : 0;
}

bool endedAsExpected(const Run& run, int signal) {
  if (WIFEXITED(run.status) && WEXITSTATUS(run.status) == 0) return true;  // done before the signal
  return WIFSIGNALED(run.status) && WTERMSIG(run.status) == signal;       // ended by it, as with no handler
}

int failures = 0;
void fail(const std::string& what) {
  std::fprintf(stderr, "FAIL: %s\n", what.c_str());
  ++failures;
}

void checkPng(const fs::path& png, const std::string& round) {
  if (!fs::exists(png)) return;
  try {
    const facet::Image image = facet::readPng(png.string());
    if (image.width() != kSide || image.height() != kSide) fail(round + ": " + png.string() + " has the wrong size");
  } catch (const facet::Error& e) {
    fail(round + ": " + png.string() + " is not a complete PNG: " + e.what());
  }
}

void checkReport(const fs::path& report, const std::string& round) {
  if (!fs::exists(report)) return;
  std::size_t images = 0;
  if (fs::is_directory(report / "images"))
    for (const auto& entry : fs::directory_iterator(report / "images")) images += entry.path().extension() == ".png" ? 1 : 0;
  std::ifstream in(report / "index.html");
  const std::string page((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (page.find("</html>") == std::string::npos || images != 3 * kReportCases)
    fail(round + ": " + report.string() + " is incomplete (" + std::to_string(images) + " images)");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: interrupt_outputs FACET WORKDIR\n");
    return 2;
  }
  const std::string facet = fs::absolute(argv[1]).string();
  const fs::path work = fs::absolute(argv[2]);
  fs::remove_all(work);
  fs::create_directories(work / "render");
  fs::create_directories(work / "diff" / "e");
  fs::create_directories(work / "diff" / "a");
  for (int i = 0; i < kReportCases; ++i) {
    facet::Image e(96, 96, {10, 20, 40, 255}), a = e;
    a.at(i % 96, 0) = {200, 20, 40, 255};
    char name[32];
    std::snprintf(name, sizeof name, "case%02d.png", i);
    facet::writePng((work / "diff" / "e" / name).string(), e);
    facet::writePng((work / "diff" / "a" / name).string(), a);
  }
  const fs::path png = work / "render" / "out.png";
  const fs::path report = work / "diff" / "report";
  const std::vector<std::string> render = {facet, "render", "--backend", "cpu", "--size", std::to_string(kSide) + "x" + std::to_string(kSide),
                                           "-o", png.string()};
  const std::vector<std::string> diff = {facet, "diff", (work / "diff" / "e").string(), (work / "diff" / "a").string(), "-o", report.string()};

  // One whole run of each first: how long the random moments may be.
  const Run whole = runAndInterrupt(render, work / "render", "", 0, {}, {});
  if (!WIFEXITED(whole.status) || WEXITSTATUS(whole.status) != 0) fail("an uninterrupted render failed");
  const Run wholeDiff = runAndInterrupt(diff, work / "diff", ".report.", 0, {}, {});
  if (!WIFEXITED(wholeDiff.status) || WEXITSTATUS(wholeDiff.status) != 2) fail("an uninterrupted diff did not end in FAILURE (2)");
  checkPng(png, "whole");
  checkReport(report, "whole");

  std::mt19937 random(12345);
  int renderHits = 0, reportHits = 0;
  for (int round = 0; round < 6; ++round) {
    const int signal = round % 2 ? SIGINT : SIGTERM;
    const bool atWrite = round % 3 != 2;  // two rounds in three while the output is written
    const std::string name = "render round " + std::to_string(round) + (atWrite ? " (at the write)" : " (at a random moment)");
    const auto delay = std::chrono::microseconds(static_cast<long>(random() % static_cast<unsigned>(whole.seconds * 1.1e6 + 1)));
    const bool keepOld = round % 4 == 3;  // sometimes an older output is there to be replaced
    if (!keepOld) fs::remove(png);
    const Run run = runAndInterrupt(render, work / "render", atWrite ? ".out.png." : "", signal, delay, {});
    if (!endedAsExpected(run, signal)) fail(name + ": ended with status " + std::to_string(run.status));
    for (const std::string& left : hidden(work / "render")) fail(name + ": left " + left);
    checkPng(png, name);
    if (atWrite && run.sawTemporary && WIFSIGNALED(run.status) && (keepOld || !fs::exists(png))) ++renderHits;
  }
  for (int round = 0; round < 4; ++round) {
    const int signal = round % 2 ? SIGINT : SIGTERM;
    const std::string name = "diff round " + std::to_string(round);
    if (round % 3 != 2) fs::remove_all(report);
    // Some time into the report, while its images are being written: within
    // the first 80 % of the write phase of the whole run, from the temporary
    // folder's creation to its rename (not the process's exit, which under a
    // sanitizer may take longer than the write).
    const double writing = reportWriting(wholeDiff);
    // The first round signals as the folder appears, so that one hit does not
    // hang on the draw of random moments.
    const long drawn = static_cast<long>(random() % static_cast<unsigned>(writing * 0.8e6 + 1));
    const auto extra = std::chrono::microseconds(round == 0 ? 0 : drawn);
    const Run run = runAndInterrupt(diff, work / "diff", ".report.", signal, {}, extra);
    if (!endedAsExpected(run, signal) && !(WIFEXITED(run.status) && WEXITSTATUS(run.status) == 2))
      fail(name + ": ended with status " + std::to_string(run.status));
    for (const std::string& left : hidden(work / "diff")) fail(name + ": left " + left);
    checkReport(report, name);
    if (run.sawTemporary && WIFSIGNALED(run.status)) ++reportHits;
  }
  // Without a hit the test would pass with no handler at all.
  if (renderHits == 0) fail("no render was interrupted while its PNG was being written");
  if (reportHits == 0) fail("no diff was interrupted while its report was being written");
  std::printf("whole runs: render %.2f s, diff %.2f s (report written in %.3f s); %d render rounds and %d report rounds interrupted mid-write; %s\n", whole.seconds,
              wholeDiff.seconds, reportWriting(wholeDiff), renderHits, reportHits, failures ? "FAILED" : "nothing left behind");
  return failures == 0 ? 0 : 1;
}
