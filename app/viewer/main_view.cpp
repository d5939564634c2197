// facet-view: the window of `facet view`, in an executable of its own so
// that only it links GLFW and X11. `facet view ARGS` runs it as
// `facet view ARGS`, with the same parsing, help and exit codes.
#include "command_main.h"
#include "commands.h"

int main(int argc, char** argv) { return facet::runCommands(argc, argv, {facet::addViewCommand}); }
