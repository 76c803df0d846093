// SPDX-License-Identifier: GPL-3.0-or-later
#include "frames/frame_common.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>

namespace bs::frames {

void check_dimensions(const std::string& file, const std::string& field, std::int64_t width, std::int64_t height,
                      const ImportLimits& limits) {
  const ErrorLocation at{file, 0, 0, field};
  if (width < 1 || height < 1)
    throw ImportError(ImportErrorCategory::InvalidValue, at,
                      "image size " + std::to_string(width) + "x" + std::to_string(height) + " is not positive");
  if (width > limits.max_frame_side || height > limits.max_frame_side)
    throw ImportError(ImportErrorCategory::TooLarge, at,
                      "image size " + std::to_string(width) + "x" + std::to_string(height) + " exceeds the limit of " +
                          std::to_string(limits.max_frame_side) + " pixels per side");
  // Both sides are <= 65535 here, so the product fits in 64 bits.
  const auto pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  if (pixels > limits.max_frame_pixels)
    throw ImportError(ImportErrorCategory::TooLarge, at,
                      "image size " + std::to_string(width) + "x" + std::to_string(height) + " (" +
                          std::to_string(pixels) + " pixels) exceeds the limit of " +
                          std::to_string(limits.max_frame_pixels) + " pixels per frame");
}

std::string check_pattern(const std::string& file, const std::string& field, std::string_view pattern) {
  std::string up(pattern);
  std::transform(up.begin(), up.end(), up.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  if (up == "BGGR" || up == "RGGB" || up == "GRBG" || up == "GBRG") return up;
  throw ImportError(
      ImportErrorCategory::InvalidValue, {file, 0, 0, field},
      "Bayer pattern \"" + std::string(pattern.substr(0, 40)) + "\" is not one of BGGR, RGGB, GRBG, GBRG");
}

std::uint64_t file_size(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw ImportError(ImportErrorCategory::Io, {path, 0, 0, {}}, "is a folder, not a file");
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw ImportError(ImportErrorCategory::Io, {path, 0, 0, {}}, "cannot read size: " + ec.message());
  return size;
}

std::ifstream open_binary(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw ImportError(ImportErrorCategory::Io, {path, 0, 0, {}}, "cannot open for reading");
  return f;
}

std::string stem_of(const std::string& path) { return std::filesystem::path(path).stem().string(); }

void check_sample_range(const std::string& file, const Frame& frame, std::uint64_t data_offset) {
  if (frame.bit_depth == 8 || frame.bit_depth == 16) return;  // every stored value is valid
  const unsigned max = (1u << frame.bit_depth) - 1u;
  const std::size_t n = frame.pixels.size() / static_cast<std::size_t>(frame.bytes_per_sample());
  for (std::size_t i = 0; i < n; ++i) {
    unsigned v = 0;
    if (frame.bit_depth > 8) {
      std::uint16_t s;
      std::memcpy(&s, frame.pixels.data() + 2 * i, 2);
      v = s;
    } else {
      v = frame.pixels[i];
    }
    if (v > max) {
      const std::size_t pixel = i / static_cast<std::size_t>(frame.channels);
      const std::size_t row = pixel / static_cast<std::size_t>(frame.width);
      const std::size_t col = pixel % static_cast<std::size_t>(frame.width);
      throw ImportError(ImportErrorCategory::InvalidValue,
                        {file, 0, 0, "offset " + std::to_string(data_offset + i * frame.bytes_per_sample())},
                        "sample at row " + std::to_string(row) + ", column " + std::to_string(col) + " is " +
                            std::to_string(v) + ", above the " + std::to_string(frame.bit_depth) + "-bit maximum " +
                            std::to_string(max) + " (wrong bit depth or byte order?)");
    }
  }
}

Frame make_frame(const std::string& path, std::string_view format, int width, int height, int channels, int bit_depth,
                 std::string pattern) {
  Frame f;
  f.label = stem_of(path);
  f.width = width;
  f.height = height;
  f.channels = channels;
  f.bit_depth = bit_depth;
  f.pattern = std::move(pattern);
  f.source_format = std::string(format);
  f.read_options = "{}";
  f.provenance.source_file = path;
  return f;
}

}  // namespace bs::frames
