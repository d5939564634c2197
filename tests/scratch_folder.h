#pragma once
// Files for tests that write to disk: a fresh folder per test case (so that
// cases and test binaries can run in parallel) and a whole file read back.
#include <filesystem>
#include <string>

namespace facet::test {

// An empty folder under the temporary directory, named for the test file
// (`group`), the case and this process; what an earlier run left is removed.
std::filesystem::path scratchFolder(const std::string& group, const std::string& name);

// The bytes of a file ("" when it cannot be read).
std::string readAll(const std::filesystem::path& path);

}  // namespace facet::test
