#include "output_option.h"

#include <string>

namespace facet {

CLI::Option* refuseEmptyName(CLI::Option* output) {
  return output->check(CLI::Validator(
      [](std::string& name) { return name.empty() ? std::string("an empty file name; give the file or folder to write") : std::string(); },
      ""));
}

}  // namespace facet
