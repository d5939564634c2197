// facet: the course's rendering pipeline, headless or in a window.
//   scene file -> Scene -> (OpenGL | CPU) backend -> Image -> comparison
#include <cstdio>
#include <exception>
#include <map>

#include <CLI/CLI.hpp>

#include "commands.h"
#include "common/error.h"

int main(int argc, char** argv) {
  CLI::App app{"facet: a course rendering pipeline with an OpenGL backend and a CPU reference"};
  app.require_subcommand(1);
  std::map<CLI::App*, facet::Command> commands;
  const auto add = [&](facet::Command command) { commands[app.get_subcommands({}).back()] = std::move(command); };
  add(facet::addInfoCommand(app));
  add(facet::addSettingsCommand(app));
  add(facet::addRenderCommand(app));
  add(facet::addDiffCommand(app));
  add(facet::addBenchCommand(app));
#if FACET_HAVE_VIEWER
  add(facet::addViewCommand(app));
#endif

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // 64 (EX_USAGE): distinct from `facet diff`'s 1 (warning) and 2 (failure).
    std::fprintf(stderr, "facet: %s (see facet --help)\n", e.what());
    return 64;
  }
  try {
    for (auto& [subcommand, run] : commands)
      if (subcommand->parsed()) return run();
  } catch (const facet::UsageError& e) {
    std::fprintf(stderr, "facet: %s\n", e.what());
    return 64;
  } catch (const facet::Error& e) {
    std::fprintf(stderr, "facet: %s\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "facet: out of memory\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "facet: internal error: %s\n", e.what());
    return 3;
  }
  return 2;
}
