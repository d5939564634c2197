// `facet view` in the headless executable: runs facet-view, which alone
// links GLFW and X11, so that render, diff and bench start on a machine
// without them. The arguments pass through untouched, help included.
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <dlfcn.h>
#include <unistd.h>

#include "commands.h"
#include "common/error.h"
#include "common/quote.h"

namespace facet {
namespace {

namespace fs = std::filesystem;

// Where facet-view sits: beside facet in a build tree, or where
// `cmake --install` puts it relative to facet (FACET_VIEW_FROM_BIN, e.g.
// ../libexec/facet/facet-view).
std::vector<fs::path> viewerCandidates() {
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  if (error) return {};
  const fs::path dir = self.parent_path();
  return {dir / "facet-view", (dir / FACET_VIEW_FROM_BIN).lexically_normal()};
}

// The window's library, checked before the exec so that its absence reads
// as one line of ours, not the dynamic loader's.
void requireWindowLibrary() {
  void* glfw = ::dlopen(FACET_GLFW_SONAME, RTLD_LAZY | RTLD_LOCAL);
  if (glfw == nullptr)
    throw Error(std::string("view: ") + FACET_GLFW_SONAME +
                " is not installed (Debian package libglfw3); every other command works without it");
  ::dlclose(glfw);
}

}  // namespace

Command addViewLauncher(CLI::App& app) {
  CLI::App* command = app.add_subcommand("view", std::string(kViewSummary));
  command->prefix_command();  // everything after `view` is facet-view's: options, positionals, --help
  command->set_help_flag();
  command->footer("Run `facet view --help` for the options (they are facet-view's).");
  return [command]() -> int {
    fs::path viewer;
    std::string looked;
    for (const fs::path& candidate : viewerCandidates()) {
      if (::access(candidate.c_str(), X_OK) == 0) {
        viewer = candidate;
        break;
      }
      looked += (looked.empty() ? "" : ", ") + candidate.string();
    }
    if (viewer.empty()) throw Error("view: the window program facet-view is not installed (looked for " + looked + ")");
    requireWindowLibrary();
    std::vector<std::string> args = {"facet", "view"};
    for (const std::string& arg : command->remaining()) args.push_back(arg);
    std::vector<char*> argv;
    for (std::string& arg : args) argv.push_back(arg.data());
    argv.push_back(nullptr);
    ::execv(viewer.c_str(), argv.data());
    throw Error("view: cannot run " + quoteInput(viewer.string()) + ": " + std::strerror(errno));
  };
}

}  // namespace facet
