// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/lens/tuner_state.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "vision/lens/points_json.h"

namespace bs::vision {
namespace {

constexpr char kMagic[8] = {'B', 'S', 'L', 'U', 'T', '1', '\n', '\0'};
constexpr std::uint32_t kMaxHeader = 1 << 20;

bool same_lens(const Lens& a, const Lens& b) {
  return a.type == b.type && a.r_pp == b.r_pp && a.k == b.k && a.cx == b.cx && a.cy == b.cy && a.fov_deg == b.fov_deg &&
         a.width == b.width && a.height == b.height;
}
bool same_view(const View& a, const View& b) {
  return a.width == b.width && a.height == b.height && a.fov_deg == b.fov_deg && a.yaw_deg == b.yaw_deg &&
         a.pitch_deg == b.pitch_deg && a.roll_deg == b.roll_deg;
}

}  // namespace

bool TunerParams::operator==(const TunerParams& o) const {
  return same_lens(lens, o.lens) && same_view(view, o.view) && masks == o.masks;
}

cv::Mat mask_image(const std::vector<MaskPolygon>& masks, cv::Size size) {
  cv::Mat m(size, CV_8UC1, cv::Scalar(0));
  for (const auto& poly : masks) {
    if (poly.size() < 3) continue;
    std::vector<cv::Point> pts;
    for (const auto& p : poly) pts.emplace_back(cvRound(p.x), cvRound(p.y));
    cv::fillPoly(m, std::vector<std::vector<cv::Point>>{pts}, cv::Scalar(255));
  }
  return m;
}

nlohmann::json tuner_to_json(const TunerParams& p) {
  nlohmann::json j = lens_to_json(p.lens, p.view);
  nlohmann::json masks = nlohmann::json::array();
  for (const auto& poly : p.masks) {
    nlohmann::json pts = nlohmann::json::array();
    for (const auto& q : poly) pts.push_back({q.x, q.y});
    masks.push_back(pts);
  }
  j["masks"] = masks;
  return j;
}

TunerParams tuner_from_json(const nlohmann::json& j) {
  TunerParams p;
  std::tie(p.lens, p.view) = lens_from_json(j);
  if (j.contains("masks")) {  // optional: a plain lens file has none
    const auto& masks = j["masks"];
    if (!masks.is_array()) throw std::invalid_argument("/masks: expected an array of polygons");
    for (std::size_t i = 0; i < masks.size(); ++i)
      p.masks.push_back(points_from_json<float>(masks[i], "/masks/" + std::to_string(i), /*finite=*/false));
  }
  return p;
}

void save_tuner_json(const TunerParams& p, const std::filesystem::path& path) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error(path.string() + ": cannot open for writing");
  f << tuner_to_json(p).dump(2) << '\n';
  if (!f) throw std::runtime_error(path.string() + ": write failed");
}

TunerParams load_tuner_json(const std::filesystem::path& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error(path.string() + ": cannot open");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(f);
    return tuner_from_json(j);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path.string() + ": not valid JSON: " + e.what());
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

TunerState::TunerState(TunerParams initial) : initial_(initial), current_{std::move(initial), {}} {}

bool TunerState::push(Snapshot next, const std::string& field) {
  // The step before a merge run holds the state from before the run began, so only the first change pushes.
  if (field.empty() || field != merge_field_) undo_.push_back(current_);
  merge_field_ = field;
  current_ = std::move(next);
  redo_.clear();
  return true;
}

bool TunerState::set(const TunerParams& p, const std::string& field) {
  if (p == current_.params) return false;
  return push({p, current_.lines}, field);
}

bool TunerState::set_lines(const Lines& lines, const std::string& field) {
  if (lines == current_.lines) return false;
  return push({current_.params, lines}, field);
}

bool TunerState::undo() {
  if (undo_.empty()) return false;
  redo_.push_back(current_);
  current_ = undo_.back();
  undo_.pop_back();
  merge_field_.clear();
  return true;
}

bool TunerState::redo() {
  if (redo_.empty()) return false;
  undo_.push_back(current_);
  current_ = redo_.back();
  redo_.pop_back();
  merge_field_.clear();
  return true;
}

void TunerState::rebase(const TunerParams& p) {
  initial_ = current_.params = p;
  undo_.clear();
  redo_.clear();
  merge_field_.clear();
}

void export_lut(const cv::Mat& map, const TunerParams& p, const std::filesystem::path& path) {
  if (map.type() != CV_32FC2 || !map.isContinuous())
    throw std::invalid_argument("export_lut needs a continuous CV_32FC2 map");
  nlohmann::json h = {{"format", "benchscope-lut"}, {"version", 1},       {"width", map.cols},
                      {"height", map.rows},         {"dtype", "float32"}, {"channels", 2},
                      {"byte_order", "little"},     {"invalid", -1},      {"lens", tuner_to_json(p)}};
  const std::string header = h.dump();
  std::ofstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error(path.string() + ": cannot open for writing");
  f.write(kMagic, sizeof kMagic);
  const auto n = static_cast<std::uint32_t>(header.size());
  const unsigned char len[4] = {static_cast<unsigned char>(n), static_cast<unsigned char>(n >> 8),
                                static_cast<unsigned char>(n >> 16), static_cast<unsigned char>(n >> 24)};
  f.write(reinterpret_cast<const char*>(len), 4);
  f.write(header.data(), static_cast<std::streamsize>(header.size()));
  static_assert(std::endian::native == std::endian::little, "the LUT payload is written in native little-endian");
  f.write(reinterpret_cast<const char*>(map.data), static_cast<std::streamsize>(map.total() * map.elemSize()));
  if (!f) throw std::runtime_error(path.string() + ": write failed");
}

cv::Mat read_lut(const std::filesystem::path& path, nlohmann::json* header_out) {
  const auto fail = [&](const std::string& why) { return std::runtime_error(path.string() + ": " + why); };
  std::ifstream f(path, std::ios::binary);
  if (!f) throw fail("cannot open");
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw fail("cannot read the file size");
  char magic[8];
  unsigned char len[4];
  if (!f.read(magic, 8) || std::memcmp(magic, kMagic, 8) != 0) throw fail("not a BenchScope LUT (bad magic at byte 0)");
  if (!f.read(reinterpret_cast<char*>(len), 4)) throw fail("truncated header length at byte 8");
  const std::uint32_t n = len[0] | (len[1] << 8) | (len[2] << 16) | (static_cast<std::uint32_t>(len[3]) << 24);
  if (n > kMaxHeader || 12ull + n > size) throw fail("header length " + std::to_string(n) + " exceeds the file");
  std::string text(n, '\0');
  f.read(text.data(), n);
  nlohmann::json h;
  try {
    h = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw fail(std::string("header is not valid JSON: ") + e.what());
  }
  if (!h.is_object() || h.value("format", "") != "benchscope-lut") throw fail("header/format: not benchscope-lut");
  if (h.value("dtype", "") != "float32" || h.value("channels", 0) != 2 || h.value("byte_order", "") != "little")
    throw fail("header: only float32, 2 channels, little-endian is supported");
  if (!h.contains("width") || !h["width"].is_number_integer() || !h.contains("height") ||
      !h["height"].is_number_integer())
    throw fail("header/width, header/height: expected integers");
  const long long w = h["width"].get<long long>(), hh = h["height"].get<long long>();
  if (w <= 0 || hh <= 0 || w > 65536 || hh > 65536) throw fail("header: width/height out of range");
  const unsigned long long payload = static_cast<unsigned long long>(w) * static_cast<unsigned long long>(hh) * 8ull;
  if (12ull + n + payload != size)
    throw fail("payload is " + std::to_string(size - 12 - n) + " bytes, header says " + std::to_string(payload));
  cv::Mat map(static_cast<int>(hh), static_cast<int>(w), CV_32FC2);
  if (!f.read(reinterpret_cast<char*>(map.data), static_cast<std::streamsize>(payload)))
    throw fail("truncated payload");
  if (header_out) *header_out = std::move(h);
  return map;
}

}  // namespace bs::vision
