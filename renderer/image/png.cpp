#include "image/png.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>

#include <zlib.h>

#include "common/atomic_file.h"
#include "common/error.h"
#include "common/quote.h"

// stb_image decodes: compiled into this file alone (static), PNG only, with
// its allocations counted, because it fails some of them without a reason,
// and an allocation that failed is out of memory, not a corrupt file. It
// reads no CRC and stops at IEND, so the structure of the file (signature,
// chunk lengths, CRCs, IHDR, chunk order, the end) is checked here first,
// and the size the header claims is held to the limit before the decoder
// allocates anything. Writing is facet's own: the three chunks around one
// zlib stream.
namespace {

thread_local bool decoderOutOfMemory = false;

void* decoderMalloc(std::size_t size) {
  void* p = std::malloc(size);
  if (!p) decoderOutOfMemory = true;
  return p;
}

void* decoderRealloc(void* old, std::size_t size) {
  void* p = std::realloc(old, size);
  if (!p && size != 0) decoderOutOfMemory = true;
  return p;
}

}  // namespace

#define STBI_MALLOC(size) decoderMalloc(size)
#define STBI_REALLOC(p, size) decoderRealloc(p, size)
#define STBI_FREE(p) std::free(p)
#define STBI_ASSERT(x) ((x) ? (void)0 : std::abort())  // in release builds too: a broken invariant stops, never reads on
#define STBI_MAX_DIMENSIONS facet::kMaxImageSide
#define STBI_ONLY_PNG
#define STBI_NO_STDIO
#define STBI_NO_LINEAR
#define STBI_NO_HDR
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#pragma GCC diagnostic ignored "-Wpedantic"
#include <stb_image.h>
#pragma GCC diagnostic pop

namespace facet {
namespace {

constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

// Deflate emits at most 258 bytes for 2 bits (a length and a distance code
// of one bit each): no stream inflates to more than 1032 times its size.
constexpr std::uint64_t kMaxInflateRatio = 1032;

// The CRC-32 of ISO 3309 that PNG uses over each chunk's type and data.
constexpr std::array<std::uint32_t, 256> kCrcTable = [] {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t n = 0; n < 256; ++n) {
    std::uint32_t c = n;
    for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xedb88320u ^ (c >> 1) : c >> 1;
    table[n] = c;
  }
  return table;
}();

std::uint32_t crc32(std::string_view bytes) {
  std::uint32_t c = 0xffffffffu;
  for (const char b : bytes) c = kCrcTable[(c ^ static_cast<std::uint8_t>(b)) & 0xffu] ^ (c >> 8);
  return c ^ 0xffffffffu;
}

std::uint32_t bigEndian32(std::string_view bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<std::uint8_t>(bytes[at + i]);
  return v;
}

std::string sizeText(std::uint64_t width, std::uint64_t height) { return std::to_string(width) + "x" + std::to_string(height); }

struct PngHeader {
  std::uint32_t width = 0, height = 0;
  int bitDepth = 0, colorType = 0, interlace = 0;
  std::uint64_t imageDataBytes = 0;  // the IDAT chunks' data, all of them
  bool emptyImageDataChunk = false;   // an IDAT chunk of no bytes (valid, but see withoutEmptyImageData)
  bool transparency = false;          // a tRNS chunk: alpha for a grey, RGB or palette image
};

// Colour types 2 (RGB), 3 (palette of RGB) and 6 (RGBA) have colour; 4 and
// 6 have alpha, and a tRNS chunk gives any other type alpha.
StoredChannels storedChannels(const PngHeader& h) {
  return {h.colorType == 2 || h.colorType == 3 || h.colorType == 6, h.colorType == 4 || h.colorType == 6 || h.transparency};
}

// Samples per pixel of each colour type of the standard; 0: no such type.
int samplesPerPixel(int colorType) {
  switch (colorType) {
    case 0: return 1;  // grey
    case 2: return 3;  // RGB
    case 3: return 1;  // palette index
    case 4: return 2;  // grey + alpha
    case 6: return 4;  // RGBA
    default: return 0;
  }
}

bool bitDepthAllowed(int colorType, int depth) {
  if (colorType == 0) return depth == 1 || depth == 2 || depth == 4 || depth == 8 || depth == 16;
  if (colorType == 3) return depth == 1 || depth == 2 || depth == 4 || depth == 8;
  return depth == 8 || depth == 16;
}

// The bytes the image data must inflate to: each row of each pass (Adam7:
// seven) is one filter byte and its packed samples.
std::uint64_t filteredBytes(const PngHeader& h) {
  const std::uint64_t bitsPerPixel = static_cast<std::uint64_t>(samplesPerPixel(h.colorType)) * static_cast<std::uint64_t>(h.bitDepth);
  const auto rows = [&](std::uint64_t width, std::uint64_t height) { return width == 0 ? 0 : height * (1 + (width * bitsPerPixel + 7) / 8); };
  if (h.interlace == 0) return rows(h.width, h.height);
  static constexpr std::uint32_t kX0[7] = {0, 4, 0, 2, 0, 1, 0}, kY0[7] = {0, 0, 4, 0, 2, 0, 1};
  static constexpr std::uint32_t kDx[7] = {8, 8, 4, 4, 2, 2, 1}, kDy[7] = {8, 8, 8, 4, 4, 2, 2};
  std::uint64_t total = 0;
  for (int p = 0; p < 7; ++p) {
    const std::uint64_t w = h.width > kX0[p] ? (h.width - kX0[p] + kDx[p] - 1) / kDx[p] : 0;
    const std::uint64_t hh = h.height > kY0[p] ? (h.height - kY0[p] + kDy[p] - 1) / kDy[p] : 0;
    total += rows(w, hh);
  }
  return total;
}

void checkHeader(std::string_view data, const std::string& name, PngHeader& h) {
  if (data.size() != 13) throw Error(name + ": corrupt PNG: IHDR holds " + std::to_string(data.size()) + " bytes, not 13");
  h.width = bigEndian32(data, 0);
  h.height = bigEndian32(data, 4);
  h.bitDepth = static_cast<std::uint8_t>(data[8]);
  h.colorType = static_cast<std::uint8_t>(data[9]);
  h.interlace = static_cast<std::uint8_t>(data[12]);
  if (h.width == 0 || h.height == 0 || h.width > INT_MAX || h.height > INT_MAX)
    throw Error(name + ": corrupt PNG: image size " + sizeText(h.width, h.height));
  if (samplesPerPixel(h.colorType) == 0) throw Error(name + ": corrupt PNG: colour type " + std::to_string(h.colorType) + " does not exist");
  if (!bitDepthAllowed(h.colorType, h.bitDepth))
    throw Error(name + ": corrupt PNG: bit depth " + std::to_string(h.bitDepth) + " is not allowed with colour type " + std::to_string(h.colorType));
  if (data[10] != 0 || data[11] != 0 || h.interlace > 1)
    throw Error(name + ": corrupt PNG: unknown compression, filter or interlace method (" + std::to_string(static_cast<std::uint8_t>(data[10])) + ", " +
                std::to_string(static_cast<std::uint8_t>(data[11])) + ", " + std::to_string(h.interlace) + ")");
  // The limit, before anything is decoded.
  if (h.width > static_cast<std::uint32_t>(kMaxImageSide) || h.height > static_cast<std::uint32_t>(kMaxImageSide))
    throw Error(name + ": PNG is " + sizeText(h.width, h.height) + " pixels, more than facet reads (at most " +
                sizeText(kMaxImageSide, kMaxImageSide) + ", the largest image it renders)");
  const std::uint64_t decoded = std::uint64_t{h.width} * h.height * 4 * (h.bitDepth == 16 ? 2 : 1);
  if (decoded > kMaxPngDecodedBytes)
    throw Error(name + ": PNG is " + sizeText(h.width, h.height) + " at 16 bits a channel, " + std::to_string(decoded >> 20) +
                " MiB decoded, more than facet reads (at most " + std::to_string(kMaxPngDecodedBytes >> 20) + " MiB, the largest image it renders)");
}

// Walks the chunks: every one complete with a matching CRC, IHDR first,
// IDAT chunks in one run, IEND last with nothing after it.
PngHeader checkStructure(std::string_view bytes, const std::string& name) {
  if (bytes.empty()) throw Error(name + ": empty file, not a PNG");
  if (bytes.size() < sizeof kSignature || std::memcmp(bytes.data(), kSignature, sizeof kSignature) != 0) throw Error(name + ": not a PNG file");
  PngHeader h;
  bool headerSeen = false, paletteSeen = false;
  enum { kNoImageData, kInImageData, kAfterImageData } imageData = kNoImageData;
  std::size_t at = sizeof kSignature;
  for (;;) {
    const std::size_t left = bytes.size() - at;
    if (left == 0) throw Error(name + ": truncated PNG: no IEND chunk (the file ends at byte " + std::to_string(at) + ")");
    if (left < 8) throw Error(name + ": truncated PNG: the file ends inside the chunk header at byte " + std::to_string(at));
    const std::uint32_t length = bigEndian32(bytes, at);
    const std::string_view type = bytes.substr(at + 4, 4);
    for (const char c : type)
      if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z')))
        throw Error(name + ": corrupt PNG: the chunk at byte " + std::to_string(at) + " has type " + quoteInput(type) + ", not four letters");
    const std::string typeName(type);
    if (std::uint64_t{length} + 4 > left - 8)
      throw Error(name + ": truncated PNG: chunk " + typeName + " at byte " + std::to_string(at) + " holds " + std::to_string(length) +
                  " bytes and a CRC, the file has " + std::to_string(left - 8) + " more");
    const std::string_view data = bytes.substr(at + 8, length);
    if (crc32(bytes.substr(at + 4, 4 + std::size_t{length})) != bigEndian32(bytes, at + 8 + length))
      throw Error(name + ": CRC error in chunk " + typeName + " at byte " + std::to_string(at) + " (the file is damaged)");
    const std::size_t chunkAt = at;
    at += 12 + std::size_t{length};

    if (!headerSeen && typeName != "IHDR") throw Error(name + ": corrupt PNG: the first chunk is " + typeName + ", not IHDR");
    if (imageData == kInImageData && typeName != "IDAT") imageData = kAfterImageData;
    if (typeName == "IHDR") {
      if (headerSeen) throw Error(name + ": corrupt PNG: a second IHDR chunk at byte " + std::to_string(chunkAt));
      checkHeader(data, name, h);
      headerSeen = true;
    } else if (typeName == "PLTE") {
      paletteSeen = true;
    } else if (typeName == "tRNS") {
      h.transparency = true;
    } else if (typeName == "IDAT") {
      if (imageData == kAfterImageData)
        throw Error(name + ": corrupt PNG: IDAT chunk at byte " + std::to_string(chunkAt) + " after other chunks (image data must be one run)");
      if (h.colorType == 3 && !paletteSeen) throw Error(name + ": corrupt PNG: a palette image with no PLTE chunk before its image data");
      imageData = kInImageData;
      h.imageDataBytes += length;
      if (length == 0) h.emptyImageDataChunk = true;
    } else if (typeName == "IEND") {
      if (length != 0) throw Error(name + ": corrupt PNG: IEND holds " + std::to_string(length) + " bytes, not 0");
      break;
    } else if (typeName[0] >= 'A' && typeName[0] <= 'Z') {  // critical: a decoder must not skip it
      throw Error(name + ": unsupported PNG: unknown critical chunk " + typeName + " at byte " + std::to_string(chunkAt));
    }
  }
  // Bytes after IEND are refused, not ignored: a file cut and joined to
  // another, or one with data appended, is not the image it claims to be.
  if (at != bytes.size())
    throw Error(name + ": trailing data: " + std::to_string(bytes.size() - at) + " bytes after the IEND chunk at byte " + std::to_string(at - 12));
  if (imageData == kNoImageData) throw Error(name + ": corrupt PNG: no image data (IDAT chunk)");
  if (filteredBytes(h) > kMaxInflateRatio * h.imageDataBytes)
    throw Error(name + ": truncated or corrupt PNG: " + std::to_string(h.imageDataBytes) + " bytes of compressed image data cannot hold " +
                sizeText(h.width, h.height) + " pixels");
  return h;
}

// The file without its empty IDAT chunks. stb_image copies each chunk into
// its buffer with memcpy, which for an empty first IDAT is memcpy(NULL, p, 0):
// undefined behaviour. The walk in checkStructure has vouched for every length.
std::string withoutEmptyImageData(std::string_view bytes) {
  std::string out(bytes.substr(0, sizeof kSignature));
  for (std::size_t at = sizeof kSignature; at < bytes.size();) {
    const std::size_t size = 12 + std::size_t{bigEndian32(bytes, at)};
    if (size != 12 || bytes.substr(at + 4, 4) != "IDAT") out.append(bytes.substr(at, size));
    at += size;
  }
  return out;
}

struct StbFree {
  void operator()(stbi_uc* pixels) const { stbi_image_free(pixels); }
};

// Between speed and size for rendered frames (encodePng).
constexpr int kPngZlibLevel = 3;

// A chunk is its data's length, its type, the data, and the CRC of type and
// data. beginChunk writes the length (0 until endChunk) and the type and
// says where the chunk starts; the data follows; endChunk, once the data is
// in, sets the length and appends the CRC.
std::size_t beginChunk(std::vector<std::uint8_t>& out, const char (&type)[5]) {
  const std::size_t at = out.size();
  out.insert(out.end(), 4, 0);
  out.insert(out.end(), type, type + 4);
  return at;
}
void endChunk(std::vector<std::uint8_t>& out, std::size_t at) {
  const std::size_t size = out.size() - at - 8;
  const auto put32 = [&](std::size_t where, std::uint32_t v) {
    for (int k = 0; k < 4; ++k) out[where + static_cast<std::size_t>(k)] = static_cast<std::uint8_t>(v >> (24 - 8 * k));
  };
  put32(at, static_cast<std::uint32_t>(size));
  const std::uint32_t crc = crc32({reinterpret_cast<const char*>(out.data() + at + 4), size + 4});
  out.insert(out.end(), 4, 0);
  put32(out.size() - 4, crc);
}
void appendChunk(std::vector<std::uint8_t>& out, const char (&type)[5], const std::uint8_t* data, std::size_t size) {
  const std::size_t at = beginChunk(out, type);
  out.insert(out.end(), data, data + size);
  endChunk(out, at);
}

// One zlib stream deflated onto the end of `out`, which grows as it fills:
// add the stream's bytes in any pieces, then finish.
class Deflater {
 public:
  Deflater(std::vector<std::uint8_t>& out, const std::string& name) : out_(out), name_(name), used_(out.size()) {
    check(deflateInit(&z_, kPngZlibLevel));
  }
  ~Deflater() { deflateEnd(&z_); }
  Deflater(const Deflater&) = delete;
  Deflater& operator=(const Deflater&) = delete;

  void add(const std::uint8_t* bytes, std::size_t size) {
    z_.next_in = const_cast<Bytef*>(bytes);  // zlib's API predates const; it only reads them
    z_.avail_in = static_cast<uInt>(size);
    // zlib has taken all the bytes when it returns with room to spare.
    do {
      run(Z_NO_FLUSH);
    } while (z_.avail_out == 0);
  }
  // The stream's end; `out` ends with its last byte.
  void finish() {
    int status = Z_OK;
    while (status != Z_STREAM_END) status = run(Z_FINISH);
    out_.resize(used_);
  }

 private:
  int run(int flush) {
    if (used_ == out_.size()) out_.resize(std::max<std::size_t>(2 * out_.size(), used_ + (std::size_t{64} << 10)));
    const auto room = static_cast<uInt>(std::min<std::size_t>(out_.size() - used_, UINT_MAX));
    z_.next_out = out_.data() + used_;
    z_.avail_out = room;
    const int status = deflate(&z_, flush);
    used_ += room - z_.avail_out;
    if (status != Z_BUF_ERROR) check(status);  // Z_BUF_ERROR: nothing to do this round, not a failure
    return status;
  }
  void check(int status) const {
    if (status == Z_MEM_ERROR) throw std::bad_alloc();
    if (status != Z_OK && status != Z_STREAM_END) throw Error(name_ + ": zlib could not compress the image (" + std::to_string(status) + ")");
  }

  std::vector<std::uint8_t>& out_;
  const std::string& name_;
  std::size_t used_;  // out_'s bytes written; the rest is room for zlib
  z_stream z_{};
};

// The PNG bytes of a checked image; std::bad_alloc when memory runs out.
std::vector<std::uint8_t> encodedPng(const Image& image, const std::string& name) {
  const int w = image.width(), h = image.height();
  const auto stride = static_cast<std::size_t>(w) * 4;
  std::uint8_t header[13] = {0, 0, 0, 0, 0, 0, 0, 0, 8, 6, 0, 0, 0};  // width, height, 8 bits, RGBA, deflate, adaptive filters, not interlaced
  for (int k = 0; k < 4; ++k) {
    header[k] = static_cast<std::uint8_t>(static_cast<std::uint32_t>(w) >> (24 - 8 * k));
    header[4 + k] = static_cast<std::uint8_t>(static_cast<std::uint32_t>(h) >> (24 - 8 * k));
  }
  std::vector<std::uint8_t> out(std::begin(kSignature), std::end(kSignature));
  appendChunk(out, "IHDR", header, sizeof header);
  // One IDAT: the rows top first (the image stores the bottom row first),
  // each after filter byte 0 (None), deflated as they come, with no copy of
  // the image: on rendered frames zlib does better with None than with Sub
  // or Up (the default scene at 800x600: 83 KB against 96 KB with Up). zlib
  // level 3 writes a smaller file there than stb_image_write (level 8, five
  // filters tried per row), and sooner (docs/performance.md).
  const std::size_t idat = beginChunk(out, "IDAT");
  {
    Deflater deflater(out, name);
    const std::uint8_t filterNone = 0;
    for (int y = 0; y < h; ++y) {
      deflater.add(&filterNone, 1);
      deflater.add(reinterpret_cast<const std::uint8_t*>(image.data()) + static_cast<std::size_t>(h - 1 - y) * stride, stride);
    }
    deflater.finish();
  }
  endChunk(out, idat);
  appendChunk(out, "IEND", nullptr, 0);
  return out;
}

}  // namespace

std::vector<std::uint8_t> encodePng(const Image& image, const std::string& name) {
  if (image.empty()) throw Error(name + ": refusing to write an empty image");
  const int w = image.width(), h = image.height();
  if (w > kMaxImageSide || h > kMaxImageSide)
    throw Error(name + ": image " + sizeText(w, h) + " is larger than facet writes (at most " + sizeText(kMaxImageSide, kMaxImageSide) + ")");
  try {
    return encodedPng(image, name);
  } catch (const std::bad_alloc&) {
    throw OutOfMemory("encoding " + name + " (" + sizeText(w, h) + ")");
  }
}

void writePng(const std::string& path, const Image& image) { writeFileAtomically(path, encodePng(image, path)); }

PngImage decodePngImage(std::string_view bytes, const std::string& name) {
  if (bytes.size() > kMaxPngFileBytes)
    throw Error(name + ": file is " + std::to_string(bytes.size()) + " bytes, more than facet reads as a PNG (" + std::to_string(kMaxPngFileBytes) + ")");
  const PngHeader header = checkStructure(bytes, name);
  const std::string doing = "decoding " + name + " (" + sizeText(header.width, header.height) + ")";
  try {
    // stb_image keeps its last failure reason, and some failures set none:
    // a reason left from an earlier file must not be reported for this one.
    stbi__g_failure_reason = nullptr;
    decoderOutOfMemory = false;
    int w = 0, h = 0, channels = 0;
    const std::string copy = header.emptyImageDataChunk ? withoutEmptyImageData(bytes) : std::string();
    const std::string_view input = header.emptyImageDataChunk ? std::string_view(copy) : bytes;
    const std::unique_ptr<stbi_uc, StbFree> pixels(
        stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(input.data()), static_cast<int>(input.size()), &w, &h, &channels, 4));
    if (!pixels) {
      if (decoderOutOfMemory) throw OutOfMemory(doing);
      const char* reason = stbi_failure_reason();
      if (!reason || !*reason) throw Error(name + ": corrupt PNG image data");
      throw Error(name + ": corrupt PNG image data (" + std::string(reason) + ")");
    }
    if (static_cast<std::uint32_t>(w) != header.width || static_cast<std::uint32_t>(h) != header.height)
      throw Error(name + ": corrupt PNG: decoded as " + sizeText(w, h) + ", its header says " + sizeText(header.width, header.height));
    PngImage out{Image(w, h), storedChannels(header)};
    const std::size_t stride = static_cast<std::size_t>(w) * 4;
    for (int y = 0; y < h; ++y)  // file row 0 is the top: it becomes stored row h-1
      std::memcpy(&out.image.at(0, h - 1 - y), pixels.get() + static_cast<std::size_t>(y) * stride, stride);
    return out;
  } catch (const OutOfMemory&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw OutOfMemory(doing);
  }
}

Image decodePng(std::string_view bytes, const std::string& name) { return decodePngImage(bytes, name).image; }

PngImage readPngImage(const std::string& path) {
  try {
    return decodePngImage(readFile(path, kMaxPngFileBytes), path);
  } catch (const OutOfMemory&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw OutOfMemory("reading " + path);
  }
}

Image readPng(const std::string& path) { return readPngImage(path).image; }

}  // namespace facet
