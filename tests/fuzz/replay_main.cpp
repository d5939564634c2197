// Replays fuzzer inputs (seed corpus and every crash the fuzzers found) through
// a fuzz target in the ordinary test build, so each finding stays a
// regression test even where clang and libFuzzer are not used.
//   replay [--require-sanitizers] FILE_OR_DIR...
// A path that does not exist, a file that cannot be read, or nothing to
// replay fails. With --require-sanitizers (the FACET_SANITIZE build) the
// replay also fails unless it runs under AddressSanitizer and
// UndefinedBehaviorSanitizer, so that CI cannot replay without them.
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

bool builtWithSanitizers() {
#if defined(__SANITIZE_ADDRESS__)
  return true;  // GCC: FACET_SANITIZE adds ASan and UBSan together
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  return true;
#else
  return false;
#endif
#else
  return false;
#endif
}

}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  int first = 1;
  if (argc > 1 && std::strcmp(argv[1], "--require-sanitizers") == 0) {
    first = 2;
    if (!builtWithSanitizers()) {
      std::fprintf(stderr, "replay: built without AddressSanitizer, but --require-sanitizers was given\n");
      return 1;
    }
  }
  int replayed = 0;
  for (int i = first; i < argc; ++i) {
    std::error_code error;
    const bool directory = fs::is_directory(argv[i], error);
    if (!directory && !fs::is_regular_file(argv[i], error)) {
      std::fprintf(stderr, "replay: %s: no such file or folder\n", argv[i]);
      return 1;
    }
    std::vector<fs::path> files;
    if (directory) {
      for (const auto& entry : fs::directory_iterator(argv[i]))
        if (entry.is_regular_file() && entry.path().filename().string().front() != '.') files.push_back(entry.path());
    } else {
      files.emplace_back(argv[i]);
    }
    for (const fs::path& file : files) {
      std::ifstream in(file, std::ios::binary);
      if (!in) {
        std::fprintf(stderr, "replay: %s: cannot be read\n", file.c_str());
        return 1;
      }
      const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
      ++replayed;
    }
  }
  std::printf("replayed %d inputs without a crash%s\n", replayed, builtWithSanitizers() ? " under ASan and UBSan" : "");
  return replayed > 0 ? 0 : 1;
}
