// Volume data: NRRD and NIfTI-1 files written here, nibabel's MRI, the
// Marschner-Lobb signal, trilinear interpolation and gradients.
#include <sys/stat.h>
#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include <doctest/doctest.h>
#include <nifti/nifti1.h>

#include "common/error.h"
#include "scratch_folder.h"
#include "volume/load_volume.h"
#include "volume/volume_file.h"
#include "scene/volume.h"

using namespace facet;
namespace fs = std::filesystem;

namespace {

const std::string kNibabelData = FACET_NIBABEL_DATA;

// [SECTION] Writing test files

void writeFile(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  REQUIRE(out.good());
}

// A value's bytes in the given byte order.
template <typename T>
std::string bytesOf(T value, bool bigEndian = false) {
  std::string b(sizeof(T), '\0');
  std::memcpy(b.data(), &value, sizeof(T));
  if (bigEndian != (std::endian::native == std::endian::big)) std::reverse(b.begin(), b.end());
  return b;
}

template <typename T>
std::string samplesOf(const std::vector<T>& values, bool bigEndian = false) {
  std::string out;
  for (const T v : values) out += bytesOf(v, bigEndian);
  return out;
}

// Values that differ along every axis: v(x, y, z) = x + 10·y + 100·z (+ offset).
template <typename T>
std::vector<T> rampValues(int nx, int ny, int nz, int offset = 0) {
  std::vector<T> values;
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) values.push_back(static_cast<T>(offset + x + 10 * y + 100 * z));
  return values;
}

std::string nrrdHeader(const std::string& type, const std::string& sizes, const std::string& more = "encoding: raw\nendian: little\n") {
  return "NRRD0004\n# written by the volume tests\ntype: " + type + "\ndimension: 3\nsizes: " + sizes + "\n" + more;
}

// CRC-32 as gzip needs it.
std::uint32_t crc32(const std::string& data) {
  std::uint32_t crc = 0xffffffffu;
  for (const char c : data) {
    crc ^= static_cast<unsigned char>(c);
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

// A gzip member holding `data` in stored (uncompressed) deflate blocks, so
// that the tests need no compressor.
std::string gzipStored(const std::string& data) {
  std::string out("\x1f\x8b\x08\x00\x00\x00\x00\x00\x00\xff", 10);
  std::size_t at = 0;
  do {
    const std::size_t n = std::min<std::size_t>(65535, data.size() - at);
    const bool last = at + n == data.size();
    out += static_cast<char>(last ? 1 : 0);
    out += bytesOf(static_cast<std::uint16_t>(n));
    out += bytesOf(static_cast<std::uint16_t>(~n & 0xffffu));
    out += data.substr(at, n);
    at += n;
  } while (at < data.size());
  out += bytesOf(crc32(data));
  out += bytesOf(static_cast<std::uint32_t>(data.size()));
  return out;
}

nifti_1_header niftiHeader(int nx, int ny, int nz, short datatype, short bitpix) {
  nifti_1_header h;
  std::memset(&h, 0, sizeof h);
  h.sizeof_hdr = 348;
  h.dim[0] = 3;
  h.dim[1] = static_cast<short>(nx);
  h.dim[2] = static_cast<short>(ny);
  h.dim[3] = static_cast<short>(nz);
  for (int i = 4; i < 8; ++i) h.dim[i] = 1;
  h.datatype = datatype;
  h.bitpix = bitpix;
  for (int i = 0; i < 8; ++i) h.pixdim[i] = 1.0f;
  h.vox_offset = 352.0f;
  std::memcpy(h.magic, "n+1", 4);
  return h;
}

// The fields niftiHeader() and the tests set, in the other byte order.
void swapHeader(nifti_1_header& h) {
  const auto swap = [](auto& field) {
    unsigned char b[sizeof field];
    std::memcpy(b, &field, sizeof field);
    std::reverse(b, b + sizeof field);
    std::memcpy(&field, b, sizeof field);
  };
  swap(h.sizeof_hdr);
  for (short& d : h.dim) swap(d);
  swap(h.datatype);
  swap(h.bitpix);
  for (float& p : h.pixdim) swap(p);
  swap(h.vox_offset);
  swap(h.scl_slope);
  swap(h.scl_inter);
}

// The header, the 4-byte extension flag, then the samples.
std::string niftiFile(const nifti_1_header& h, const std::string& samples) {
  std::string out(reinterpret_cast<const char*>(&h), sizeof h);
  out += std::string(4, '\0');
  return out + samples;
}

// The message of the facet::Error that `read` throws ("" when none).
std::string errorOf(const std::function<void()>& read) {
  try {
    read();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// An error line names `name` and says `problem`, on one line.
void checkError(const std::string& message, const std::string& name, const std::string& problem) {
  CAPTURE(message);
  CHECK(message.find(name) != std::string::npos);
  CHECK(message.find(problem) != std::string::npos);
  CHECK(message.find('\n') == std::string::npos);
}

void checkNrrdError(const fs::path& dir, const std::string& file, const std::string& contents, const std::string& problem) {
  const fs::path path = dir / file;
  writeFile(path, contents);
  checkError(errorOf([&] { readNrrd(path.string()); }), file, problem);
}

void checkNiftiError(const fs::path& dir, const std::string& file, const std::string& contents, const std::string& problem) {
  const fs::path path = dir / file;
  writeFile(path, contents);
  checkError(errorOf([&] { readNifti(path.string()); }), file, problem);
}

// Every sample equal to x + 10·y + 100·z + offset.
void checkRamp(const Volume& v, int offset = 0) {
  for (int z = 0; z < v.size.z; ++z)
    for (int y = 0; y < v.size.y; ++y)
      for (int x = 0; x < v.size.x; ++x) {
        CAPTURE(x);
        CAPTURE(y);
        CAPTURE(z);
        REQUIRE(v.at(x, y, z) == static_cast<float>(offset + x + 10 * y + 100 * z));
      }
}

// ρ of Marschner and Lobb, written out again from the paper's formula.
double marschnerLobbFormula(double x, double y, double z) {
  const double pi = std::numbers::pi, alpha = 0.25, fM = 6.0;
  const double rhoR = std::cos(2.0 * pi * fM * std::cos(pi * std::sqrt(x * x + y * y) / 2.0));
  return (1.0 - std::sin(pi * z / 2.0) + alpha * (1.0 + rhoR)) / (2.0 * (1.0 + alpha));
}

Volume smallVolume(glm::ivec3 size, glm::vec3 spacing, const std::function<float(int, int, int)>& value) {
  Volume v;
  v.size = size;
  v.spacing = spacing;
  v.values.resize(v.sampleCount());
  for (int z = 0; z < size.z; ++z)
    for (int y = 0; y < size.y; ++y)
      for (int x = 0; x < size.x; ++x) v.values[v.index(x, y, z)] = value(x, y, z);
  updateRange(v);
  return v;
}

}  // namespace

// [SECTION] NRRD

// loadVolume of `good` and (every third read) `broken` on 8 threads at once, as
// batch's workers load volumes: every good read gives `size`, every broken one
// an error naming `problem`.
void readOnThreads(const fs::path& good, const fs::path& broken, glm::ivec3 size, const std::string& problem) {
  constexpr int kThreads = 8, kReads = 40;
  std::atomic<int> read{0}, refused{0}, expectedRefusals{0};
  std::vector<std::string> wrong(kThreads);
  {
    std::vector<std::jthread> threads;
    for (int t = 0; t < kThreads; ++t)
      threads.emplace_back([&, t] {
        for (int i = 0; i < kReads; ++i) {
          const bool bad = (t + i) % 3 == 0;
          expectedRefusals += bad ? 1 : 0;
          try {
            const Volume v = loadVolume((bad ? broken : good).string(), 64);
            if (!bad && v.size == size) ++read;
          } catch (const Error& e) {
            if (bad && std::string(e.what()).find(problem) != std::string::npos) ++refused;
            else wrong[static_cast<std::size_t>(t)] = e.what();
          }
        }
      });
  }
  for (const std::string& message : wrong) CHECK_MESSAGE(message.empty(), message);
  CHECK(refused == expectedRefusals);
  CHECK(read == kThreads * kReads - expectedRefusals);
}

TEST_CASE("NRRD reader: uint8, int8, int16, uint16 and float samples with spacings round-trip") {
  const fs::path dir = test::scratchFolder("volume_readers", "nrrd_types");
  const std::string more = "spacings: 0.5 1.25 3\nencoding: raw\nendian: little\n";
  struct Case {
    std::string type, samples;
    int offset;
  };
  const Case cases[] = {
      {"uint8", samplesOf(rampValues<std::uint8_t>(4, 3, 2)), 0},
      {"int8", samplesOf(rampValues<std::int8_t>(4, 3, 2, -120)), -120},
      {"short", samplesOf(rampValues<std::int16_t>(4, 3, 2, -1000)), -1000},
      {"unsigned short", samplesOf(rampValues<std::uint16_t>(4, 3, 2, 60000)), 60000},
      {"float", samplesOf(rampValues<float>(4, 3, 2, -50)), -50},
  };
  for (const Case& c : cases) {
    CAPTURE(c.type);
    const fs::path path = dir / "ramp.nrrd";
    writeFile(path, nrrdHeader(c.type, "4 3 2", more) + "\n" + c.samples);
    const Volume v = readNrrd(path.string());
    CHECK(v.source == path.string());
    CHECK(v.size == glm::ivec3(4, 3, 2));
    CHECK(v.spacing == glm::vec3(0.5f, 1.25f, 3.0f));
    CHECK(v.values.size() == 24);
    checkRamp(v, c.offset);
    CHECK(v.minValue == static_cast<float>(c.offset));
    CHECK(v.maxValue == static_cast<float>(c.offset + 3 + 20 + 100));
  }
}

TEST_CASE("NRRD reader: a detached .nhdr with big-endian samples, spacing from space directions") {
  const fs::path dir = test::scratchFolder("volume_readers", "nrrd_detached");
  writeFile(dir / "ramp.raw", samplesOf(rampValues<std::int16_t>(3, 4, 5, -7), true));
  writeFile(dir / "ramp.nhdr", nrrdHeader("int16", "3 4 5",
                                          "space dimension: 3\nspace directions: (0,2,0) (0,0,-0.5) (3,4,0)\n"
                                          "encoding: raw\nendian: big\ndata file: ramp.raw\n"));
  const Volume v = loadVolume((dir / "ramp.nhdr").string(), 64);
  CHECK(v.size == glm::ivec3(3, 4, 5));
  CHECK(v.spacing == glm::vec3(2.0f, 0.5f, 5.0f));  // the lengths of the direction vectors
  checkRamp(v, -7);
  CHECK(v.minValue == -7.0f);
  CHECK(v.maxValue == 425.0f);
}

TEST_CASE("NRRD reader: gzip and ascii encodings, a byte skip, no spacing given") {
  const fs::path dir = test::scratchFolder("volume_readers", "nrrd_encodings");
  const std::string samples = samplesOf(rampValues<std::uint16_t>(2, 3, 4));
  writeFile(dir / "gz.nrrd", nrrdHeader("ushort", "2 3 4", "encoding: gzip\nendian: little\n") + "\n" + gzipStored(samples));
  const Volume gz = readNrrd((dir / "gz.nrrd").string());
  CHECK(gz.spacing == glm::vec3(1.0f));
  checkRamp(gz);

  std::string text;
  for (const float value : rampValues<float>(2, 3, 4)) text += std::to_string(value) + "\n";
  writeFile(dir / "ascii.nrrd", nrrdHeader("float", "2 3 4", "encoding: ascii\n") + "\n" + text);
  checkRamp(readNrrd((dir / "ascii.nrrd").string()));

  writeFile(dir / "skip.raw", "JUNKJUNK" + samples);
  writeFile(dir / "skip.nhdr", nrrdHeader("uint16", "2 3 4", "encoding: raw\nendian: little\nbyte skip: 8\ndata file: skip.raw\n"));
  checkRamp(readNrrd((dir / "skip.nhdr").string()));
}

TEST_CASE("NRRD reader: files read on many threads at once, ascii and broken ones too (teem keeps its state in globals)") {
  const fs::path dir = test::scratchFolder("volume_readers", "nrrd_threads");
  std::string text;
  for (const float value : rampValues<float>(2, 3, 4)) text += std::to_string(value) + "\n";
  writeFile(dir / "ascii.nrrd", nrrdHeader("float", "2 3 4", "encoding: ascii\n") + "\n" + text);
  writeFile(dir / "broken.nrrd", nrrdHeader("float", "2 3 x", "encoding: ascii\n") + "\n" + text);
  readOnThreads(dir / "ascii.nrrd", dir / "broken.nrrd", {2, 3, 4}, "sizes");
}

TEST_CASE("NRRD reader: broken files are refused with one line naming the file") {
  const fs::path dir = test::scratchFolder("volume_readers", "nrrd_broken");
  const std::string ramp16 = samplesOf(rampValues<std::int16_t>(4, 4, 4));

  SUBCASE("missing file") { checkError(errorOf([&] { readNrrd((dir / "gone.nrrd").string()); }), "gone.nrrd", "no such file"); }
  SUBCASE("a folder") {
    fs::create_directory(dir / "folder.nrrd");
    checkError(errorOf([&] { readNrrd((dir / "folder.nrrd").string()); }), "folder.nrrd", "not a regular file");
  }
  SUBCASE("truncated raw data") {
    checkNrrdError(dir, "short.nrrd", nrrdHeader("int16", "4 4 4") + "\n" + ramp16.substr(0, 100),
                   "4x4x4 int16 samples need 128 bytes, the file holds 100");
  }
  SUBCASE("dimensions larger or smaller than the data") {
    checkNrrdError(dir, "big.nrrd", nrrdHeader("int16", "4 4 5") + "\n" + ramp16, "4x4x5 int16 samples need 160 bytes, the file holds 128");
    checkNrrdError(dir, "small.nrrd", nrrdHeader("int16", "4 4 3") + "\n" + ramp16, "4x4x3 int16 samples need 96 bytes, the file holds 128");
  }
  SUBCASE("truncated detached data file") {
    writeFile(dir / "short.raw", ramp16.substr(0, 7));
    checkNrrdError(dir, "short.nhdr", nrrdHeader("int16", "4 4 4", "encoding: raw\nendian: little\ndata file: short.raw\n"),
                   "need 128 bytes, its data file short.raw holds 7");
  }
  SUBCASE("missing detached data file") {
    checkNrrdError(dir, "lost.nhdr", nrrdHeader("int16", "4 4 4", "encoding: raw\nendian: little\ndata file: lost.raw\n"), "lost.raw");
  }
  SUBCASE("a detached data file that is a FIFO is refused before it is opened, not waited on") {
    const fs::path fifo = dir / "pipe.raw";
    fs::remove(fifo);
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    checkNrrdError(dir, "pipe.nhdr", nrrdHeader("int16", "4 4 4", "encoding: raw\nendian: little\ndata file: pipe.raw\n"),
                   "its data file pipe.raw: not a regular file");
    checkNrrdError(dir, "absolute.nhdr", nrrdHeader("int16", "4 4 4", "encoding: raw\nendian: little\ndata file: " + fifo.string() + "\n"),
                   "pipe.raw: not a regular file");
  }
  SUBCASE("truncated gzip and ascii data") {
    const std::string gz = gzipStored(ramp16);
    checkNrrdError(dir, "short-gz.nrrd", nrrdHeader("int16", "4 4 4", "encoding: gzip\nendian: little\n") + "\n" + gz.substr(0, 60),
                   "4x4x4 int16 samples in gzip encoding");
    checkNrrdError(dir, "short-ascii.nrrd", nrrdHeader("float", "2 2 2", "encoding: ascii\n") + "\n1 2 3\n",
                   "2x2x2 float32 samples in ASCII encoding");
  }
  SUBCASE("unsupported sample types") {
    checkNrrdError(dir, "double.nrrd", nrrdHeader("double", "2 2 2") + "\n" + std::string(64, '\0'), "float64 samples are not supported");
    checkNrrdError(dir, "int64.nrrd", nrrdHeader("int64", "2 2 2") + "\n" + std::string(64, '\0'), "int64 samples are not supported");
    checkNrrdError(dir, "int32.nrrd", nrrdHeader("int", "2 2 2") + "\n" + std::string(32, '\0'), "int32 samples are not supported");
    checkNrrdError(dir, "rgb.nrrd", "NRRD0004\ntype: uchar\ndimension: 4\nsizes: 3 2 2 2\nencoding: raw\n\n" + std::string(24, '\0'),
                   "4 axes, a volume has 3");
  }
  SUBCASE("wrong number of axes or too few samples") {
    checkNrrdError(dir, "image.nrrd", "NRRD0004\ntype: uchar\ndimension: 2\nsizes: 4 4\nencoding: raw\n\n" + std::string(16, '\0'),
                   "2 axes, a volume has 3");
    checkNrrdError(dir, "flat.nrrd", nrrdHeader("uchar", "4 1 4") + "\n" + std::string(16, '\0'), "1 sample along y, a volume needs at least 2");
  }
  SUBCASE("spacing that is not a positive number") {
    checkNrrdError(dir, "negative.nrrd", nrrdHeader("uchar", "2 2 2", "spacings: 1 -2 1\nencoding: raw\n") + "\n" + std::string(8, '\0'),
                   "spacing along y is -2, not a positive number");
    checkNrrdError(dir, "zero.nrrd", nrrdHeader("uchar", "2 2 2", "spacings: 1 1 0\nencoding: raw\n") + "\n" + std::string(8, '\0'),
                   "spacings: axis 2 spacing (0) invalid");
    checkNrrdError(dir, "direction.nrrd",
                   nrrdHeader("uchar", "2 2 2", "space dimension: 3\nspace directions: (0,0,0) (0,1,0) (0,0,1)\nencoding: raw\n") + "\n" +
                       std::string(8, '\0'),
                   "spacing along x is 0");
    checkNrrdError(dir, "infinite.nrrd", nrrdHeader("uchar", "2 2 2", "spacings: inf 1 1\nencoding: raw\n") + "\n" + std::string(8, '\0'),
                   "spacings");
  }
  SUBCASE("a box past facet's extent, or spacings too unequal for the ray caster's step") {
    const std::string samples = "\n" + std::string(8, '\0');
    const auto spaced = [&](const std::string& spacings) { return nrrdHeader("uchar", "2 2 2", "spacings: " + spacings + "\nencoding: raw\n") + samples; };
    checkNrrdError(dir, "wide.nrrd", spaced("1e38 1e38 1e38"), "2 samples 1e+38 apart along x span 1e+38, more than facet's limit of 1e+09");
    checkNrrdError(dir, "uneven.nrrd", spaced("1 1000.5 1"), "spacings 1, 1000.5 and 1: the largest is more than 1000 times the smallest");
    const fs::path edge = dir / "edge.nrrd";
    writeFile(edge, spaced("1 1000 1"));
    CHECK(readNrrd(edge.string()).spacing.y == 1000.0f);  // at the limit, read
    writeFile(edge, spaced("1e9 1e9 1e9"));
    CHECK(readNrrd(edge.string()).extent().x == 1e9f);
  }
  SUBCASE("headers teem or facet cannot use") {
    checkNrrdError(dir, "sizes.nrrd", nrrdHeader("uchar", "2 2 x") + "\n" + std::string(8, '\0'), "sizes");
    // teem called these "axis 0 size is zero!": the size as written, and which axis.
    checkNrrdError(dir, "negative.nrrd", nrrdHeader("uchar", "-4 2 2") + "\n" + std::string(16, '\0'),
                   "sizes: axis 0 has '-4' samples, not a whole number from 1 to 2147483647");
    checkNrrdError(dir, "wraps.nrrd", nrrdHeader("uchar", "2 18446744073709551616 2") + "\n" + std::string(16, '\0'),
                   "sizes: axis 1 has '18446744073709551616' samples, not a whole number from 1 to 2147483647");
    checkNrrdError(dir, "type.nrrd", nrrdHeader("shrt", "2 2 2") + "\n" + std::string(16, '\0'), "type");
    checkNrrdError(dir, "text.nrrd", "1 2 3\n4 5 6\n", "not a NRRD file");
    checkNrrdError(dir, "empty.nrrd", "", "not a NRRD file");
    checkNrrdError(dir, "stdin.nhdr", nrrdHeader("uchar", "2 2 2", "encoding: raw\ndata file: -\n"), "standard input");
    checkNrrdError(dir, "list.nhdr", nrrdHeader("uchar", "2 2 2", "encoding: raw\ndata file: LIST\na.raw\nb.raw\n"), "several data files");
    checkNrrdError(dir, "numbered.nhdr", nrrdHeader("uchar", "2 2 2", "encoding: raw\ndata file: /dev/null%.0d 1 2000000000 1\n"),
                   "several data files");
    checkNrrdError(dir, "long.nrrd", "NRRD0004\n# " + std::string(2u << 20, 'x') + "\n", "header longer than 1 MiB");
    writeFile(dir / "zero.nhdr", nrrdHeader("uchar", "2 2 2", "encoding: raw\ndata file: /dev/zero\n"));
    checkError(errorOf([&] { readNrrd((dir / "zero.nhdr").string()); }), "zero.nhdr", "its data file /dev/zero: not a regular file");
  }
  SUBCASE("more samples than the scene budget") {
    checkNrrdError(dir, "huge.nrrd", nrrdHeader("float", "2048 2048 2048") + "\n" + std::string(8, '\0'),
                   "2048x2048x2048 float32 samples need");
    // 2^62 samples: teem can count them, their bytes pass 2^64.
    checkNrrdError(dir, "huger.nrrd", nrrdHeader("float", "1048576 1048576 4194304") + "\n",
                   "1048576x1048576x4194304 float32 samples need more than the scene budget of 1 GiB");
    checkNrrdError(dir, "hugest.nrrd", nrrdHeader("float", "2000000000 2000000000 2000000000") + "\n", "sizes: total # of elements too large");
  }
}

// [SECTION] NIfTI-1

TEST_CASE("NIfTI reader: int16 with scl_slope and scl_inter, uint8, float32, big-endian, vox_offset 0") {
  const fs::path dir = test::scratchFolder("volume_readers", "nifti_types");
  SUBCASE("int16 scaled by scl_slope and scl_inter") {
    nifti_1_header h = niftiHeader(4, 3, 2, DT_INT16, 16);
    h.pixdim[1] = 0.75f, h.pixdim[2] = 1.5f, h.pixdim[3] = 4.0f;
    h.scl_slope = 2.0f;
    h.scl_inter = -3.0f;
    writeFile(dir / "scaled.nii", niftiFile(h, samplesOf(rampValues<std::int16_t>(4, 3, 2, -40))));
    const Volume v = loadVolume((dir / "scaled.nii").string(), 64);
    CHECK(v.size == glm::ivec3(4, 3, 2));
    CHECK(v.spacing == glm::vec3(0.75f, 1.5f, 4.0f));
    for (int z = 0; z < 2; ++z)
      for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x) REQUIRE(v.at(x, y, z) == 2.0f * static_cast<float>(-40 + x + 10 * y + 100 * z) - 3.0f);
    CHECK(v.minValue == -83.0f);
    CHECK(v.maxValue == 2.0f * 83.0f - 3.0f);
  }
  SUBCASE("uint8, int8, uint16 and float32 unscaled (slope 0)") {
    const struct {
      short datatype, bitpix;
      std::string samples;
      int offset;
    } cases[] = {
        {DT_UINT8, 8, samplesOf(rampValues<std::uint8_t>(4, 3, 2)), 0},
        {DT_INT8, 8, samplesOf(rampValues<std::int8_t>(4, 3, 2, -128)), -128},
        {DT_UINT16, 16, samplesOf(rampValues<std::uint16_t>(4, 3, 2, 65000)), 65000},
        {DT_FLOAT32, 32, samplesOf(rampValues<float>(4, 3, 2, -9)), -9},
    };
    for (const auto& c : cases) {
      CAPTURE(c.datatype);
      writeFile(dir / "plain.nii", niftiFile(niftiHeader(4, 3, 2, c.datatype, c.bitpix), c.samples));
      checkRamp(readNifti((dir / "plain.nii").string()), c.offset);
    }
  }
  SUBCASE("a big-endian file, 4 dimensions with one volume") {
    nifti_1_header h = niftiHeader(3, 4, 5, DT_INT16, 16);
    h.dim[0] = 4;
    h.pixdim[3] = 2.5f;
    swapHeader(h);
    writeFile(dir / "big.nii", niftiFile(h, samplesOf(rampValues<std::int16_t>(3, 4, 5, -300), true)));
    const Volume v = readNifti((dir / "big.nii").string());
    CHECK(v.spacing == glm::vec3(1.0f, 1.0f, 2.5f));
    checkRamp(v, -300);
  }
  SUBCASE("vox_offset 0 means the samples follow the 352 bytes of header and extension flag") {
    nifti_1_header h = niftiHeader(2, 2, 2, DT_UINT8, 8);
    h.vox_offset = 0.0f;
    writeFile(dir / "zero.nii", niftiFile(h, samplesOf(rampValues<std::uint8_t>(2, 2, 2))));
    checkRamp(readNifti((dir / "zero.nii").string()));
  }
  SUBCASE("samples after a header extension, at vox_offset 368") {
    nifti_1_header h = niftiHeader(2, 2, 2, DT_UINT8, 8);
    h.vox_offset = 368.0f;
    std::string file(reinterpret_cast<const char*>(&h), sizeof h);
    file += std::string("\x01\0\0\0", 4) + bytesOf(std::int32_t{16}) + bytesOf(std::int32_t{6}) + std::string("comment\0", 8);  // NIFTI_ECODE_COMMENT
    REQUIRE(file.size() == 368);
    writeFile(dir / "extended.nii", file + samplesOf(rampValues<std::uint8_t>(2, 2, 2)));
    checkRamp(readNifti((dir / "extended.nii").string()));
  }
  SUBCASE("gzip-compressed .nii.gz") {
    nifti_1_header h = niftiHeader(5, 4, 3, DT_FLOAT32, 32);
    writeFile(dir / "packed.nii.gz", gzipStored(niftiFile(h, samplesOf(rampValues<float>(5, 4, 3, 1)))));
    const Volume v = loadVolume((dir / "packed.nii.gz").string(), 64);
    CHECK(v.size == glm::ivec3(5, 4, 3));
    checkRamp(v, 1);
  }
}

TEST_CASE("NIfTI reader: files read on many threads at once, broken ones too") {
  const fs::path dir = test::scratchFolder("volume_readers", "nifti_threads");
  const std::string samples = samplesOf(rampValues<std::int16_t>(4, 3, 2, -40));
  writeFile(dir / "good.nii", niftiFile(niftiHeader(4, 3, 2, DT_INT16, 16), samples));
  writeFile(dir / "short.nii", niftiFile(niftiHeader(4, 3, 2, DT_INT16, 16), samples.substr(0, 10)));
  readOnThreads(dir / "good.nii", dir / "short.nii", {4, 3, 2}, "short.nii");
}

TEST_CASE("NIfTI reader: broken files are refused with one line naming the file") {
  const fs::path dir = test::scratchFolder("volume_readers", "nifti_broken");
  const std::string ramp = samplesOf(rampValues<std::int16_t>(4, 4, 4));
  const nifti_1_header good = niftiHeader(4, 4, 4, DT_INT16, 16);

  SUBCASE("missing file") { checkError(errorOf([&] { readNifti((dir / "gone.nii").string()); }), "gone.nii", "no such file"); }
  SUBCASE("truncated samples, or dimensions larger than the data") {
    checkNiftiError(dir, "short.nii", niftiFile(good, ramp.substr(0, 50)), "4x4x4 int16 samples need 128 bytes after offset 352, the file holds 50");
    nifti_1_header h = good;
    h.dim[3] = 9;
    checkNiftiError(dir, "big.nii", niftiFile(h, ramp), "4x4x9 int16 samples need 288 bytes after offset 352, the file holds 128");
    h = good;
    h.vox_offset = 1e6f;
    checkNiftiError(dir, "far.nii", niftiFile(h, ramp), "after offset 1000000, the file holds 0");
  }
  SUBCASE("truncated header") { checkNiftiError(dir, "header.nii", niftiFile(good, "").substr(0, 100), "100 bytes, shorter than the 348-byte"); }
  SUBCASE("truncated and corrupt gzip") {
    const std::string gz = gzipStored(niftiFile(good, ramp));
    checkNiftiError(dir, "short.nii.gz", gz.substr(0, gz.size() - 60), "truncated or corrupt gzip data");
    checkNiftiError(dir, "header.nii.gz", gz.substr(0, 200), "after decompression, shorter than the 348-byte");
    std::string corrupt = gz;
    corrupt[10] = '\x07';  // a reserved deflate block type
    checkNiftiError(dir, "corrupt.nii.gz", corrupt, "shorter than the 348-byte");
    checkNiftiError(dir, "unnamed.nii", gz, "gzip-compressed");
  }
  SUBCASE("unsupported sample types") {
    checkNiftiError(dir, "double.nii", niftiFile(niftiHeader(2, 2, 2, DT_FLOAT64, 64), std::string(64, '\0')), "float64 samples are not supported");
    checkNiftiError(dir, "rgb.nii", niftiFile(niftiHeader(2, 2, 2, DT_RGB24, 24), std::string(24, '\0')), "RGB24 samples are not supported");
    checkNiftiError(dir, "int64.nii", niftiFile(niftiHeader(2, 2, 2, DT_INT64, 64), std::string(64, '\0')), "int64 samples are not supported");
    checkNiftiError(dir, "odd.nii", niftiFile(niftiHeader(2, 2, 2, 3, 8), std::string(8, '\0')), "datatype 3 samples are not supported");
  }
  SUBCASE("wrong number of dimensions or too few samples") {
    nifti_1_header h = good;
    h.dim[0] = 2;
    checkNiftiError(dir, "image.nii", niftiFile(h, ramp), "2 dimensions (dim[0]), a volume has 3");
    h = good;
    h.dim[0] = 4;
    h.dim[4] = 2;
    checkNiftiError(dir, "series.nii", niftiFile(h, ramp + ramp), "2 volumes (dim[4])");
    h = good;
    h.dim[2] = 1;
    checkNiftiError(dir, "flat.nii", niftiFile(h, ramp), "1 sample along y (dim[2]), a volume needs at least 2");
    h.dim[2] = -3;
    checkNiftiError(dir, "minus.nii", niftiFile(h, ramp), "-3 samples along y (dim[2])");
  }
  SUBCASE("spacing that is not a positive number") {
    nifti_1_header h = good;
    h.pixdim[2] = -1.0f;
    checkNiftiError(dir, "negative.nii", niftiFile(h, ramp), "spacing along y (pixdim[2]) is -1, not a positive number");
    h.pixdim[2] = 0.0f;
    checkNiftiError(dir, "zero.nii", niftiFile(h, ramp), "spacing along y (pixdim[2]) is 0");
    h = good;
    h.pixdim[3] = std::numeric_limits<float>::quiet_NaN();
    checkNiftiError(dir, "nan.nii", niftiFile(h, ramp), "spacing along z (pixdim[3]) is nan");
  }
  SUBCASE("a box past facet's extent: pixdim 1e38 would overflow the ray caster's box") {
    nifti_1_header h = good;
    h.pixdim[1] = 1e38f;
    checkNiftiError(dir, "wide.nii", niftiFile(h, ramp), "span 3e+38, more than facet's limit of 1e+09");
    h = good;
    h.pixdim[3] = 1e-6f;
    checkNiftiError(dir, "thin.nii", niftiFile(h, ramp), "the largest is more than 1000 times the smallest");
  }
  SUBCASE("not a single-file NIfTI-1") {
    nifti_1_header h = good;
    h.sizeof_hdr = 540;
    checkNiftiError(dir, "two.nii", niftiFile(h, ramp), "NIfTI-2");
    h.sizeof_hdr = 1234;
    checkNiftiError(dir, "size.nii", niftiFile(h, ramp), "not a NIfTI-1 file (sizeof_hdr is 1234, not 348)");
    h = good;
    std::memcpy(h.magic, "ni1", 4);
    checkNiftiError(dir, "pair.nii", niftiFile(h, ramp), "separate .img file");
    std::memcpy(h.magic, "xyz", 4);
    checkNiftiError(dir, "magic.nii", niftiFile(h, ramp), "magic is not n+1");
    h = good;
    h.vox_offset = -4.0f;
    checkNiftiError(dir, "offset.nii", niftiFile(h, ramp), "vox_offset -4 is not a byte offset");
  }
  SUBCASE("nibabel's 4-D series are refused") {
    checkError(errorOf([&] { readNifti(kNibabelData + "/functional.nii"); }), "functional.nii", "20 volumes (dim[4])");
    checkError(errorOf([&] { readNifti(kNibabelData + "/example4d.nii.gz"); }), "example4d.nii.gz", "2 volumes (dim[4])");
  }
  SUBCASE("more samples than the scene budget") {
    checkNiftiError(dir, "huge.nii", niftiFile(niftiHeader(32767, 32767, 32767, DT_FLOAT32, 32), ""),
                    "32767x32767x32767 float32 samples need 281 TB, more than the scene budget of 1 GiB");
    checkNiftiError(dir, "large.nii", niftiFile(niftiHeader(1024, 1024, 210, DT_UINT8, 8), ""),
                    "1024x1024x210 uint8 samples need 1.10 GB, more than the scene budget of 1 GiB");
  }
}

TEST_CASE("NIfTI reader: nibabel's anatomical.nii MRI and standard.nii.gz as nibabel reads them") {
  // python3 -c "import nibabel; i = nibabel.load('anatomical.nii'); d = i.get_fdata();
  //             print(i.shape, i.header.get_zooms(), d.min(), d.max(), d[0,0,0], d[10,20,12], d[32,40,24])"
  const Volume mri = loadVolume(kNibabelData + "/anatomical.nii", 64);
  CHECK(mri.size == glm::ivec3(33, 41, 25));
  CHECK(mri.spacing == glm::vec3(2.0f));
  CHECK(mri.minValue == -610.0f);
  CHECK(mri.maxValue == 30393.0f);
  CHECK(mri.at(0, 0, 0) == 10712.0f);
  CHECK(mri.at(1, 0, 0) == 10463.0f);
  CHECK(mri.at(0, 1, 0) == 6349.0f);
  CHECK(mri.at(0, 0, 1) == 8026.0f);
  CHECK(mri.at(10, 20, 12) == 10872.0f);
  CHECK(mri.at(32, 40, 24) == 2971.0f);
  CHECK(mri.at(24, 32, 14) == -610.0f);
  CHECK(mri.at(17, 23, 0) == 30393.0f);
  double sum = 0.0;
  for (const float v : mri.values) sum += v;
  CHECK(sum == 284166082.0);

  const Volume standard = readNifti(kNibabelData + "/standard.nii.gz");
  CHECK(standard.size == glm::ivec3(4, 5, 7));
  CHECK(standard.spacing == glm::vec3(1.0f, 3.0f, 2.0f));
  CHECK(standard.minValue == 0.0f);
  CHECK(standard.maxValue == 255.0f);
  CHECK(std::count(standard.values.begin(), standard.values.end(), 255.0f) == 30);
  CHECK(standard.at(1, 0, 0) == 255.0f);
  CHECK(standard.at(0, 1, 0) == 255.0f);
  CHECK(standard.at(3, 1, 0) == 255.0f);
  CHECK(standard.at(3, 3, 0) == 255.0f);
  CHECK(standard.at(0, 0, 0) == 0.0f);
}

// [SECTION] Both readers: one table of sample types

namespace {

// How each format writes a type of the table (a test-side copy, so that the
// table is held to the formats), and the ramp's offset for it.
struct FormatType {
  const char* nrrd;
  short datatype, bitpix;
  int offset;
};

FormatType formatType(SampleKind kind) {
  switch (kind) {
    case SampleKind::Int8: return {"int8", DT_INT8, 8, -120};
    case SampleKind::UInt8: return {"uint8", DT_UINT8, 8, 0};
    case SampleKind::Int16: return {"int16", DT_INT16, 16, -1000};
    case SampleKind::UInt16: return {"uint16", DT_UINT16, 16, 60000};
    case SampleKind::Float32: return {"float", DT_FLOAT32, 32, -50};
    case SampleKind::Int32: return {"int32", DT_INT32, 32, 0};
    case SampleKind::UInt32: return {"uint32", DT_UINT32, 32, 0};
    case SampleKind::Int64: return {"int64", DT_INT64, 64, 0};
    case SampleKind::UInt64: return {"uint64", DT_UINT64, 64, 0};
    case SampleKind::Float64: return {"double", DT_FLOAT64, 64, 0};
    case SampleKind::Count: break;
  }
  FAIL("no such sample kind");
  return {};
}

// A 4x3x2 ramp of the kind's samples (zeros for a type facet does not read).
std::string rampSamples(SampleKind kind, int offset, bool bigEndian) {
  switch (kind) {
    case SampleKind::Int8: return samplesOf(rampValues<std::int8_t>(4, 3, 2, offset), bigEndian);
    case SampleKind::UInt8: return samplesOf(rampValues<std::uint8_t>(4, 3, 2, offset), bigEndian);
    case SampleKind::Int16: return samplesOf(rampValues<std::int16_t>(4, 3, 2, offset), bigEndian);
    case SampleKind::UInt16: return samplesOf(rampValues<std::uint16_t>(4, 3, 2, offset), bigEndian);
    case SampleKind::Float32: return samplesOf(rampValues<float>(4, 3, 2, offset), bigEndian);
    default: return std::string(24 * sampleType(kind).bytes, '\0');
  }
}

}  // namespace

TEST_CASE("sample types: NRRD and NIfTI read each type of the one table alike, in either byte order, and refuse the others alike") {
  const fs::path dir = test::scratchFolder("volume_readers", "sample_types");
  CHECK(readSampleTypeNames() == "int8, uint8, int16, uint16 and float32");
  for (int i = 0; i < static_cast<int>(SampleKind::Count); ++i) {
    const SampleKind kind = static_cast<SampleKind>(i);
    const SampleType& type = sampleType(kind);
    const FormatType f = formatType(kind);
    CAPTURE(type.name);
    writeFile(dir / "little.nrrd", nrrdHeader(f.nrrd, "4 3 2") + "\n" + rampSamples(kind, f.offset, false));
    writeFile(dir / "big.nrrd", nrrdHeader(f.nrrd, "4 3 2", "encoding: raw\nendian: big\n") + "\n" + rampSamples(kind, f.offset, true));
    const nifti_1_header h = niftiHeader(4, 3, 2, f.datatype, f.bitpix);
    writeFile(dir / "native.nii", niftiFile(h, rampSamples(kind, f.offset, false)));
    nifti_1_header swapped = h;
    swapHeader(swapped);
    writeFile(dir / "swapped.nii", niftiFile(swapped, rampSamples(kind, f.offset, true)));
    nifti_1_header scaled = h;
    scaled.scl_slope = 2.0f;
    scaled.scl_inter = -3.0f;
    writeFile(dir / "scaled.nii", niftiFile(scaled, rampSamples(kind, f.offset, false)));

    if (!type.toFloat) {
      const std::string refusal = std::string(type.name) + " samples are not supported (int8, uint8, int16, uint16 and float32 are)";
      checkError(errorOf([&] { readNrrd((dir / "little.nrrd").string()); }), "little.nrrd", refusal);
      checkError(errorOf([&] { readNifti((dir / "native.nii").string()); }), "native.nii", refusal);
      continue;
    }
    CHECK(type.bytes * 8 == static_cast<std::size_t>(f.bitpix));  // and readNifti holds it to niftiio's bytes per voxel
    checkRamp(readNrrd((dir / "little.nrrd").string()), f.offset);
    checkRamp(readNrrd((dir / "big.nrrd").string()), f.offset);
    checkRamp(readNifti((dir / "native.nii").string()), f.offset);
    checkRamp(readNifti((dir / "swapped.nii").string()), f.offset);
    const Volume v = readNifti((dir / "scaled.nii").string());
    for (int z = 0; z < 2; ++z)
      for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x) REQUIRE(v.at(x, y, z) == static_cast<float>(2.0 * (f.offset + x + 10 * y + 100 * z) - 3.0));
  }
}

// [SECTION] loadVolume

TEST_CASE("loadVolume: the built-in volume, extensions in any case, and names it cannot read") {
  const fs::path dir = test::scratchFolder("volume_readers", "load_volume");
  CHECK(loadVolume("builtin:marschner-lobb", 9).size == glm::ivec3(9));
  checkError(errorOf([] { loadVolume("builtin:marschner-lobb", 1); }), "volume.resolution", "1 is out of range [2, 512]");
  checkError(errorOf([] { loadVolume("builtin:marschner-lobb", 513); }), "volume.resolution", "513 is out of range [2, 512]");
  checkError(errorOf([] { loadVolume("builtin:engine", 64); }), "builtin:engine", "no such built-in volume");
  writeFile(dir / "ramp.raw", "x");
  checkError(errorOf([&] { loadVolume((dir / "ramp.raw").string(), 64); }), "ramp.raw",
             "unknown volume format (supported: .nrrd, .nhdr, .nii, .nii.gz");
  checkError(errorOf([&] { loadVolume((dir / "absent.nii").string(), 64); }), "absent.nii", "no such file");
  writeFile(dir / "UPPER.NRRD", nrrdHeader("uchar", "2 2 2") + "\n" + samplesOf(rampValues<std::uint8_t>(2, 2, 2)));
  checkRamp(loadVolume((dir / "UPPER.NRRD").string(), 64));
}

// [SECTION] Marschner-Lobb

TEST_CASE("Marschner-Lobb: the formula of the paper, values in [0, 1] on [-1, 1] cubed") {
  const int n = 41;  // sample 20 sits on 0
  const Volume v = makeMarschnerLobb(n);
  CHECK(v.source == "builtin:marschner-lobb");
  CHECK(v.size == glm::ivec3(n));
  CHECK(v.spacing == glm::vec3(0.05f));
  CHECK(v.extent().x == doctest::Approx(2.0));
  for (const float value : v.values) REQUIRE((value >= 0.0f && value <= 1.0f));
  // On the z axis r = 0, so ρ_r = cos(2π·6) = 1: ρ(0, 0, −1) = 1 and ρ(0, 0, 1) = 0.2.
  CHECK(v.at(20, 20, 0) == doctest::Approx(1.0).epsilon(1e-6));
  CHECK(v.at(20, 20, n - 1) == doctest::Approx(0.2).epsilon(1e-6));
  CHECK(v.at(20, 20, 20) == doctest::Approx(0.6).epsilon(1e-6));
  const auto coordinate = [&](int i) { return -1.0 + 2.0 * i / (n - 1); };
  for (const glm::ivec3 s : {glm::ivec3(0, 0, 0), glm::ivec3(3, 17, 29), glm::ivec3(40, 5, 11), glm::ivec3(25, 31, 8), glm::ivec3(12, 20, 33)}) {
    CAPTURE(s.x);
    CAPTURE(s.y);
    CAPTURE(s.z);
    const double expected = marschnerLobbFormula(coordinate(s.x), coordinate(s.y), coordinate(s.z));
    CHECK(v.at(s.x, s.y, s.z) == static_cast<float>(expected));  // computed in double, rounded once
  }
  CHECK(marschnerLobb(0.3f, -0.7f, 0.25f) == static_cast<float>(marschnerLobbFormula(0.3f, -0.7f, 0.25f)));
  CHECK(marschnerLobb(0.0f, 0.0f, -1.0f) == 1.0f);
  CHECK(v.minValue >= 0.0f);
  CHECK(v.maxValue == doctest::Approx(1.0).epsilon(1e-6));
  checkError(errorOf([] { makeMarschnerLobb(0); }), "volume.resolution", "0 is out of range");
  CHECK(makeMarschnerLobb(2).values.size() == 8);
}

// [SECTION] Trilinear interpolation, gradients, range

TEST_CASE("volume trilinear: exact at samples, linear along edges, the cube centre, clamped outside") {
  // Spacing differs per axis, values differ per axis: a swapped axis shows.
  const glm::vec3 spacing(0.5f, 2.0f, 4.0f);
  const Volume v = smallVolume({3, 4, 5}, spacing, [](int x, int y, int z) {
    return static_cast<float>(x * x + 7 * y * y * y + 100 * z - 3 * x * y * z);
  });
  for (int z = 0; z < 5; ++z)
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 3; ++x) REQUIRE(trilinear(v, glm::vec3(x, y, z) * spacing) == v.at(x, y, z));
  // Along an x edge from sample (1, 2, 3) to (2, 2, 3): a quarter of the way.
  const float a = v.at(1, 2, 3), b = v.at(2, 2, 3);
  CHECK(trilinear(v, glm::vec3(1.25f, 2.0f, 3.0f) * spacing) == a + 0.25f * (b - a));
  // Along a z edge from (0, 1, 2) to (0, 1, 3).
  const float c = v.at(0, 1, 2), d = v.at(0, 1, 3);
  CHECK(trilinear(v, glm::vec3(0.0f, 1.0f, 2.75f) * spacing) == c + 0.75f * (d - c));
  // The centre of cell (1, 2, 3): the mean of its 8 corners.
  float mean = 0.0f;
  for (int k = 0; k < 8; ++k) mean += v.at(1 + (k & 1), 2 + ((k >> 1) & 1), 3 + (k >> 2));
  CHECK(trilinear(v, glm::vec3(1.5f, 2.5f, 3.5f) * spacing) == doctest::Approx(mean / 8.0f));
  // A field linear in x, y and z is reproduced anywhere.
  const Volume linear = smallVolume({4, 3, 5}, spacing, [](int x, int y, int z) {
    return 1.0f + 2.0f * static_cast<float>(x) - 3.0f * static_cast<float>(y) + 0.5f * static_cast<float>(z);
  });
  const glm::vec3 p(0.8f, 3.1f, 9.7f);
  const glm::vec3 g = p / spacing;
  CHECK(trilinear(linear, p) == doctest::Approx(1.0f + 2.0f * g.x - 3.0f * g.y + 0.5f * g.z));
  // Outside the box: the nearest point on it.
  CHECK(trilinear(v, glm::vec3(-5.0f, -1.0f, -0.1f)) == v.at(0, 0, 0));
  CHECK(trilinear(v, glm::vec3(100.0f, 100.0f, 100.0f)) == v.at(2, 3, 4));
  CHECK(trilinear(v, glm::vec3(1.0f, 100.0f, 8.0f)) == v.at(2, 3, 2));
  CHECK(trilinear(v, glm::vec3(std::nanf(""), 0.0f, 0.0f)) == v.at(0, 0, 0));
}

TEST_CASE("volume trilinear: along x, then y, then z, each lerp rounded once") {
  const Volume v = smallVolume({2, 2, 2}, glm::vec3(1.0f), [](int x, int y, int z) {
    // Corners and fractions for which each of the six orders rounds differently.
    const float corners[8] = {-5.4f, -6.5f, 1.0f, 5.8f, 8.2f, 8.8f, -7.3f, -1.0f};
    return corners[x + 2 * y + 4 * z];
  });
  const float tx = 0.5f, ty = 0.4f, tz = 0.8f;
  const auto lerp = [](float a, float b, float t) { return a + t * (b - a); };
  const float c00 = lerp(v.at(0, 0, 0), v.at(1, 0, 0), tx), c10 = lerp(v.at(0, 1, 0), v.at(1, 1, 0), tx);
  const float c01 = lerp(v.at(0, 0, 1), v.at(1, 0, 1), tx), c11 = lerp(v.at(0, 1, 1), v.at(1, 1, 1), tx);
  const float expected = lerp(lerp(c00, c10, ty), lerp(c01, c11, ty), tz);
  // The same corners along y first: another float, so the order shows.
  const float yFirst = lerp(lerp(lerp(v.at(0, 0, 0), v.at(0, 1, 0), ty), lerp(v.at(1, 0, 0), v.at(1, 1, 0), ty), tx),
                            lerp(lerp(v.at(0, 0, 1), v.at(0, 1, 1), ty), lerp(v.at(1, 0, 1), v.at(1, 1, 1), ty), tx), tz);
  REQUIRE(yFirst != expected);
  CHECK(trilinear(v, glm::vec3(tx, ty, tz)) == expected);
}

TEST_CASE("volume sampleGradient: central differences inside, one-sided at the border, per model-space unit") {
  const glm::vec3 spacing(0.5f, 2.0f, 4.0f);
  // Linear in model space: f = 3·X + 5·Y − 2·Z with X = x·0.5, Y = y·2, Z = z·4.
  const Volume linear = smallVolume({4, 3, 5}, spacing, [](int x, int y, int z) {
    return 3.0f * 0.5f * static_cast<float>(x) + 5.0f * 2.0f * static_cast<float>(y) - 2.0f * 4.0f * static_cast<float>(z);
  });
  for (const glm::ivec3 s : {glm::ivec3(0, 0, 0), glm::ivec3(1, 1, 2), glm::ivec3(3, 2, 4), glm::ivec3(2, 0, 4)}) {
    const glm::vec3 g = sampleGradient(linear, s.x, s.y, s.z);
    CHECK(g.x == doctest::Approx(3.0f));
    CHECK(g.y == doctest::Approx(5.0f));
    CHECK(g.z == doctest::Approx(-2.0f));
  }
  // x² per sample index: central 2x inside, one-sided at the ends.
  const Volume square = smallVolume({5, 2, 2}, glm::vec3(1.0f), [](int x, int, int) { return static_cast<float>(x * x); });
  CHECK(sampleGradient(square, 2, 0, 0).x == 4.0f);   // (9 − 1) / 2
  CHECK(sampleGradient(square, 0, 1, 1).x == 1.0f);   // (1 − 0) / 1
  CHECK(sampleGradient(square, 4, 0, 1).x == 7.0f);   // (16 − 9) / 1
  CHECK(sampleGradient(square, 2, 0, 0).y == 0.0f);
}

TEST_CASE("volume updateRange: over the finite values, 0 and 0 when there are none") {
  Volume v = smallVolume({2, 2, 2}, glm::vec3(1.0f), [](int x, int y, int z) { return static_cast<float>(x - 4 * y + 9 * z); });
  CHECK(v.minValue == -4.0f);
  CHECK(v.maxValue == 10.0f);
  v.values[0] = std::numeric_limits<float>::infinity();
  v.values[2] = std::numeric_limits<float>::quiet_NaN();
  v.values[5] = -std::numeric_limits<float>::infinity();
  updateRange(v);
  CHECK(v.minValue == -3.0f);
  CHECK(v.maxValue == 9.0f);
  std::fill(v.values.begin(), v.values.end(), std::numeric_limits<float>::quiet_NaN());
  updateRange(v);
  CHECK(v.minValue == 0.0f);
  CHECK(v.maxValue == 0.0f);
}
