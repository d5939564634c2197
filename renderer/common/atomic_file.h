#pragma once
// Output files that are complete or absent, and input files read whole.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace facet {

// Writes `bytes` to the file `path` names without ever leaving a partial or
// damaged file there:
//  - a regular file (new or existing) is written into a temporary file beside
//    it (.NAME.XXXXXX, removed on failure and on SIGINT/SIGTERM/SIGHUP:
//    common/interrupt_cleanup.h), flushed to disk, then renamed over it;
//  - a symbolic link is followed: the file it points to is replaced, the link
//    stays;
//  - a new file gets mode 0666 less the umask; a replaced one keeps its mode
//    (and, where allowed, its owner and group);
//  - a character device or a pipe (/dev/null, /dev/stdout) is written to, never
//    replaced; a folder or any other kind of file is refused.
// Throws facet::Error with one line naming the path and the problem, e.g.
// "/dev/full: write failed (No space left on device)".
void writeFileAtomically(const std::string& path, std::span<const std::uint8_t> bytes);
void writeFileAtomically(const std::string& path, std::string_view text);

// Whether a missing folder on the way to an output is an error or is created
// by the command before it writes.
enum class MissingFolders { Refuse, Created };

// Checks, before any work, that writeFileAtomically(path) can succeed: path is
// not empty, not a folder, not a kind of file it refuses, its folder exists
// (or, with MissingFolders::Created, the nearest existing one is a folder)
// and is writable, and path is not the same file as any of `inputs` (device
// and inode when both exist, whatever the spelling or links; otherwise the
// canonical names, so that an output not written yet is caught too). Throws facet::Error naming the path and the problem.
void checkOutputFile(const std::string& path, const std::vector<std::string>& inputs,
                     MissingFolders missing = MissingFolders::Refuse);

// The error message of `path` refused for being one of `inputs` (an empty
// string when it is none of them): shared by file and folder outputs.
std::string sameFileAsInput(const std::string& path, const std::vector<std::string>& inputs);

// An output of a command and the option that names it ("-o", "--shadow-report").
struct NamedOutput {
  std::string path;
  std::string option;
};

// A key equal for two paths exactly when they are one file by the rule of
// checkDistinctOutputs: the device and inode of an existing file, the
// canonical name of one not written yet.
std::string fileIdentityKey(const std::string& path);

// Throws facet::Error when two of `outputs` are one file: the same existing
// file (device and inode), or the same canonical name for one not written
// yet ("out/a.png", "$PWD/out/a.png" and "link/a.png" alike), naming the
// path and both options, before any of them is written.
void checkDistinctOutputs(const std::vector<NamedOutput>& outputs);

// Throws facet::Error naming `output` unless new entries can be made in
// `folder`: it exists (or, with MissingFolders::Created, its nearest
// existing parent does), is a folder and is writable.
void checkCanCreateIn(const std::string& folder, const std::string& output, MissingFolders missing);

// What a write to `path` lands on: symbolic links in its last component
// followed, relative targets taken from the link's folder (a dangling link
// gives the path it would create). Throws facet::Error on a loop of links.
std::string followLinks(const std::string& path);

// The folder part of a path: "a/b" -> "a", "b" -> ".", "/b" -> "/".
std::string folderOf(const std::string& path);

// Reads a whole file; throws facet::Error naming the path when it cannot, when
// it is not a regular file, or when it is larger than maxBytes.
// The file is opened without waiting (O_NONBLOCK) and checked as opened
// (fstat), so a FIFO or a device never blocks the read.
std::string readFile(const std::string& path, std::uint64_t maxBytes);

// The first `bytes` bytes of a regular file (all of a shorter one), opened as
// readFile opens it; throws facet::Error naming the path as it does.
std::string readFileStart(const std::string& path, std::uint64_t bytes);

// A path as an error line shows it: as given when it is printable UTF-8 of a
// sensible length, otherwise quoteInput() (common/quote.h).
std::string shownPath(std::string_view path);
// The same in quotes, for a path inside a sentence: "'out/a.png'"; a path
// shownPath would not show whole is quoteInput's short prefix.
std::string quotedPath(std::string_view path);

// strerror(code) as an error line says it, from a lower-case letter: "no
// space left on device".
std::string describeErrno(int code);

}  // namespace facet
