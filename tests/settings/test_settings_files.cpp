// The files a RenderSettings names are its string fields that are not text:
// what `facet batch --resume` hashes besides the scene's own files.
#include <doctest/doctest.h>

#include "settings/settings_files.h"

using namespace facet;

TEST_CASE("namedFiles lists every file the settings name, and no text") {
  RenderSettings settings;
  CHECK(namedFiles(settings).empty());  // the default volume.transfer "grey" is text, not a file
  settings.material.bumpMap = "bumps.png";
  settings.environment.map = "sky.png";
  settings.volume.file = "head.nii.gz";
  settings.volume.transfer = "0 0 0 0 0, 1 1 1 1 1";
  Emitter emitter;
  emitter.sprite = "spark.png";
  settings.particles = {Emitter{}, emitter};
  const std::vector<std::string> files = namedFiles(settings);
  CHECK(files == std::vector<std::string>{"bumps.png", "sky.png", "spark.png", "head.nii.gz"});  // field-table order
}
