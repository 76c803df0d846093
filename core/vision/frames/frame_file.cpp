// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/frames/frame_file.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "image_files/image_files.h"
#include "model/raw_sidecar.h"

namespace bs::vision {
namespace {

[[noreturn]] void fail(const std::string& file, const std::string& why) { throw std::runtime_error(file + ": " + why); }

std::string sidecar_of(const std::string& path) {
  if (auto found = find_raw_sidecar(path)) return *found;
  fail(path, "raw Bayer data needs a JSON sidecar (" + raw_sidecar_path(path) +
                 ") with width, height, pattern, bit_depth and endianness");
}

FrameFile read_raw(const std::string& path) {
  const std::string side = sidecar_of(path);
  std::ifstream sf(side);
  if (!sf) fail(side, "cannot open sidecar");
  const nlohmann::json j = nlohmann::json::parse(sf, nullptr, false);
  if (j.is_discarded() || !j.is_object()) fail(side, "is not a JSON object");
  RawSidecar s;
  try {
    s = raw_sidecar_from_json(j);  // the rules every reader of sidecars shares (model/raw_sidecar.h)
  } catch (const RawSidecarError& e) {
    fail(side, e.what());
  }
  const int w = s.width, h = s.height;
  if (w < 2 || h < 2)
    fail(side,
         "/width: a " + std::to_string(w) + "x" + std::to_string(h) + " frame is smaller than one 2x2 Bayer cell");
  FrameFile f;
  f.bit_depth = s.bit_depth;
  if (s.pattern) {
    f.pattern = bayer_pattern_from_string(*s.pattern);
    f.pattern_from_file = true;
  }
  const bool big_endian = s.big_endian;
  const std::size_t bytes = f.bit_depth > 8 ? 2 : 1;
  const std::uintmax_t expected = static_cast<std::uintmax_t>(w) * static_cast<std::uintmax_t>(h) * bytes;
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) fail(path, "cannot read: " + ec.message());
  // Checked before allocating: the sidecar's size claim must match the bytes that are really there.
  if (size != expected)
    fail(path, "is " + std::to_string(size) + " bytes; the sidecar's " + std::to_string(w) + "x" + std::to_string(h) +
                   " at " + std::to_string(f.bit_depth) + " bits needs " + std::to_string(expected));
  f.mosaic.create(h, w, bytes == 1 ? CV_8UC1 : CV_16UC1);
  std::ifstream in(path, std::ios::binary);
  in.read(reinterpret_cast<char*>(f.mosaic.data), static_cast<std::streamsize>(expected));
  if (static_cast<std::uintmax_t>(in.gcount()) != expected) fail(path, "read error");
  if (bytes == 2 && big_endian) {
    for (int r = 0; r < h; ++r) {
      auto* row = f.mosaic.ptr<std::uint16_t>(r);
      for (int c = 0; c < w; ++c) row[c] = static_cast<std::uint16_t>((row[c] >> 8) | (row[c] << 8));
    }
  }
  if (f.bit_depth < 8 * static_cast<int>(bytes)) {
    double max = 0;
    cv::minMaxLoc(f.mosaic, nullptr, &max);
    if (max >= (1 << f.bit_depth))
      fail(path, "holds the value " + std::to_string(static_cast<int>(max)) + ", more than " +
                     std::to_string(f.bit_depth) + " bits (wrong bit_depth or endianness in the sidecar?)");
  }
  return f;
}

}  // namespace

FrameFile read_frame_file(const std::string& path, BayerPattern default_pattern) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) fail(path, "no such file");
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".raw" || ext == ".bin") return read_raw(path);
  const cv::Mat img = bs::image_files::read(path, cv::IMREAD_UNCHANGED);
  if (img.empty()) fail(path, "not an image OpenCV can read (PNG, PGM, TIFF) and not raw Bayer (.raw + .json)");
  if (img.channels() != 1)
    fail(path, "has " + std::to_string(img.channels()) +
                   " channels; the pipeline needs the camera's raw Bayer mosaic (one channel, shown as grey)");
  if (img.depth() != CV_8U && img.depth() != CV_16U) fail(path, "must be 8- or 16-bit");
  if (img.cols < 2 || img.rows < 2) fail(path, "is smaller than one 2x2 Bayer cell");
  FrameFile f;
  f.mosaic = img;
  f.bit_depth = img.depth() == CV_8U ? 8 : 16;
  f.pattern = default_pattern;
  return f;
}

cv::Mat to_8bit(const cv::Mat& mosaic, int bit_depth) {
  if (mosaic.depth() == CV_8U) return mosaic;
  cv::Mat out;
  mosaic.convertTo(out, CV_8U, 255.0 / ((1 << bit_depth) - 1));
  return out;
}

}  // namespace bs::vision
