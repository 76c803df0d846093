// SPDX-License-Identifier: GPL-3.0-or-later
#include "frames/frame_raw.h"

#include <bit>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "common/json_access.h"
#include "frames/frame_common.h"
#include "model/provenance_json.h"

namespace bs {
namespace {

constexpr std::size_t kMaxSidecarBytes = std::size_t{1} << 20;  // a sidecar is a few hundred bytes

bool host_is_big_endian() { return std::endian::native == std::endian::big; }

}  // namespace

RawFrameOptions read_raw_sidecar(const std::string& sidecar_path, const ImportLimits& limits) {
  ImportLimits sidecar_limits = limits;
  sidecar_limits.max_json_bytes = std::min(limits.max_json_bytes, kMaxSidecarBytes);
  const std::string text = read_whole_file(sidecar_path, sidecar_limits.max_json_bytes);
  const auto doc = json_access::parse(text, sidecar_path, sidecar_limits);
  const json_access::Reader r(sidecar_path, text);
  RawSidecar s;
  try {
    s = raw_sidecar_from_json(doc);
  } catch (const RawSidecarError& e) {
    using K = RawSidecarError::Kind;
    const ImportErrorCategory category = e.kind() == K::Missing     ? ImportErrorCategory::MissingField
                                         : e.kind() == K::WrongType ? ImportErrorCategory::WrongType
                                         : e.kind() == K::Invalid   ? ImportErrorCategory::InvalidValue
                                                                    : ImportErrorCategory::Unsupported;
    r.fail(category, e.pointer(), e.reason());  // with the member's line:column
  }
  // Sizes against the limits (check_dimensions), so a sidecar claiming 100000 x 100000 is refused here, long
  // before the raw file is opened.
  frames::check_dimensions(sidecar_path, "/width", s.width, s.height, limits);
  if (!s.pattern)
    r.fail(ImportErrorCategory::MissingField, "/pattern",
           "missing: the Bayer pattern (BGGR, RGGB, GRBG or GBRG) is needed to demosaic the frame");
  RawFrameOptions o;
  o.width = s.width;
  o.height = s.height;
  o.pattern = *s.pattern;
  o.bit_depth = s.bit_depth;
  o.big_endian = s.big_endian;
  o.synthetic = s.synthetic;
  o.lens_json = s.lens_json;
  return o;
}

ImportBatch read_raw_frame(const std::string& path, const RawFrameOptions& o, const ImportLimits& limits,
                           const CancelToken& cancel, const std::string& geometry_source) {
  const std::string src = geometry_source.empty() ? path : geometry_source;
  frames::check_dimensions(src, "width", o.width, o.height, limits);
  if (o.bit_depth < 1 || o.bit_depth > 16)
    throw ImportError(ImportErrorCategory::InvalidValue, {src, 0, 0, "bit_depth"},
                      "bit depth " + std::to_string(o.bit_depth) + " is not between 1 and 16");
  const std::string pattern = o.pattern.empty() ? std::string() : frames::check_pattern(src, "pattern", o.pattern);
  Frame frame = frames::make_frame(path, "raw-bayer", o.width, o.height, 1, o.bit_depth, pattern);
  const std::uint64_t expected = frame.expected_bytes();
  const std::uint64_t size = frames::file_size(path);
  if (size != expected)
    throw ImportError(ImportErrorCategory::InvalidValue, {path, 0, 0, "size"},
                      "file is " + std::to_string(size) + " bytes, but " + std::to_string(o.width) + "x" +
                          std::to_string(o.height) + " samples at " + std::to_string(o.bit_depth) + " bits (" +
                          std::to_string(frame.bytes_per_sample()) + " byte" +
                          (frame.bytes_per_sample() > 1 ? "s" : "") + " each) from " + src + " need " +
                          std::to_string(expected) + " bytes");
  cancel.throw_if_cancelled();
  frame.pixels.resize(static_cast<std::size_t>(expected));  // == the real file size, checked above
  {
    std::ifstream f = frames::open_binary(path);
    f.read(reinterpret_cast<char*>(frame.pixels.data()), static_cast<std::streamsize>(expected));
    if (static_cast<std::uint64_t>(f.gcount()) != expected)
      throw ImportError(ImportErrorCategory::Syntax, {path, 0, 0, "offset " + std::to_string(f.gcount())},
                        "file ended early while reading pixels (changed while being read?)");
  }
  if (frame.bit_depth > 8 && o.big_endian != host_is_big_endian())
    for (std::size_t i = 0; i + 1 < frame.pixels.size(); i += 2) std::swap(frame.pixels[i], frame.pixels[i + 1]);
  frames::check_sample_range(path, frame, 0);
  frame.synthetic = o.synthetic;
  frame.lens_json = o.lens_json;
  frame.read_options = nlohmann::json{
      {"width", o.width},
      {"height", o.height},
      {"pattern", pattern},
      {"bit_depth", o.bit_depth},
      {"endianness", o.big_endian ? "big" : "little"},
      {"synthetic",
       o.synthetic}}.dump();
  if (o.synthetic) {
    frame.provenance.origin = DataOrigin::Unknown;
    frame.provenance.tool = "benchscope-cli synth-frame";
    frame.provenance.note = "synthetic: a test chart rendered through a lens model, not a camera capture";
  }
  ImportBatch batch;
  batch.frames.push_back(std::move(frame));
  return batch;
}

RawFrameOptions parse_raw_geometry(const std::string& text) {
  RawFrameOptions o;
  char pattern[16] = "BGGR", endian[8] = "le";
  int w = 0, h = 0, bits = 8;
  const int n = std::sscanf(text.c_str(), "%dx%d:%15[A-Za-z]:%d:%7s", &w, &h, pattern, &bits, endian);
  if (n < 2) throw std::invalid_argument("expected WxH[:PATTERN[:BITS[:le|be]]], e.g. 1280x1024:BGGR:8");
  if (w < 1 || h < 1) throw std::invalid_argument("width and height must be positive");
  if (bits < 1 || bits > 16) throw std::invalid_argument("bits must be between 1 and 16");
  const std::string e = endian;
  if (e != "le" && e != "be") throw std::invalid_argument("byte order must be le or be");
  o.width = w;
  o.height = h;
  o.bit_depth = bits;
  o.big_endian = e == "be";
  std::string p = pattern;
  if (p == "grey" || p == "gray" || p == "none") {
    o.pattern.clear();
  } else {
    for (auto& c : p) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (p != "BGGR" && p != "RGGB" && p != "GRBG" && p != "GBRG")
      throw std::invalid_argument("pattern must be BGGR, RGGB, GRBG, GBRG or grey");
    o.pattern = p;
  }
  return o;
}

static int sniff_raw_bayer(std::string_view, std::string_view path) {
  // Raw samples have no magic bytes: the extension and the sidecar beside the file decide. A .raw without a
  // sidecar is still claimed, so the user hears that the sidecar is missing rather than "binary file".
  if (!ends_with_ci(path, ".raw")) return 0;
  return find_raw_sidecar(std::string(path)) ? 100 : 50;
}

static ImportBatch parse_raw_bayer_file(const std::string& path, const ParseOptions& /*options*/,
                                        const ImportLimits& limits, const CancelToken& cancel) {
  const std::optional<std::string> found = find_raw_sidecar(path);
  if (!found)
    throw ImportError(ImportErrorCategory::MissingField, {path, 0, 0, "sidecar"},
                      "raw frame without its sidecar " + raw_sidecar_path(path) +
                          " (width, height, pattern, bit_depth, endianness); write one, or give the geometry "
                          "(benchscope-cli import --raw-geometry WxH:PATTERN:BITS)");
  const std::string& sidecar = *found;
  RawFrameOptions o;
  try {
    o = read_raw_sidecar(sidecar, limits);
  } catch (const ImportError& e) {
    // Name the file the user imported first, then the sidecar place: "a.raw: sidecar a.json:4:12 /width: ...".
    const ErrorLocation& l = e.location();
    std::string where = "sidecar " + sidecar;
    if (l.line > 0) where += ":" + std::to_string(l.line) + (l.column > 0 ? ":" + std::to_string(l.column) : "");
    if (!l.field.empty()) where += " " + l.field;
    throw ImportError(e.category(), {path, 0, 0, where}, e.reason());
  }
  return read_raw_frame(path, o, limits, cancel, sidecar);
}

bool raw_without_sidecar(const std::string& path) {
  return path.size() > 4 && path.ends_with(".raw") && !find_raw_sidecar(path);
}

const FileFormat kRawBayerFileFormat{
    "raw-bayer", "raw Bayer frame (.raw + JSON sidecar)", sniff_raw_bayer, parse_raw_bayer_file, nullptr, ".raw", true};

}  // namespace bs
