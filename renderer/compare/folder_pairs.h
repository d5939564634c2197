#pragma once
// Pairing the PNG files of two folders by name.
#include <string>
#include <vector>

namespace facet {

struct FilePair {
  std::string name;          // file name, the same on both sides
  std::string expectedPath;  // empty: only the actual folder has it
  std::string actualPath;    // empty: only the expected folder has it
};

// Every file whose name ends in .png (any case) directly in either folder,
// sorted by name; other files and subfolders are ignored. Throws
// facet::Error naming a folder that cannot be read.
std::vector<FilePair> pairFolderFiles(const std::string& expectedFolder, const std::string& actualFolder);

}  // namespace facet
