// SPDX-License-Identifier: GPL-3.0-or-later
#include "clpeak_text.h"

#include <cctype>
#include <charconv>
#include <optional>

namespace bs {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::optional<double> leading_number(std::string_view s, std::string_view* rest = nullptr) {
  s = trim(s);
  double v = 0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || ptr == s.data()) return std::nullopt;
  if (rest) *rest = trim(std::string_view(ptr, static_cast<std::size_t>(s.data() + s.size() - ptr)));
  return v;
}

struct Section {
  std::string metric;  // "single-precision compute"
  std::string unit;    // SI unit of the converted values
  double scale = 1;    // file unit -> SI
};

// "Single-precision compute (GFLOPS)" -> metric + SI unit; nullopt when the title has no known unit.
std::optional<Section> section_from_title(std::string_view title) {
  const auto open = title.rfind('(');
  if (open == std::string_view::npos || title.back() != ')') return std::nullopt;
  const std::string_view unit = title.substr(open + 1, title.size() - open - 2);
  std::string metric(trim(title.substr(0, open)));
  for (char& c : metric) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (unit == "GFLOPS") return Section{metric, "FLOP/s", 1e9};
  if (unit == "GBPS") return Section{metric, "B/s", 1e9};
  if (unit == "GIOPS") return Section{metric, "1/s", 1e9};
  if (unit == "us") return Section{metric, "s", 1e-6};
  return std::nullopt;
}

double latency_scale(std::string_view unit) {
  if (unit == "us") return 1e-6;
  if (unit == "ms") return 1e-3;
  if (unit == "ns") return 1e-9;
  return 1.0;
}

}  // namespace

int ClpeakTextImporter::sniff(std::string_view head, std::string_view) const {
  const bool platform = head.find("Platform: ") != std::string_view::npos;
  const bool device = head.find("Device: ") != std::string_view::npos;
  const bool sections = head.find("(GFLOPS)") != std::string_view::npos || head.find("(GBPS)") != std::string_view::npos;
  if (platform && device && sections) return 90;
  if (platform && (device || sections)) return 50;
  return 0;
}

ImportBatch ClpeakTextImporter::parse(const std::string& path, const ImportLimits& limits,
                                      const CancelToken& cancel) const {
  const std::string text = read_whole_file(path, limits.max_json_bytes);
  cancel.throw_if_cancelled();
  return parse_clpeak_text(text, path);
}

ImportBatch parse_clpeak_text(std::string_view text, const std::string& file) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  ImportBatch batch;
  std::string platform;
  std::optional<Section> section;
  ResultSet* device = nullptr;
  std::string properties;
  auto finish_device = [&] {
    if (device && !properties.empty()) device->provenance.note = properties;
    properties.clear();
  };
  std::size_t line_no = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view line = trim(text.substr(pos, end - pos));
    ++line_no;
    pos = end + 1;
    if (line.empty()) {
      if (end == text.size()) break;
      continue;
    }
    const ErrorLocation here{file, line_no, 1, {}};
    if (line.starts_with("Platform:")) {
      finish_device();
      platform = std::string(trim(line.substr(9)));
      device = nullptr;
      section.reset();
      continue;
    }
    if (line.starts_with("Device:")) {
      finish_device();
      if (platform.empty())
        throw ImportError(ImportErrorCategory::Syntax, here, "a Device: line before any Platform: line");
      ResultSet set;
      set.platform = platform;
      set.device = std::string(trim(line.substr(7)));
      const std::string lower_platform = [&] {
        std::string s = platform;
        for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return s;
      }();
      // PoCL and Intel's CPU runtime expose CPUs; everything else clpeak is run on is a GPU.
      set.device_kind = (lower_platform.find("portable computing") != std::string::npos ||
                         set.device.find("CPU") != std::string::npos || set.device.find("cpu") != std::string::npos)
                            ? DeviceKind::Cpu
                            : DeviceKind::Gpu;
      set.backend = "OpenCL";
      set.source_format = "clpeak-text";
      set.provenance.origin = DataOrigin::Measured;
      set.provenance.tool = "clpeak";
      set.provenance.gpu_model = set.device;
      set.provenance.source_file = file;
      batch.result_sets.push_back(std::move(set));
      device = &batch.result_sets.back();
      section.reset();
      continue;
    }
    if (!device) continue;  // clpeak prints a banner before the first platform
    const auto colon = line.find(':');
    if (colon == std::string_view::npos) {
      section = section_from_title(line);  // a new section, or a note such as "No half precision support! Skipped"
      continue;
    }
    const std::string key(trim(line.substr(0, colon)));
    const std::string_view value_text = trim(line.substr(colon + 1));
    std::string_view rest;
    const auto value = leading_number(value_text, &rest);
    if (key == "Kernel launch latency") {
      if (!value)
        throw ImportError(ImportErrorCategory::Syntax, {file, line_no, colon + 2, key}, "expected a number in us");
      device->measurements.push_back({"kernel launch latency", "kernel launch latency", "s",
                                      {*value * latency_scale(rest)}, {}});
      section.reset();
      continue;
    }
    if (section) {
      if (!value)
        throw ImportError(ImportErrorCategory::Syntax, {file, line_no, colon + 2, key},
                          "expected a number, found '" + std::string(value_text) + "'");
      if (*value < 0)
        throw ImportError(ImportErrorCategory::InvalidValue, {file, line_no, colon + 2, key}, "negative throughput");
      device->measurements.push_back({key, section->metric, section->unit, {*value * section->scale}, {}});
    } else {
      properties += (properties.empty() ? "" : "; ") + key + ": " + std::string(value_text);
    }
  }
  finish_device();
  if (batch.result_sets.empty())
    throw ImportError(ImportErrorCategory::MissingField, {file, 0, 0, {}}, "no 'Device:' section found");
  for (const ResultSet& set : batch.result_sets)
    if (set.measurements.empty())
      throw ImportError(ImportErrorCategory::MissingField, {file, 0, 0, set.device},
                        "device has no measurements (clpeak output truncated?)");
  return batch;
}

}  // namespace bs
