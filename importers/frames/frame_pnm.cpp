// SPDX-License-Identifier: GPL-3.0-or-later
#include "frames/frame_pnm.h"

#include <bit>
#include <cctype>
#include <fstream>

#include "frames/frame_common.h"
#include "util/text.h"

namespace bs {
namespace {

constexpr std::size_t kMaxHeaderBytes = 64 * 1024;  // comments included; the head read_head() gives us

struct Header {
  char kind = '5';
  std::int64_t width = 0, height = 0, maxval = 0;
  std::size_t data_offset = 0;
  std::string pattern = "BGGR";
};

class HeaderParser {
 public:
  HeaderParser(std::string_view head, const std::string& file) : head_(head), file_(file) {}

  Header parse() {
    Header h;
    h.kind = head_[1];
    pos_ = 2;
    h.width = number("width");
    h.height = number("height");
    h.maxval = number("maxval");
    // Exactly one whitespace byte separates maxval from the samples (a second one would be a sample).
    if (pos_ >= head_.size() || !std::isspace(static_cast<unsigned char>(head_[pos_])))
      fail(ImportErrorCategory::Syntax, "maxval", "expected one whitespace byte after maxval, then the samples");
    h.data_offset = pos_ + 1;
    if (!pattern_.empty()) h.pattern = pattern_;
    return h;
  }

 private:
  [[noreturn]] void fail(ImportErrorCategory c, const std::string& field, const std::string& reason) const {
    throw ImportError(c, {file_, line_, 0, "header " + field}, reason);
  }

  // Skips whitespace and comments; a comment "# pattern: XXXX" (or "# bayer: XXXX") sets the Bayer pattern.
  void skip_space() {
    while (pos_ < head_.size()) {
      const char c = head_[pos_];
      if (c == '#') {
        const std::size_t end = head_.find('\n', pos_);
        comment(head_.substr(pos_ + 1, end == std::string_view::npos ? std::string_view::npos : end - pos_ - 1));
        if (end == std::string_view::npos) {
          pos_ = head_.size();
          return;
        }
        pos_ = end;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        if (c == '\n') ++line_;
        ++pos_;
      } else {
        return;
      }
    }
  }

  void comment(std::string_view text) {
    const std::string text_lower = bs::lower(text);
    for (std::string_view key : {"pattern:", "bayer:"}) {
      const std::size_t at = text_lower.find(key);
      if (at == std::string::npos) continue;
      std::string value;
      for (std::size_t i = at + key.size(); i < text.size(); ++i)
        if (!std::isspace(static_cast<unsigned char>(text[i]))) value += text[i];
      if (value == "grey" || value == "gray" || value == "none") {
        pattern_ = "-";  // marks "no mosaic"; turned into "" below
      } else {
        pattern_ = frames::check_pattern(file_, "comment " + std::string(key.substr(0, key.size() - 1)), value);
      }
    }
  }

  std::int64_t number(const char* field) {
    skip_space();
    if (pos_ >= head_.size())
      fail(pos_ >= kMaxHeaderBytes ? ImportErrorCategory::TooLarge : ImportErrorCategory::Syntax, field,
           pos_ >= kMaxHeaderBytes ? "header longer than 64 KiB" : "file ends inside the header");
    if (!std::isdigit(static_cast<unsigned char>(head_[pos_])))
      fail(ImportErrorCategory::Syntax, field, "expected a decimal number, found '" + printable(head_[pos_]) + "'");
    std::int64_t v = 0;
    while (pos_ < head_.size() && std::isdigit(static_cast<unsigned char>(head_[pos_]))) {
      v = v * 10 + (head_[pos_] - '0');
      if (v > (std::int64_t{1} << 40)) fail(ImportErrorCategory::TooLarge, field, "number is absurdly large");
      ++pos_;
    }
    return v;
  }

  static std::string printable(char c) {
    if (std::isprint(static_cast<unsigned char>(c))) return std::string(1, c);
    char buf[8];
    std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned char>(c));
    return buf;
  }

 public:
  std::string pattern_;

 private:
  std::string_view head_;
  const std::string& file_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
};

}  // namespace

static int sniff_pnm(std::string_view head, std::string_view) {
  if (head.size() < 3 || head[0] != 'P') return 0;
  const char k = head[1];
  const bool space = std::isspace(static_cast<unsigned char>(head[2])) || head[2] == '#';
  if (!space) return 0;
  if (k == '5' || k == '6') return 100;
  if (k == '2' || k == '3' || k == '7') return 60;  // claimed, to say clearly that they are not supported
  return 0;
}

static ImportBatch parse_pnm_file(const std::string& path, const ParseOptions& /*options*/, const ImportLimits& limits,
                                  const CancelToken& cancel) {
  const std::string head = read_head(path, kMaxHeaderBytes);
  if (head.size() < 3 || head[0] != 'P')
    throw ImportError(ImportErrorCategory::UnknownFormat, {path, 1, 1, {}}, "not a PGM/PPM file (no P5/P6 magic)");
  if (head[1] == '2' || head[1] == '3' || head[1] == '7')
    throw ImportError(ImportErrorCategory::Unsupported, {path, 1, 1, "magic"},
                      std::string("Netpbm variant P") + head[1] +
                          " (ASCII or PAM) is not supported; save as binary PGM (P5) or PPM (P6)");
  if (head[1] != '5' && head[1] != '6')
    throw ImportError(ImportErrorCategory::UnknownFormat, {path, 1, 1, "magic"}, "not a PGM (P5) or PPM (P6) file");
  HeaderParser parser(head, path);
  const Header h = parser.parse();
  const int channels = h.kind == '6' ? 3 : 1;
  frames::check_dimensions(path, "header width", h.width, h.height, limits);
  if (h.maxval < 1 || h.maxval > 65535)
    throw ImportError(ImportErrorCategory::InvalidValue, {path, 0, 0, "header maxval"},
                      "maxval " + std::to_string(h.maxval) + " is not between 1 and 65535");
  const int bits = std::bit_width(static_cast<unsigned>(h.maxval));
  std::string pattern = channels == 1 ? h.pattern : std::string();
  if (pattern == "-") pattern.clear();
  Frame frame =
      frames::make_frame(path, "pnm", static_cast<int>(h.width), static_cast<int>(h.height), channels, bits, pattern);
  const std::uint64_t need = frame.expected_bytes();
  const std::uint64_t size = frames::file_size(path);
  // Checked against the real file size before allocating: the header's claims are untrusted.
  if (size < h.data_offset + need)
    throw ImportError(ImportErrorCategory::Syntax, {path, 0, 0, "offset " + std::to_string(size)},
                      "file is truncated: the header's " + std::to_string(h.width) + "x" + std::to_string(h.height) +
                          (channels == 3 ? "x3" : "") + " samples of " + std::to_string(frame.bytes_per_sample()) +
                          " byte(s) need " + std::to_string(need) + " bytes after the " +
                          std::to_string(h.data_offset) + "-byte header, the file has " +
                          std::to_string(size - std::min<std::uint64_t>(size, h.data_offset)));
  cancel.throw_if_cancelled();
  frame.pixels.resize(static_cast<std::size_t>(need));
  std::ifstream f(path, std::ios::binary);
  f.seekg(static_cast<std::streamoff>(h.data_offset));
  f.read(reinterpret_cast<char*>(frame.pixels.data()), static_cast<std::streamsize>(need));
  if (static_cast<std::uint64_t>(f.gcount()) != need)
    throw ImportError(ImportErrorCategory::Syntax, {path, 0, 0, "offset " + std::to_string(h.data_offset)},
                      "file ended early while reading pixels (changed while being read?)");
  if (frame.bit_depth > 8 && std::endian::native == std::endian::little)  // PNM samples are big-endian
    for (std::size_t i = 0; i + 1 < frame.pixels.size(); i += 2) std::swap(frame.pixels[i], frame.pixels[i + 1]);
  // Samples above maxval are invalid (the specification says so); check against maxval, not only the bit depth.
  const std::size_t n = frame.pixels.size() / static_cast<std::size_t>(frame.bytes_per_sample());
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned v = frame.bit_depth > 8 ? static_cast<unsigned>(frame.pixels[2 * i]) |
                                                 static_cast<unsigned>(frame.pixels[2 * i + 1]) << 8
                                           : frame.pixels[i];
    const unsigned v_host =
        frame.bit_depth > 8 && std::endian::native == std::endian::big ? ((v & 0xFF) << 8) | (v >> 8) : v;
    if (v_host > static_cast<unsigned>(h.maxval))
      throw ImportError(ImportErrorCategory::InvalidValue,
                        {path, 0, 0, "offset " + std::to_string(h.data_offset + i * frame.bytes_per_sample())},
                        "sample " + std::to_string(v_host) + " is above maxval " + std::to_string(h.maxval));
  }
  if (size > h.data_offset + need) {
    ImportBatch batch;
    batch.warnings.push_back(path + ": " + std::to_string(size - h.data_offset - need) +
                             " bytes after the first image were ignored");
    batch.frames.push_back(std::move(frame));
    return batch;
  }
  ImportBatch batch;
  batch.frames.push_back(std::move(frame));
  return batch;
}

const FileFormat kPnmFileFormat{
    "pnm", "PGM/PPM image (binary P5/P6)", sniff_pnm, parse_pnm_file, nullptr, ".pgm .ppm .pnm", true};

}  // namespace bs
