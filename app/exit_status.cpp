#include "exit_status.h"

#include <new>

#include "common/error.h"

namespace facet {

void printErrorLine(std::FILE* out, const char* prefix, const char* text, const char* suffix) {
  constexpr int kMaxBytes = 1000;
  std::fputs("facet: ", out);
  std::fputs(prefix, out);
  int n = 0;
  for (; text[n] != '\0' && n < kMaxBytes; ++n) {
    const auto c = static_cast<unsigned char>(text[n]);
    std::fputc(c < 0x20 || c == 0x7f ? ' ' : c, out);
  }
  if (text[n] != '\0') std::fputs("...", out);
  std::fputs(suffix, out);
  std::fputc('\n', out);
}

int reportError(std::exception_ptr error, std::FILE* out) {
  // Most derived first: UsageError is an Error, OutOfMemory a bad_alloc.
  try {
    std::rethrow_exception(error);
  } catch (const UsageError& e) {
    printErrorLine(out, "", e.what());
    return kExitUsage;
  } catch (const Error& e) {
    printErrorLine(out, "", e.what());
    return kExitBadInput;
  } catch (const OutOfMemory& e) {
    printErrorLine(out, "out of memory while ", e.what());
    return kExitInternal;
  } catch (const std::bad_alloc&) {
    printErrorLine(out, "out of memory", "");
    return kExitInternal;
  } catch (const std::exception& e) {
    printErrorLine(out, "internal error: ", e.what());
    return kExitInternal;
  } catch (...) {
    printErrorLine(out, "internal error: an exception that is not a std::exception", "");
    return kExitInternal;
  }
}

}  // namespace facet
