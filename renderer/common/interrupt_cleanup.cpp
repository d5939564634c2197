#include "common/interrupt_cleanup.h"
#include "vocabulary/limits.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstddef>
#include <cstring>

#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace facet {
namespace {

// A signal handler can reach nothing but process-wide state: the paths it
// removes live in these fixed slots, the one global state of facet, forced
// by the OS's signal interface. Slots, not one path: a report folder is
// guarded while the image file inside it is being written.
constexpr int kSlots = 8;
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

enum SlotState : int { kFree, kFilling, kHeld };

struct Slot {
  std::atomic<int> state{kFree};
  InterruptCleanup::Kind kind = InterruptCleanup::Kind::File;
  char path[kMaxPathBytes] = {};
};
static_assert(std::atomic<int>::is_always_lock_free, "the handler reads the slots' state");

Slot slots[kSlots];

// Removes `name` (relative to the folder `parent`) and, when it is a folder,
// everything in it, with system calls only (async-signal-safe). getdents64
// is read again from the start after each pass, since removing entries while
// reading may skip some.
void removeTree(int parent, const char* name, int depth) {
  if (::unlinkat(parent, name, 0) == 0 || (errno != EISDIR && errno != EPERM)) return;
  const int fd = ::openat(parent, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd >= 0 && depth < 8) {
    alignas(8) char buffer[2048];
    for (int pass = 0; pass < 64; ++pass) {
      bool removed = false;
      ::lseek(fd, 0, SEEK_SET);
      for (;;) {
        const long n = ::syscall(SYS_getdents64, fd, buffer, sizeof buffer);
        if (n <= 0) break;
        for (long at = 0; at < n;) {
          // struct linux_dirent64: d_ino (8), d_off (8), d_reclen (2), d_type (1), d_name.
          unsigned short length = 0;
          std::memcpy(&length, buffer + at + 16, sizeof length);
          const char* entry = buffer + at + 19;
          if (std::strcmp(entry, ".") != 0 && std::strcmp(entry, "..") != 0) {
            removeTree(fd, entry, depth + 1);
            removed = true;
          }
          at += length;
        }
      }
      if (!removed) break;
    }
  }
  if (fd >= 0) ::close(fd);
  ::unlinkat(parent, name, AT_REMOVEDIR);
}

extern "C" void onInterrupt(int signal) {
  const int savedErrno = errno;
  for (Slot& slot : slots) {
    if (slot.state.load() != kHeld) continue;
    if (slot.kind == InterruptCleanup::Kind::File) ::unlink(slot.path);
    else removeTree(AT_FDCWD, slot.path, 0);
  }
  // The default action, so the parent sees death by this signal: it stays
  // pending (blocked while this handler runs) and ends the process on return.
  struct sigaction fallback {};
  fallback.sa_handler = SIG_DFL;
  ::sigemptyset(&fallback.sa_mask);
  ::sigaction(signal, &fallback, nullptr);
  ::raise(signal);
  errno = savedErrno;
}

void installHandler() {
  for (const int signal : kSignals) {
    struct sigaction current {};
    if (::sigaction(signal, nullptr, &current) != 0) continue;
    if (current.sa_handler != SIG_DFL || (current.sa_flags & SA_SIGINFO)) continue;  // ours, the program's, or ignored
    struct sigaction handler {};
    handler.sa_handler = onInterrupt;
    ::sigemptyset(&handler.sa_mask);
    for (const int other : kSignals) ::sigaddset(&handler.sa_mask, other);  // one cleanup at a time
    handler.sa_flags = SA_RESTART;
    ::sigaction(signal, &handler, nullptr);
  }
}

}  // namespace

InterruptCleanup::InterruptCleanup(const std::string& path, Kind kind) {
  if (path.empty() || path.size() >= kMaxPathBytes || path.find('\0') != std::string::npos) return;
  installHandler();
  for (int i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (!slots[i].state.compare_exchange_strong(expected, kFilling)) continue;
    slots[i].kind = kind;
    std::memcpy(slots[i].path, path.c_str(), path.size() + 1);
    slots[i].state.store(kHeld);
    slot_ = i;
    return;
  }
}

InterruptCleanup::~InterruptCleanup() { release(); }

void InterruptCleanup::release() {
  if (slot_ < 0) return;
  slots[slot_].state.store(kFree);
  slot_ = -1;
}

}  // namespace facet
