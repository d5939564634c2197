#pragma once
// The field table as docs/settings.md shows it: one Markdown row per settings key
// (dotted, as --set takes it), its default, its range or choices, and its
// help line. `facet settings --keys` prints it; a test holds docs/settings.md's
// copy to it.
#include <string>

namespace facet {

std::string settingsTable();

}  // namespace facet
