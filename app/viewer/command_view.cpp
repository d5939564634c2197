// Placeholder until the viewer lands.
#include "commands.h"
#include "common/error.h"

namespace facet {
Command addViewCommand(CLI::App& app) {
  app.add_subcommand("view", "Open the interactive viewer (not yet available)");
  return []() -> int { throw Error("view is not available yet"); };
}
}  // namespace facet
