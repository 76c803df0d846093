// SPDX-License-Identifier: GPL-3.0-or-later
#include "frames/frame_codec.h"

#include <cstring>
#include <fstream>
#include <map>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "frames/frame_common.h"
#include "image_files/image_files.h"

namespace bs {
namespace {

constexpr std::string_view kPngMagic("\x89PNG\r\n\x1a\n", 8);

[[noreturn]] void fail(ImportErrorCategory c, const std::string& file, std::uint64_t offset, const std::string& why) {
  throw ImportError(c, {file, 0, 0, "offset " + std::to_string(offset)}, why);
}

// Reads `n` bytes at `offset`; false when the file is shorter.
bool read_at(std::ifstream& f, std::uint64_t offset, void* out, std::size_t n) {
  f.clear();
  f.seekg(static_cast<std::streamoff>(offset));
  f.read(static_cast<char*>(out), static_cast<std::streamsize>(n));
  return static_cast<std::size_t>(f.gcount()) == n;
}

std::uint32_t be32(const unsigned char* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | p[3];
}

// Decoded by OpenCV into a frame: 8/16-bit, 1 or 3 channels (alpha dropped, 2-channel grey+alpha -> grey).
Frame frame_from_mat(const std::string& path, std::string_view format, cv::Mat img, int significant_bits) {
  if (img.depth() != CV_8U && img.depth() != CV_16U)
    throw ImportError(ImportErrorCategory::Unsupported, {path, 0, 0, "sample type"},
                      "only 8- and 16-bit integer samples are supported (this file has OpenCV depth " +
                          std::to_string(img.depth()) + ")");
  if (img.channels() == 4) cv::cvtColor(img, img, cv::COLOR_BGRA2BGR);
  if (img.channels() == 2) cv::extractChannel(img, img, 0);
  if (img.channels() != 1 && img.channels() != 3)
    throw ImportError(ImportErrorCategory::Unsupported, {path, 0, 0, "channels"},
                      std::to_string(img.channels()) + " channels; only grey and colour images are supported");
  const int container_bits = img.depth() == CV_16U ? 16 : 8;
  const int bits = significant_bits > 0 && significant_bits <= container_bits && significant_bits > container_bits - 8
                       ? significant_bits
                       : container_bits;
  Frame frame =
      frames::make_frame(path, format, img.cols, img.rows, img.channels(), bits, img.channels() == 1 ? "BGGR" : "");
  frame.pixels.resize(frame.expected_bytes());
  const std::size_t row_bytes = static_cast<std::size_t>(img.cols) * img.elemSize();
  for (int y = 0; y < img.rows; ++y)
    std::memcpy(frame.pixels.data() + static_cast<std::size_t>(y) * row_bytes, img.ptr(y), row_bytes);
  frames::check_sample_range(path, frame, 0);
  return frame;
}

cv::Mat decode(const std::string& path, std::string_view what) {
  cv::Mat img;
  try {
    img = bs::image_files::read(path, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {
    throw ImportError(ImportErrorCategory::Syntax, {path, 0, 0, "pixels"},
                      std::string(what) + " decoder failed: " + e.err);
  }
  if (img.empty())
    throw ImportError(ImportErrorCategory::Syntax, {path, 0, 0, "pixels"},
                      std::string(what) + " decoder could not read the image data (damaged or truncated file)");
  return img;
}

}  // namespace

// ---- PNG ------------------------------------------------------------------------------------------------------

static int sniff_png(std::string_view head, std::string_view) { return head.starts_with(kPngMagic) ? 100 : 0; }

static ImportBatch parse_png_file(const std::string& path, const ParseOptions& /*options*/, const ImportLimits& limits,
                                  const CancelToken& cancel) {
  const std::uint64_t size = frames::file_size(path);
  std::ifstream f = frames::open_binary(path);
  char magic[8];
  if (!read_at(f, 0, magic, 8) || std::string_view(magic, 8) != kPngMagic)
    fail(ImportErrorCategory::UnknownFormat, path, 0, "no PNG signature");
  // Walk the chunk chain: length (4, big-endian), type (4), data, CRC (4). Every chunk must lie inside the file;
  // a file cut short loses IEND (or a chunk runs past the end), which is how truncation shows without decoding.
  std::uint64_t at = 8;
  std::int64_t width = 0, height = 0;
  int bit_depth = 0, colour_type = 0, significant_bits = 0;
  bool seen_ihdr = false, seen_idat = false, seen_iend = false;
  for (int chunk = 0; !seen_iend; ++chunk) {
    if ((chunk & 1023) == 0) cancel.throw_if_cancelled();
    unsigned char hdr[8];
    if (!read_at(f, at, hdr, 8))
      fail(ImportErrorCategory::Syntax, path, at,
           "file is truncated: it ends at byte " + std::to_string(size) + " before the IEND chunk");
    const std::uint32_t len = be32(hdr);
    const std::string type(reinterpret_cast<const char*>(hdr + 4), 4);
    if (len > 0x7FFFFFFFu) fail(ImportErrorCategory::Syntax, path, at, "chunk length exceeds 2^31-1");
    if (at + 12 + len > size)
      fail(ImportErrorCategory::Syntax, path, at,
           "file is truncated: chunk " + type + " claims " + std::to_string(len) + " bytes but the file ends at byte " +
               std::to_string(size));
    if (chunk == 0) {
      if (type != "IHDR" || len != 13) fail(ImportErrorCategory::Syntax, path, at, "first chunk is not a 13-byte IHDR");
      unsigned char ihdr[13];
      read_at(f, at + 8, ihdr, 13);
      width = be32(ihdr);
      height = be32(ihdr + 4);
      bit_depth = ihdr[8];
      colour_type = ihdr[9];
      frames::check_dimensions(path, "IHDR width", width, height, limits);
      if (bit_depth != 1 && bit_depth != 2 && bit_depth != 4 && bit_depth != 8 && bit_depth != 16)
        fail(ImportErrorCategory::InvalidValue, path, at + 16,
             "IHDR bit depth " + std::to_string(bit_depth) + " is invalid");
      seen_ihdr = true;
    } else if (type == "sBIT" && len >= 1) {
      unsigned char s = 0;
      read_at(f, at + 8, &s, 1);
      if (colour_type == 0 || colour_type == 4) significant_bits = s;
    } else if (type == "IDAT") {
      seen_idat = true;
    } else if (type == "IEND") {
      seen_iend = true;
    }
    at += 12 + len;
  }
  if (!seen_ihdr || !seen_idat) fail(ImportErrorCategory::Syntax, path, 8, "no image data (IDAT) before IEND");
  cancel.throw_if_cancelled();
  cv::Mat img = decode(path, "PNG");
  if (img.cols != width || img.rows != height)
    fail(ImportErrorCategory::Syntax, path, 16, "decoded size differs from IHDR");
  ImportBatch batch;
  batch.frames.push_back(frame_from_mat(path, "png", std::move(img), significant_bits));
  return batch;
}

// ---- TIFF -----------------------------------------------------------------------------------------------------

namespace {

struct TiffReader {
  std::ifstream& f;
  const std::string& path;
  std::uint64_t size;
  bool big;
  std::uint32_t u16(std::uint64_t at) {
    unsigned char b[2];
    if (!read_at(f, at, b, 2))
      fail(ImportErrorCategory::Syntax, path, at, "file is truncated inside the TIFF directory");
    return big ? (b[0] << 8 | b[1]) : (b[1] << 8 | b[0]);
  }
  std::uint32_t u32(std::uint64_t at) {
    unsigned char b[4];
    if (!read_at(f, at, b, 4))
      fail(ImportErrorCategory::Syntax, path, at, "file is truncated inside the TIFF directory");
    return big ? be32(b) : (std::uint32_t{b[3]} << 24 | std::uint32_t{b[2]} << 16 | std::uint32_t{b[1]} << 8 | b[0]);
  }
};

struct TiffEntry {
  std::uint32_t type = 0, count = 0;
  std::uint64_t value_at = 0;  // offset of the value(s): inside the entry when they fit in 4 bytes
};

}  // namespace

static int sniff_tiff(std::string_view head, std::string_view) {
  if (head.starts_with(std::string_view("II*\0", 4)) || head.starts_with(std::string_view("MM\0*", 4))) return 100;
  return 0;
}

static ImportBatch parse_tiff_file(const std::string& path, const ParseOptions& /*options*/, const ImportLimits& limits,
                                   const CancelToken& cancel) {
  const std::uint64_t size = frames::file_size(path);
  std::ifstream f = frames::open_binary(path);
  char magic[4];
  if (!read_at(f, 0, magic, 4)) fail(ImportErrorCategory::Syntax, path, 0, "file is shorter than a TIFF header");
  const bool big = magic[0] == 'M';
  TiffReader r{f, path, size, big};
  const std::uint64_t ifd = r.u32(4);
  if (ifd < 8)
    fail(ImportErrorCategory::Syntax, path, 4,
         "first directory offset " + std::to_string(ifd) + " is inside the header");
  if (ifd + 2 > size)
    fail(ImportErrorCategory::Syntax, path, 4,
         "file is truncated: the first directory is at byte " + std::to_string(ifd) + ", the file has " +
             std::to_string(size) + " bytes");
  const std::uint32_t n = r.u16(ifd);
  if (ifd + 2 + 12ull * n + 4 > size)
    fail(ImportErrorCategory::Syntax, path, ifd,
         "file is truncated: the directory's " + std::to_string(n) + " entries run past the end");
  std::map<std::uint32_t, TiffEntry> tags;
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint64_t e = ifd + 2 + 12ull * i;
    TiffEntry t{r.u16(e + 2), r.u32(e + 4), e + 8};
    const std::uint32_t unit = t.type == 3 ? 2 : t.type == 4 ? 4 : t.type == 1 ? 1 : 4;
    if (static_cast<std::uint64_t>(unit) * t.count > 4) t.value_at = r.u32(e + 8);
    tags[r.u16(e)] = t;
  }
  auto value = [&](std::uint32_t tag, std::uint32_t index) -> std::uint64_t {
    const TiffEntry& t = tags.at(tag);
    if (t.type == 3) return r.u16(t.value_at + 2ull * index);
    return r.u32(t.value_at + 4ull * index);
  };
  if (!tags.count(256) || !tags.count(257))
    fail(ImportErrorCategory::MissingField, path, ifd, "directory has no ImageWidth/ImageLength tag");
  const auto width = static_cast<std::int64_t>(value(256, 0));
  const auto height = static_cast<std::int64_t>(value(257, 0));
  frames::check_dimensions(path, "ImageWidth", width, height, limits);
  // Every strip (or tile) must lie inside the file: a cut-short TIFF fails here, with the strip named.
  const bool tiled = tags.count(324) && tags.count(325);
  const std::uint32_t off_tag = tiled ? 324 : 273, len_tag = tiled ? 325 : 279;
  if (!tags.count(off_tag) || !tags.count(len_tag))
    fail(ImportErrorCategory::MissingField, path, ifd, "directory has no strip or tile offsets");
  const std::uint32_t pieces = tags.at(off_tag).count;
  if (pieces != tags.at(len_tag).count || pieces == 0 || pieces > limits.max_frame_pixels)
    fail(ImportErrorCategory::Syntax, path, ifd, "strip/tile offset and byte-count tags disagree");
  if (tags.at(off_tag).value_at + 4ull * pieces > size || tags.at(len_tag).value_at + 4ull * pieces > size)
    fail(ImportErrorCategory::Syntax, path, tags.at(off_tag).value_at, "file is truncated inside the strip tables");
  for (std::uint32_t i = 0; i < pieces; ++i) {
    if ((i & 1023) == 0) cancel.throw_if_cancelled();
    const std::uint64_t off = value(off_tag, i), len = value(len_tag, i);
    if (off + len > size)
      fail(ImportErrorCategory::Syntax, path, off,
           std::string("file is truncated: ") + (tiled ? "tile " : "strip ") + std::to_string(i) + " needs bytes " +
               std::to_string(off) + ".." + std::to_string(off + len) + ", the file has " + std::to_string(size));
  }
  cancel.throw_if_cancelled();
  cv::Mat img = decode(path, "TIFF");
  if (img.cols != width || img.rows != height)
    fail(ImportErrorCategory::Syntax, path, ifd, "decoded size differs from the directory's ImageWidth/ImageLength");
  ImportBatch batch;
  batch.frames.push_back(frame_from_mat(path, "tiff", std::move(img), 0));
  return batch;
}

const FileFormat kPngFileFormat{"png", "PNG image", sniff_png, parse_png_file, nullptr, ".png", true};

const FileFormat kTiffFileFormat{"tiff", "TIFF image", sniff_tiff, parse_tiff_file, nullptr, ".tif .tiff", true};

}  // namespace bs
