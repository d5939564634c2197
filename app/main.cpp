// facet: the course's rendering pipeline, headless or in a window.
//   scene file -> Scene -> (OpenGL | CPU) backend -> Image -> comparison
// This executable links no window system: `facet view` runs facet-view.
#include "command_main.h"
#include "commands.h"

int main(int argc, char** argv) {
  return facet::runCommands(argc, argv,
                            {
                                facet::addInfoCommand, facet::addSettingsCommand, facet::addRenderCommand, facet::addDiffCommand,
                                facet::addBenchCommand, facet::addBatchCommand,
#if FACET_HAVE_VIEWER
                                facet::addViewLauncher,
#endif
                            });
}
