// readNifti: NIfTI-1 volumes (.nii, .nii.gz) through nifti2's niftiio, checked before the samples are read.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <nifti1_io.h>

#include "common/atomic_file.h"
#include "common/error.h"
#include "common/quote.h"
#include "scene/memory_budget.h"
#include "settings/render_settings.h"
#include "volume/load_volume.h"
#include "volume/volume_file.h"

namespace facet {
namespace {

constexpr int kHeaderBytes = 348;       // sizeof_hdr of NIfTI-1
constexpr int kNifti2HeaderBytes = 540;  // sizeof_hdr of NIfTI-2
// A single-file NIfTI-1 keeps its samples at vox_offset, at least 352: the
// header and the 4-byte extension flag. Older writers (SPM's anatomical.nii
// in nibabel's test data) leave vox_offset 0; nibabel then reads at 352, as here.
constexpr std::uint64_t kMinDataOffset = 352;
constexpr std::size_t kReadChunk = std::size_t{1} << 20;

static_assert(sizeof(nifti_1_header) == kHeaderBytes);

struct ImageFree {
  void operator()(nifti_image* image) const { nifti_image_free(image); }
};

struct ZnzClose {
  void operator()(znzptr* file) const {
    znzFile f = file;
    znzclose(f);
  }
};
using ZnzFile = std::unique_ptr<znzptr, ZnzClose>;

// NIfTI-1's sample types: those of facet's table (volume/volume_file.h), and
// those only NIfTI-1 has.
SampleType niftiSampleType(int datatype) {
  switch (datatype) {
    case DT_INT8: return sampleType(SampleKind::Int8);
    case DT_UINT8: return sampleType(SampleKind::UInt8);
    case DT_INT16: return sampleType(SampleKind::Int16);
    case DT_UINT16: return sampleType(SampleKind::UInt16);
    case DT_FLOAT32: return sampleType(SampleKind::Float32);
    case DT_INT32: return sampleType(SampleKind::Int32);
    case DT_UINT32: return sampleType(SampleKind::UInt32);
    case DT_INT64: return sampleType(SampleKind::Int64);
    case DT_UINT64: return sampleType(SampleKind::UInt64);
    case DT_FLOAT64: return sampleType(SampleKind::Float64);
    case DT_FLOAT128: return {"float128", 16, true};
    case DT_COMPLEX64: return {"complex64", 8, true};
    case DT_COMPLEX128: return {"complex128", 16, true};
    case DT_COMPLEX256: return {"complex256", 32, true};
    case DT_RGB24: return {"RGB24", 3, false};
    case DT_RGBA32: return {"RGBA32", 4, false};
    case DT_BINARY: return {"binary (1-bit)"};
    default: return {nullptr};
  }
}

std::int32_t byteSwapped(std::int32_t v) {
  const auto u = static_cast<std::uint32_t>(v);
  return static_cast<std::int32_t>((u >> 24) | ((u >> 8) & 0xff00u) | ((u << 8) & 0xff0000u) | (u << 24));
}

// The header as the file holds it, in this machine's byte order, refused
// unless everything facet and niftiio rely on is sound: niftiio itself
// prints to stderr on some of these (a bad dim[0], datatype or dim[1])
// whatever its debug level, and sets bad spacings to 1 without a word.
nifti_1_header readCheckedHeader(const std::string& path, const std::string& shown, bool compressed) {
  ZnzFile file(znzopen(path.c_str(), "rb", compressed ? 1 : 0));
  if (!file) throw Error(shown + ": cannot open (" + describeErrno(errno) + ")");
  unsigned char bytes[kHeaderBytes] = {};
  std::size_t got = znzread(bytes, 1, sizeof bytes, file.get());
  if (got == static_cast<std::size_t>(-1)) got = 0;  // a gzip error
  if (!compressed && got >= 2 && bytes[0] == 0x1f && bytes[1] == 0x8b)
    throw Error(shown + ": gzip-compressed (a compressed NIfTI file is named .nii.gz)");
  if (got < sizeof bytes)
    throw Error(shown + ": " + countOf(got, "byte") + (compressed ? " after decompression" : "") + ", shorter than the 348-byte NIfTI-1 header");
  nifti_1_header h;
  std::memcpy(&h, bytes, sizeof h);
  bool swapped = false;
  if (h.sizeof_hdr != kHeaderBytes) {
    const std::int32_t other = byteSwapped(h.sizeof_hdr);
    if (h.sizeof_hdr == kNifti2HeaderBytes || other == kNifti2HeaderBytes) throw Error(shown + ": a NIfTI-2 file; facet reads NIfTI-1");
    if (other != kHeaderBytes) throw Error(shown + ": not a NIfTI-1 file (sizeof_hdr is " + std::to_string(h.sizeof_hdr) + ", not 348)");
    swapped = true;
  }
  if (swapped) swap_nifti_header(&h, 1);
  if (std::memcmp(h.magic, "ni1", 4) == 0)
    throw Error(shown + ": a NIfTI-1 header whose samples are in a separate .img file (magic ni1); facet reads single .nii files");
  if (std::memcmp(h.magic, "n+1", 4) != 0) throw Error(shown + ": not a single-file NIfTI-1 (its magic is not n+1)");

  const int dims = h.dim[0];
  if (dims == 4 && h.dim[4] != 1)
    throw Error(shown + ": " + std::to_string(h.dim[4]) + " volumes (dim[4]), facet reads one 3-D volume");
  if (dims != 3 && dims != 4) throw Error(shown + ": " + std::to_string(dims) + " dimensions (dim[0]), a volume has 3");
  for (int a = 0; a < 3; ++a) {
    const int n = h.dim[a + 1];
    if (n < 2)
      throw Error(shown + ": " + std::to_string(n) + (n == 1 ? " sample" : " samples") + " along " + kAxisNames[a] + " (dim[" +
                  std::to_string(a + 1) + "]), a volume needs at least 2");
  }
  const SampleType type = niftiSampleType(h.datatype);
  if (!type.toFloat) {
    const std::string name = type.name ? type.name : "datatype " + std::to_string(h.datatype);
    throw Error(shown + ": " + name + " samples are not supported (" + readSampleTypeNames() + " are)");
  }
  for (int a = 0; a < 3; ++a) {
    const float spacing = h.pixdim[a + 1];
    if (!(std::isfinite(spacing) && spacing > 0.0f))
      throw Error(shown + ": spacing along " + kAxisNames[a] + " (pixdim[" + std::to_string(a + 1) + "]) is " + shownNumber(spacing) +
                  ", not a positive number");
  }
  // niftiio converts vox_offset to an int.
  if (!(std::isfinite(h.vox_offset) && h.vox_offset >= 0.0f && h.vox_offset < 2147483648.0f))
    throw Error(shown + ": vox_offset " + shownNumber(h.vox_offset) + " is not a byte offset into the file");
  return h;
}

}  // namespace

Volume readNifti(const std::string& path) {
  const std::string shown = shownPath(path);
  requireRegularFile(path, shown);
  // niftiio reports problems on stderr at its default level 1; here they
  // become one facet::Error line instead.
  nifti_set_debug_level(0);
  const bool compressed = nifti_is_gzfile(path.c_str()) != 0;
  const nifti_1_header header = readCheckedHeader(path, shown, compressed);
  const SampleType type = niftiSampleType(header.datatype);

  Volume volume;
  volume.source = path;
  std::string dims;
  for (int a = 0; a < 3; ++a) {
    volume.size[a] = header.dim[a + 1];
    if (a) dims += 'x';
    dims += std::to_string(header.dim[a + 1]);
  }
  const std::string samples = dims + " " + type.name + " samples";
  const std::uint64_t count = volume.sampleCount();  // at most 32767³, no overflow
  const std::uint64_t dataBytes = count * type.bytes;
  const std::uint64_t offset = std::max<std::uint64_t>(kMinDataOffset, static_cast<std::uint64_t>(header.vox_offset));

  // Priced before niftiio or facet allocates: the floats kept, the file's
  // samples read first, and the header extensions niftiio reads before vox_offset.
  const std::uint64_t perSample = sizeof(float) + type.bytes;
  MemoryBudget budget(kSceneMemoryBudget, "scene budget");
  budget.charge(count * perSample, shown + ": " + samples);
  if (offset > kMinDataOffset) budget.charge(offset - kMinDataOffset, shown + ": header extensions before vox_offset " + std::to_string(offset));
  if (!compressed) {
    std::error_code ec;
    const std::uint64_t fileBytes = std::filesystem::file_size(path, ec);
    if (ec) throw Error(shown + ": " + ec.message());
    if (fileBytes < offset || fileBytes - offset < dataBytes)
      throw Error(shown + ": " + samples + " need " + std::to_string(dataBytes) + " bytes after offset " + std::to_string(offset) +
                  ", the file holds " + std::to_string(fileBytes > offset ? fileBytes - offset : 0));
  }

  std::unique_ptr<nifti_image, ImageFree> image(nifti_image_read(path.c_str(), 0));
  if (!image) throw Error(shown + ": niftiio cannot read its header");
  if (image->nx != volume.size.x || image->ny != volume.size.y || image->nz != volume.size.z || image->nvox != count ||
      image->datatype != header.datatype || static_cast<std::size_t>(image->nbyper) != type.bytes)
    throw Error(shown + ": niftiio reads its header differently");
  for (int a = 0; a < 3; ++a) volume.spacing[a] = image->pixdim[a + 1];
  requireBoundedBox(volume, shown);

  // The samples through znzlib (niftiio's file layer) in chunks: unlike
  // nifti_image_load, this tells a gzip error from a complete read.
  std::vector<unsigned char> bytes(static_cast<std::size_t>(dataBytes));
  {
    ZnzFile file(znzopen(path.c_str(), "rb", compressed ? 1 : 0));
    if (!file) throw Error(shown + ": cannot open (" + describeErrno(errno) + ")");
    const std::string truncated = shown + ": " + (compressed ? "truncated or corrupt gzip data (" : "the file ends early (") + samples + " need " +
                                  std::to_string(dataBytes) + " bytes after offset " + std::to_string(offset) + ")";
    if (znzseek(file.get(), static_cast<znz_off_t>(offset), SEEK_SET) < 0) throw Error(truncated);
    for (std::size_t done = 0; done < bytes.size();) {
      const std::size_t chunk = std::min(kReadChunk, bytes.size() - done);
      const std::size_t got = znzread(bytes.data() + done, 1, chunk, file.get());
      if (got != chunk) throw Error(truncated);  // short, or (size_t)-1 for a gzip error
      done += chunk;
    }
  }

  const bool swap = type.bytes > 1 && image->byteorder != nifti_short_order();
  // niftiio has already set a non-finite slope or intercept to 0.
  const double slope = image->scl_slope, intercept = image->scl_inter;
  volume.values.resize(static_cast<std::size_t>(count));
  type.toFloat(bytes.data(), swap, SampleScale{slope, intercept}, volume.values);
  updateRange(volume);
  return volume;
}

}  // namespace facet
