// The README's settings table is the field table's: `facet settings --keys`
// prints it, and this holds the README's copy (between its two markers) to
// that output, so a key added, renamed or given a new default cannot leave
// the documentation behind.
#include <string>

#include <doctest/doctest.h>

#include "scratch_folder.h"
#include "settings/settings_table.h"

using namespace facet;

TEST_CASE("the README's settings table is settingsTable(), key for key") {
  const std::string readme = test::readAll(FACET_README);
  const std::string begin = "<!-- settings table: facet settings --keys -->\n", end = "<!-- end of settings table -->";
  const std::size_t from = readme.find(begin), to = readme.find(end);
  REQUIRE(from != std::string::npos);
  REQUIRE(to != std::string::npos);
  const std::string table = settingsTable();
  CHECK(table.find("| `textures.filter` | `auto` | auto, nearest, bilinear, trilinear |") != std::string::npos);
  CHECK(table.find("| `lights.N.kind` | `point` |") != std::string::npos);
  CHECK(readme.substr(from + begin.size(), to - from - begin.size()) == table);
}
