#include "command_main.h"

#include <cstdio>
#include <exception>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "common/error.h"
#include "common/quote.h"
#include "exit_status.h"
#include "one_dash_options.h"

namespace facet {
namespace {

// CLI11 reads a word that names no subcommand as a stray argument and then
// says "A subcommand is required"; the word itself is the problem.
void checkCommandName(CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return;
  std::string names;
  for (const CLI::App* sub : app.get_subcommands({})) {
    if (sub->check_name(argv[1])) return;
    names += (names.empty() ? "" : ", ") + sub->get_name();
  }
  throw UsageError("unknown command " + quoteInput(argv[1]) + " (commands: " + names + "; see facet --help)");
}

int parseAndRun(int argc, char** argv, const std::vector<AddCommand>& adders) {
  CLI::App app{"facet: a course rendering pipeline with an OpenGL backend and a CPU reference"};
  app.name("facet");
  app.set_version_flag("--version", "facet " FACET_VERSION);
  app.require_subcommand(1);
  std::map<CLI::App*, Command> commands;
  for (const AddCommand& add : adders) {
    Command command = add(app);
    commands[app.get_subcommands({}).back()] = std::move(command);
  }
  app.footer(
      "Exit codes: 0 success (facet diff: idiff's 0-4, see facet diff --help), 1 bad input (a file, a frame), 64 a wrong "
      "command line, 70 an internal error or out of memory.");

  checkCommandName(app, argc, argv);
  // facet diff also takes idiff's one-dash spellings (-fail 0.004).
  std::vector<std::string> words(argv + 1, argv + argc);
  if (!words.empty() && words[0] == "diff")
    for (const CLI::App* command : app.get_subcommands({}))
      if (command->get_name() == "diff") words = withOneDashLongOptions(*command, std::move(words));
  std::vector<char*> rewritten = {argv[0]};
  for (std::string& word : words) rewritten.push_back(word.data());
  rewritten.push_back(nullptr);
  try {
    app.parse(static_cast<int>(words.size()) + 1, rewritten.data());
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // 64 (EX_USAGE): distinct from `facet diff`'s 1 (warning) and 2 (failure).
    printErrorLine(stderr, "", e.what(), " (see facet --help)");
    return kExitUsage;
  }
  for (auto& [subcommand, command] : commands)
    if (subcommand->parsed()) return command();
  throw std::logic_error("the command line parsed, but no command ran");  // require_subcommand(1) rules it out
}

}  // namespace

const char* facetVersion() { return FACET_VERSION; }

int runCommands(int argc, char** argv, const std::vector<AddCommand>& commands) {
#if FACET_NEEDS_FMA
  // The rasterizer's sources are built with -mfma where the building CPU has
  // it (FACET_CPU_FMA): on a CPU without it that code would die of SIGILL.
  // This file is built without it, so the check runs before any such code.
  if (!__builtin_cpu_supports("fma")) {
    printErrorLine(stderr, "", "this facet was built with FMA instructions (FACET_CPU_FMA=ON) and this CPU has none: build it with -DFACET_CPU_FMA=OFF");
    return kExitInternal;
  }
#endif
  // Every exception a command lets through ends here, as one line and an
  // exit code (app/exit_status.h): bad input 1 or 64, anything else 70.
  try {
    return parseAndRun(argc, argv, commands);
  } catch (...) {
    return reportError(std::current_exception(), stderr);
  }
}

}  // namespace facet
