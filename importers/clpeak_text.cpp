// SPDX-License-Identifier: GPL-3.0-or-later
#include "clpeak_text.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>

namespace bs {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::optional<double> leading_number(std::string_view s, std::string_view* rest) {
  s = trim(s);
  double v = 0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || ptr == s.data() || !std::isfinite(v)) return std::nullopt;
  *rest = trim(std::string_view(ptr, static_cast<std::size_t>(s.data() + s.size() - ptr)));
  return v;
}

struct SiUnit {
  std::string unit;  // "FLOP/s", "B/s", "1/s", "s" or "" (dimensionless)
  double scale = 1;  // value in the file's unit * scale = value in `unit`
};

// The units clpeak prints, old (GFLOPS, GBPS, GIOPS, us) and new (TFLOPS, GOPS, TOPS, GB/s, GTexel/s, µs, ns, ppm).
std::optional<SiUnit> si_unit(std::string_view text) {
  const std::string u = lower(trim(text));
  if (u == "mflops") return SiUnit{"FLOP/s", 1e6};
  if (u == "gflops") return SiUnit{"FLOP/s", 1e9};
  if (u == "tflops") return SiUnit{"FLOP/s", 1e12};
  if (u == "giops" || u == "gops") return SiUnit{"1/s", 1e9};
  if (u == "tiops" || u == "tops") return SiUnit{"1/s", 1e12};
  if (u == "gtexel/s" || u == "gtexels") return SiUnit{"1/s", 1e9};
  if (u == "mbps" || u == "mb/s") return SiUnit{"B/s", 1e6};
  if (u == "gbps" || u == "gb/s") return SiUnit{"B/s", 1e9};
  if (u == "tbps" || u == "tb/s") return SiUnit{"B/s", 1e12};
  if (u == "s") return SiUnit{"s", 1};
  if (u == "ms") return SiUnit{"s", 1e-3};
  if (u == "us" || u == "\xC2\xB5s" || u == "\xCE\xBCs") return SiUnit{"s", 1e-6};  // us, micro sign, Greek mu
  if (u == "ns") return SiUnit{"s", 1e-9};
  if (u == "ppm") return SiUnit{"", 1e-6};
  return std::nullopt;
}

// "clEnqueueNDRangeKernel (-5)": what clpeak prints when an OpenCL call fails (cl::Error what() and code).
bool is_opencl_error(std::string_view text) {
  text = trim(text);
  if (!text.ends_with(")")) return false;
  const auto open = text.rfind('(');
  if (open == std::string_view::npos) return false;
  const std::string_view code = text.substr(open + 1, text.size() - open - 2);
  std::int64_t value = 0;
  const auto [ptr, ec] = std::from_chars(code.data(), code.data() + code.size(), value);
  return ec == std::errc() && ptr == code.data() + code.size() && value < 0;
}

struct Section {
  std::string metric;  // "single-precision compute", with a "[variant]" when the title has one
  SiUnit unit;
  std::size_t line = 0;
};

// "Single-precision compute (GFLOPS)", "Single-precision compute [AVX2+FMA] (GFLOPS)  (continued)".
// nullopt for lines that are not a section title (notes such as "No half precision support! Skipped").
std::optional<Section> section_from_title(std::string_view title, std::string& unknown_unit) {
  title = trim(title);
  if (title.ends_with("(continued)")) title = trim(title.substr(0, title.size() - 11));
  if (!title.ends_with(")") || is_opencl_error(title)) return std::nullopt;
  const auto open = title.rfind('(');
  if (open == std::string_view::npos || open == 0) return std::nullopt;
  const std::string_view unit_text = title.substr(open + 1, title.size() - open - 2);
  std::string_view name = trim(title.substr(0, open));
  std::string variant;
  if (name.ends_with("]") && name.rfind('[') != std::string_view::npos) {
    const auto bracket = name.rfind('[');
    variant = std::string(name.substr(bracket));
    name = trim(name.substr(0, bracket));
  }
  if (name.empty()) return std::nullopt;
  Section section;
  section.metric = lower(name) + (variant.empty() ? "" : " " + variant);
  if (auto unit = si_unit(unit_text)) {
    section.unit = *unit;
  } else {
    // An unknown unit keeps its values as printed, dimensionless, and says so once.
    unknown_unit = std::string(unit_text);
    section.unit = SiUnit{"", 1};
  }
  return section;
}

// Device names that are CPUs: PoCL ("pthread-...", "cpu-haswell-..."), Intel / AMD / ARM CPU runtimes.
bool names_a_cpu(std::string_view device) {
  const std::string d = lower(device);
  for (const char* hint : {"cpu", "pthread", "processor", "xeon", "ryzen", "epyc", "core(tm)", "cortex-"})
    if (d.find(hint) != std::string::npos) return true;
  return false;
}

// "Device: name" or "Device 0: name" (clpeak 2 numbers platforms and devices). Returns the name.
std::optional<std::string_view> labelled(std::string_view line, std::string_view label) {
  if (!line.starts_with(label)) return std::nullopt;
  std::string_view rest = line.substr(label.size());
  while (!rest.empty() && (rest.front() == ' ' || std::isdigit(static_cast<unsigned char>(rest.front()))))
    rest.remove_prefix(1);
  if (!rest.starts_with(":")) return std::nullopt;
  return trim(rest.substr(1));
}

class ClpeakParser {
 public:
  explicit ClpeakParser(const std::string& file) : file_(file) {}

  void line(std::string_view raw, std::size_t line_no) {
    line_no_ = line_no;
    const std::string_view text = trim(raw);
    if (text.empty()) return;
    if (auto backend = labelled(text, "Backend")) {
      finish_device();
      backend_ = std::string(*backend);
      platform_.clear();
      platform_line_ = line_no;
      return;
    }
    if (auto platform = labelled(text, "Platform")) {
      finish_device();
      platform_ = std::string(*platform);
      platform_line_ = line_no;
      return;
    }
    if (auto device = labelled(text, "Device")) {
      start_device(*device);
      return;
    }
    if (device_ < 0) return;  // banners and notes before the first device
    handle_device_line(text);
  }

  ImportBatch finish() {
    finish_device();
    if (devices_seen_ == 0)
      throw ImportError(ImportErrorCategory::MissingField, {file_, platform_line_ > 0 ? platform_line_ : 1, 1, {}},
                        platform_line_ > 0 ? "a platform without any 'Device:' section (no measurements)"
                                           : "no 'Platform:' / 'Device:' section found: not clpeak output");
    if (batch_.result_sets.empty())
      throw ImportError(ImportErrorCategory::MissingField, {file_, last_device_line_, 1, {}},
                        "no device has any measurement (every test was skipped or failed)");
    return std::move(batch_);
  }

 private:
  void warn(const std::string& what) {
    batch_.warnings.push_back(file_ + ":" + std::to_string(line_no_) + ": " + what);
  }
  [[noreturn]] void fail(ImportErrorCategory category, std::size_t column, const std::string& field,
                         const std::string& reason) const {
    throw ImportError(category, {file_, line_no_, column, field}, reason);
  }

  ResultSet& device() { return batch_.result_sets[static_cast<std::size_t>(device_)]; }

  void start_device(std::string_view name) {
    finish_device();
    if (platform_.empty() && backend_.empty())
      fail(ImportErrorCategory::Syntax, 1, {}, "a 'Device:' line before any 'Platform:' line");
    ++devices_seen_;
    last_device_line_ = line_no_;
    ResultSet set;
    set.platform = platform_.empty() ? backend_ : platform_;
    set.device = std::string(name);
    set.device_kind = names_a_cpu(name) ? DeviceKind::Cpu : DeviceKind::Gpu;
    set.backend = backend_.empty() ? "OpenCL" : backend_;
    if (lower(set.backend) == "cpu") set.device_kind = DeviceKind::Cpu;
    set.source_format = "clpeak-text";
    set.provenance.origin = DataOrigin::Measured;
    set.provenance.tool = "clpeak";
    set.provenance.source_file = file_;
    batch_.result_sets.push_back(std::move(set));
    device_ = static_cast<int>(batch_.result_sets.size()) - 1;
    section_.reset();
    properties_.clear();
  }

  void finish_device() {
    if (device_ < 0) return;
    ResultSet& set = device();
    if (set.device_kind == DeviceKind::Cpu) {
      set.provenance.cpu_model = set.device;
    } else {
      set.provenance.gpu_model = set.device;
    }
    set.provenance.note = properties_;
    if (set.measurements.empty()) {
      batch_.warnings.push_back(file_ + ":" + std::to_string(last_device_line_) + ": device '" + set.device +
                                "' has no measurements (tests skipped or failed); left out");
      batch_.result_sets.pop_back();
    }
    device_ = -1;
    section_.reset();
    properties_.clear();
  }

  void add(const std::string& name, const std::string& metric, const SiUnit& unit, double value) {
    ResultSet& set = device();
    const auto it = std::find_if(set.measurements.begin(), set.measurements.end(),
                                 [&](const Measurement& m) { return m.name == name && m.metric == metric; });
    if (it != set.measurements.end()) {
      it->values.push_back(value * unit.scale);
    } else {
      set.measurements.push_back({name, metric, unit.unit, {value * unit.scale}, {}});
    }
  }

  void handle_device_line(std::string_view text) {
    const auto colon = text.find(':');
    if (colon == std::string_view::npos) {
      std::string unknown_unit;
      section_ = section_from_title(text, unknown_unit);
      if (section_) section_->line = line_no_;
      if (!unknown_unit.empty())
        warn("unknown unit '" + unknown_unit + "' in section '" + std::string(text) + "'; values kept as printed");
      else if (!section_ && is_opencl_error(text))
        warn("OpenCL error '" + std::string(text) + "' on device '" + device().device + "'; its tests were skipped");
      return;
    }
    const std::string key(trim(text.substr(0, colon)));
    const std::string_view value_text = trim(text.substr(colon + 1));
    const std::size_t value_column = colon + 2;
    if (key == "Build Log") {
      warn("OpenCL kernels did not build on device '" + device().device + "'; its tests were skipped");
      section_.reset();
      return;
    }
    if (key == "Kernel launch latency") {
      section_.reset();
      measure_value("kernel launch latency", "kernel launch latency", SiUnit{"s", 1e-6}, value_text, value_column);
      return;
    }
    if (section_) {
      measure_value(key, section_->metric, section_->unit, value_text, value_column);
      return;
    }
    const std::string lkey = lower(key);
    if ((lkey == "device type" || lkey == "type") && lower(value_text).find("cpu") != std::string::npos)
      device().device_kind = DeviceKind::Cpu;
    properties_ += (properties_.empty() ? "" : "; ") + key + ": " + std::string(value_text);
  }

  void measure_value(const std::string& name, const std::string& metric, const SiUnit& section_unit,
                     std::string_view value_text, std::size_t column) {
    // clpeak 2 marks tests that did not run: "float4 : [skipped] reason", "[unsupported] ...", "[error] ...".
    if (value_text.starts_with("[")) {
      if (value_text.starts_with("[error]")) warn("test '" + name + "' failed: " + std::string(value_text));
      return;
    }
    if (is_opencl_error(value_text) || value_text == "Tests skipped") {
      warn("test '" + name + "' (" + metric + ") failed with OpenCL error '" + std::string(value_text) + "'; skipped");
      return;
    }
    std::string_view rest;
    const auto value = leading_number(value_text, &rest);
    if (!value)
      fail(ImportErrorCategory::Syntax, column, name,
           "expected a number, found '" + std::string(value_text) + "'");
    if (*value < 0) fail(ImportErrorCategory::InvalidValue, column, name, "a measurement cannot be negative");
    // A unit after the number overrides the section's ("Kernel launch latency : 5.32 us"); clpeak 2 may append
    // a baseline comparison "(was 1.00, +3.0% better)", which is not part of the reading.
    SiUnit unit = section_unit;
    if (!rest.empty() && !rest.starts_with("(")) {
      const auto space = rest.find_first_of(" \t");
      const std::string_view token = rest.substr(0, space);
      if (auto parsed = si_unit(token)) unit = *parsed;
    }
    add(name, metric, unit, *value);
  }

  std::string file_;
  ImportBatch batch_;
  std::string backend_;
  std::string platform_;
  std::size_t platform_line_ = 0;
  std::size_t line_no_ = 0;
  std::size_t last_device_line_ = 0;
  std::size_t devices_seen_ = 0;
  int device_ = -1;  // index into batch_.result_sets, -1 outside a device block
  std::optional<Section> section_;
  std::string properties_;
};

}  // namespace

int ClpeakTextImporter::sniff(std::string_view head, std::string_view) const {
  const bool platform = head.find("Platform: ") != std::string_view::npos ||
                        head.find("Platform 0: ") != std::string_view::npos;
  const bool device = head.find("Device: ") != std::string_view::npos || head.find("Device 0: ") != std::string_view::npos;
  const bool sections = head.find("(GFLOPS)") != std::string_view::npos ||
                        head.find("(GBPS)") != std::string_view::npos || head.find("(GB/s)") != std::string_view::npos ||
                        head.find("(GIOPS)") != std::string_view::npos;
  if (platform && device && sections) return 90;
  if ((platform || head.find("Backend: ") != std::string_view::npos) && (device || sections)) return 50;
  return 0;
}

bool ClpeakTextImporter::usual_extension(std::string_view path) const {
  return path.ends_with(".txt") || path.ends_with(".log");
}

ImportBatch ClpeakTextImporter::parse(const std::string& path, const ImportLimits& limits,
                                      const CancelToken& cancel) const {
  const std::string text = read_whole_file(path, limits.max_json_bytes);
  cancel.throw_if_cancelled();
  return parse_clpeak_text(text, path, &cancel);
}

ImportBatch parse_clpeak_text(std::string_view text, const std::string& file, const CancelToken* cancel) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  ClpeakParser parser(file);
  std::size_t line_no = 0;
  for (std::size_t pos = 0; pos < text.size();) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    ++line_no;
    if (cancel && (line_no & 0xFFF) == 0) cancel->throw_if_cancelled();
    parser.line(text.substr(pos, end - pos), line_no);  // a trailing '\r' (CRLF) is trimmed as whitespace
    pos = end + 1;
  }
  return parser.finish();
}

}  // namespace bs
