// readNrrd: NRRD volumes (.nrrd, .nhdr) through teem, checked before the samples are read.
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include <teem/nrrd.h>
#include <zlib.h>

#include "common/atomic_file.h"
#include "common/error.h"
#include "common/quote.h"
#include "scene/memory_budget.h"
#include "settings/render_settings.h"
#include "volume/load_volume.h"
#include "volume/volume_file.h"
#include "vocabulary/limits.h"

// teem's gzip stream (nrrd/gzio.c): exported by libteem, declared only in
// its private header. Only zlib's gzFile type comes from zlib.h.
extern "C" {
gzFile _nrrdGzOpen(FILE* fd, const char* mode);
int _nrrdGzClose(gzFile file);
int _nrrdGzRead(gzFile file, void* buf, unsigned int len, unsigned int* didread);
}

namespace facet {
namespace {

// How much of teem's message an error line keeps.
constexpr std::size_t kMaxTeemMessage = 240;

// teem's reading state and array, released on every way out.
class TeemNrrd {
 public:
  TeemNrrd() : nrrd_(nrrdNew()), io_(nrrdIoStateNew()) {}
  ~TeemNrrd() {
    if (io_) {
      airFclose(io_->dataFile);  // kept open for the samples (airFclose leaves stdin alone)
      io_->dataFile = nullptr;
      nrrdIoStateNix(io_);
    }
    if (nrrd_) nrrdNuke(nrrd_);
  }
  TeemNrrd(const TeemNrrd&) = delete;
  TeemNrrd& operator=(const TeemNrrd&) = delete;
  Nrrd* nrrd() const { return nrrd_; }
  NrrdIoState* io() const { return io_; }

 private:
  Nrrd* nrrd_;
  NrrdIoState* io_;
};

// teem reports through biff, outermost call first:
//   [nrrd] nrrdLoad: trouble reading "a.nrrd"
//   [nrrd] _nrrdFormatNRRD_read: trouble parsing sizes info |2 2 x|
//   [nrrd] _nrrdSizeCheck: axis 2 size is zero!
// One line keeps the field being parsed and the innermost reason:
// "sizes: axis 2 size is zero!".
std::string teemProblem() {
  if (!biffCheck(NRRD)) return "teem cannot read it";  // biffGetDone would warn on stderr
  char* raw = biffGetDone(NRRD);
  const std::string text = raw ? raw : "";
  std::free(raw);
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    if (line.rfind("[nrrd] ", 0) == 0) line.erase(0, 7);
    const std::size_t colon = line.find(": ");  // after the function's name
    if (colon != std::string::npos && line.find(' ') > colon) line.erase(0, colon + 2);
    if (!line.empty() && line != "trouble" && line != ":") lines.push_back(line);
    start = end + 1;
  }
  if (lines.empty()) return "teem cannot read it";
  std::string field;
  for (const std::string& line : lines) {
    constexpr std::string_view kParsing = "trouble parsing ";
    const std::size_t info = line.find(" info");
    if (line.rfind(kParsing, 0) == 0 && info != std::string::npos) field = line.substr(kParsing.size(), info - kParsing.size()) + ": ";
  }
  std::string problem = field + lines.back();
  for (char& c : problem)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
  if (problem.size() > kMaxTeemMessage) problem = problem.substr(0, kMaxTeemMessage) + "...";
  return problem;
}

// teem keeps its messages (biff) and its readers' state in process globals, so
// one NRRD file is read at a time in the process: batch's workers load volumes
// side by side, and two ASCII reads at once corrupted teem's memory.
std::mutex& teemLock() {
  static std::mutex lock;
  return lock;
}

// Drops what teem has said so far: biff keeps messages until they are taken,
// and a later teemProblem() would report them as this file's.
void discardTeemMessages() {
  if (biffCheck(NRRD)) std::free(biffGetDone(NRRD));
}

std::string lowerCase(std::string_view text) {
  std::string lower(text);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower;
}

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
  return text;
}

// teem answers a size of -4 or 2^64 with "axis 0 size is zero!", which
// is not what is wrong: each size is checked here as written, a whole
// number from 1 to 2^31 - 1.
void checkSizes(std::string_view sizes, const std::string& shown) {
  std::size_t axis = 0;
  while (!sizes.empty()) {
    const std::size_t end = std::min(sizes.find_first_of(" \t"), sizes.size());
    const std::string_view size = sizes.substr(0, end);
    sizes = trimmed(sizes.substr(end));
    const bool digits = !size.empty() && size.find_first_not_of("0123456789") == std::string_view::npos;
    if (!digits || size.size() > 10 || std::stoull(std::string(size)) < 1 || std::stoull(std::string(size)) > 2147483647ull)
      throw Error(shown + ": sizes: axis " + std::to_string(axis) + " has " + quoteInput(size) + " samples, not a whole number from 1 to 2147483647");
    ++axis;
  }
}

// Looks at the header before teem does: the magic, the header's length, its
// sizes, and its "data file" field, so that teem never parses an endless line, reads
// standard input, or walks a numbered list of thousands of data files.
void checkHeaderText(const std::string& path, const std::string& shown) {
  const std::string head = readFileStart(path, kMaxNrrdHeaderBytes + 1);  // never waits on a FIFO
  if (head.rfind("NRRD000", 0) != 0) {
    if (head.size() >= 2 && static_cast<unsigned char>(head[0]) == 0x1f && static_cast<unsigned char>(head[1]) == 0x8b)
      throw Error(shown + ": not a NRRD file but gzip data (NRRD compresses its samples, not the header: use encoding: gzip)");
    throw Error(shown + ": not a NRRD file (it does not start with NRRD000)");
  }
  bool ended = false;
  std::size_t start = 0;
  while (start < head.size()) {
    const std::size_t newline = head.find('\n', start);
    if (newline == std::string::npos) break;  // a last line without its newline: only a detached header may end so
    std::string_view line(head.data() + start, newline - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    start = newline + 1;
    if (line.empty()) {
      ended = true;
      break;
    }
    const std::size_t colon = line.find(':');
    if (colon == std::string_view::npos || line[0] == '#' || (colon + 1 < line.size() && line[colon + 1] == '=')) continue;
    const std::string key = lowerCase(trimmed(line.substr(0, colon)));
    const std::string_view value = trimmed(line.substr(colon + 1));
    if (key == "sizes") {
      checkSizes(value, shown);
      continue;
    }
    if (key != "data file" && key != "datafile") continue;
    if (value == "-") throw Error(shown + ": data file '-' (standard input) is not read");
    if (value.rfind("LIST", 0) == 0 || value.find_first_of(" \t") != std::string_view::npos)
      throw Error(shown + ": samples split over several data files are not supported (one data file)");
    // teem opens it with a blocking read: a FIFO there would wait forever.
    // A relative name is relative to the header's folder, as teem reads it.
    const std::filesystem::path data(value);
    const std::filesystem::path dataPath = data.is_absolute() ? data : std::filesystem::path(path).parent_path() / data;
    requireRegularFile(dataPath.string(), shown + ": its data file " + shownPath(std::string(value)));
  }
  if (!ended && head.size() > kMaxNrrdHeaderBytes) throw Error(shown + ": header longer than " + byteCount(kMaxNrrdHeaderBytes));
}

// teem's sample types: those of facet's table (volume/volume_file.h), and
// the block type, which has no fixed layout.
SampleType nrrdSampleType(int type) {
  switch (type) {
    case nrrdTypeChar: return sampleType(SampleKind::Int8);
    case nrrdTypeUChar: return sampleType(SampleKind::UInt8);
    case nrrdTypeShort: return sampleType(SampleKind::Int16);
    case nrrdTypeUShort: return sampleType(SampleKind::UInt16);
    case nrrdTypeFloat: return sampleType(SampleKind::Float32);
    case nrrdTypeInt: return sampleType(SampleKind::Int32);
    case nrrdTypeUInt: return sampleType(SampleKind::UInt32);
    case nrrdTypeLLong: return sampleType(SampleKind::Int64);
    case nrrdTypeULLong: return sampleType(SampleKind::UInt64);
    case nrrdTypeDouble: return sampleType(SampleKind::Float64);
    case nrrdTypeBlock: return {"block"};
    default: return {"unknown"};  // teem knows no other
  }
}

// The distance between samples along an axis: "spacings", else the length of
// its "space directions" vector, else 1.
double axisSpacing(const Nrrd& nrrd, int axis) {
  const NrrdAxisInfo& info = nrrd.axis[axis];
  if (!std::isnan(info.spacing)) return info.spacing;
  if (nrrd.spaceDim > 0 && !std::isnan(info.spaceDirection[0])) {
    double squares = 0.0;
    for (unsigned i = 0; i < nrrd.spaceDim && i < NRRD_SPACE_DIM_MAX; ++i) squares += info.spaceDirection[i] * info.spaceDirection[i];
    return std::sqrt(squares);
  }
  return 1.0;
}

// gzip-encoded samples through teem's gzip stream, the one its gzip
// encoding reads with, but closed on every path: the encoding's reader
// leaks the stream whenever the data is truncated or corrupt. `skip`
// decompressed bytes come first, as "byte skip" means for compressed data.
void readGzip(FILE* data, long skip, unsigned char* out, std::size_t count, const std::string& what) {
  const long position = std::ftell(data);
  unsigned char magic[2] = {};
  if (position < 0 || ::pread(fileno(data), magic, 2, position) != 2 || magic[0] != 0x1f || magic[1] != 0x8b)
    throw Error(what + ": the data is not gzip data");
  const auto close = [](gzFile stream) {
    _nrrdGzClose(stream);
    discardTeemMessages();  // closing a failed stream adds teem's complaint
  };
  const std::unique_ptr<gzFile_s, decltype(close)> gz(_nrrdGzOpen(data, "rb"), close);
  if (!gz) throw Error(what + ": " + teemProblem());
  const auto read = [&](unsigned char* into, std::size_t n) {
    unsigned got = 0;
    return _nrrdGzRead(gz.get(), into, static_cast<unsigned>(n), &got) == 0 && got == n;
  };
  const std::string truncated = what + ": truncated or corrupt gzip data (" + std::to_string(count) + " bytes expected)";
  constexpr std::size_t kChunk = std::size_t{1} << 20;
  std::vector<unsigned char> skipped(std::min<std::size_t>(kChunk, static_cast<std::size_t>(std::max(skip, 0L))));
  for (long done = 0; done < skip;) {
    const std::size_t n = std::min(skipped.size(), static_cast<std::size_t>(skip - done));
    if (!read(skipped.data(), n)) throw Error(truncated);
    done += static_cast<long>(n);
  }
  for (std::size_t done = 0; done < count;) {
    const std::size_t n = std::min(kChunk, count - done);
    if (!read(out + done, n)) throw Error(truncated);
    done += n;
  }
}

}  // namespace

Volume readNrrd(const std::string& path) {
  const std::string shown = shownPath(path);
  requireRegularFile(path, shown);
  checkHeaderText(path, shown);

  // The header, with the data file opened and positioned but not read:
  // the samples are checked and priced first.
  const std::lock_guard<std::mutex> oneAtATime(teemLock());
  discardTeemMessages();
  TeemNrrd teem;
  if (!teem.nrrd() || !teem.io()) throw Error(shown + ": teem cannot start reading");
  NrrdIoState& io = *teem.io();
  io.skipData = AIR_TRUE;
  io.keepNrrdDataFileOpen = AIR_TRUE;
  const std::string teemPath = path == "-" ? "./-" : path;  // teem reads "-" as standard input
  if (nrrdLoad(teem.nrrd(), teemPath.c_str(), &io)) throw Error(shown + ": " + teemProblem());
  const Nrrd& nrrd = *teem.nrrd();

  if (nrrd.dim != 3) throw Error(shown + ": " + countOf(nrrd.dim, "axis", "axes") + ", a volume has 3");
  const SampleType type = nrrdSampleType(nrrd.type);
  if (!type.toFloat) throw Error(shown + ": " + type.name + " samples are not supported (" + readSampleTypeNames() + " are)");
  Volume volume;
  volume.source = path;
  std::string dims;
  for (int a = 0; a < 3; ++a) {
    const std::size_t n = nrrd.axis[a].size;
    if (n < 2) throw Error(shown + ": " + countOf(n, "sample") + " along " + kAxisNames[a] + ", a volume needs at least 2");
    if (n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
      throw Error(shown + ": " + std::to_string(n) + " samples along " + kAxisNames[a] + " are more than facet indexes");
    volume.size[a] = static_cast<int>(n);
    if (a) dims += 'x';
    dims += std::to_string(n);
    const double spacing = axisSpacing(nrrd, a);
    if (!(std::isfinite(spacing) && spacing > 0.0 && spacing <= std::numeric_limits<float>::max()))
      throw Error(shown + ": spacing along " + kAxisNames[a] + " is " + shownNumber(spacing) + ", not a positive number");
    volume.spacing[a] = static_cast<float>(spacing);
  }
  requireBoundedBox(volume, shown);
  const std::string samples = dims + " " + type.name + " samples";

  // Priced before anything is allocated: the floats kept and the file's samples read first.
  const std::uint64_t count = static_cast<std::uint64_t>(volume.size.x) * static_cast<std::uint64_t>(volume.size.y);  // < 2^62
  const std::uint64_t perSample = sizeof(float) + type.bytes;
  if (count > std::numeric_limits<std::uint64_t>::max() / perSample / static_cast<std::uint64_t>(volume.size.z))
    throw Error(shown + ": " + samples + " need more than the scene budget of " + byteCount(kSceneMemoryBudget));  // bytes past 2^64
  const std::uint64_t total = count * static_cast<std::uint64_t>(volume.size.z);
  MemoryBudget budget(kSceneMemoryBudget, "scene budget");
  budget.charge(total * perSample, shown + ": " + samples);
  const std::size_t fileBytes = static_cast<std::size_t>(total * type.bytes);

  FILE* data = io.dataFile;
  if (!data) throw Error(shown + ": teem opened no data file");
  const bool detached = io.dataFNArr && io.dataFNArr->len > 0;
  const std::string dataName = detached && io.dataFN && io.dataFN[0] ? "its data file " + shownPath(io.dataFN[0]) : "the file";
  struct stat info {};
  if (fstat(fileno(data), &info) != 0 || !S_ISREG(info.st_mode)) throw Error(shown + ": " + dataName + " is not a regular file");
  if (io.encoding == nrrdEncodingBzip2)  // teem's bzip2 reader leaks its stream on every error, as its gzip reader does
    throw Error(shown + ": bzip2 encoding is not supported (raw, gzip, ascii and hex are)");
  if (io.byteSkip < 0 && io.encoding->isCompression)
    throw Error(shown + ": byte skip " + std::to_string(io.byteSkip) + " with " + io.encoding->name + " encoding is not supported");

  std::vector<unsigned char> bytes(fileBytes);
  if (io.encoding == nrrdEncodingRaw) {
    // Raw samples are counted against the file before reading: what is left
    // after the header (or the skipped bytes) must be exactly the samples
    // (a negative byte skip deliberately leaves bytes after them).
    const long position = std::ftell(data);
    const std::uint64_t remaining = position >= 0 && info.st_size > position ? static_cast<std::uint64_t>(info.st_size - position) : 0;
    if (remaining < fileBytes || (io.byteSkip >= 0 && remaining != fileBytes))
      throw Error(shown + ": " + samples + " need " + std::to_string(fileBytes) + " bytes, " + dataName + " holds " + std::to_string(remaining));
    if (std::fread(bytes.data(), 1, fileBytes, data) != fileBytes) throw Error(shown + ": read failed (" + describeErrno(errno) + ")");
  } else if (io.encoding == nrrdEncodingGzip) {
    readGzip(data, io.byteSkip, bytes.data(), fileBytes, shown + ": " + samples + " in gzip encoding");
  } else if (io.encoding->read(data, bytes.data(), static_cast<std::size_t>(total), teem.nrrd(), &io)) {
    throw Error(shown + ": " + samples + " in " + io.encoding->name + " encoding: " + teemProblem());
  }

  const bool swap = type.bytes > 1 && io.encoding->endianMatters && io.endian != airEndianUnknown && io.endian != airMyEndian();
  volume.values.resize(static_cast<std::size_t>(total));
  type.toFloat(bytes.data(), swap, SampleScale{}, volume.values);
  updateRange(volume);
  return volume;
}

}  // namespace facet
