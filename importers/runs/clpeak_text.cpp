// SPDX-License-Identifier: GPL-3.0-or-later
#include "runs/clpeak_text.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>

#include "common/text_file.h"
#include "util/text.h"

namespace bs {
namespace {

// The number at the start of a value ("11437.44", "8.48 GFLOPS", "inf", "-5189.91 us"); false when there is none.
bool leading_number(std::string_view s, std::string_view* rest, double* value) {
  s = trim(s);
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), *value);
  if (ec != std::errc() || ptr == s.data()) return false;
  *rest = trim(std::string_view(ptr, static_cast<std::size_t>(s.data() + s.size() - ptr)));
  return true;
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
  std::string metric;          // "single-precision compute", with a "[variant]" when the title has one
  std::optional<SiUnit> unit;  // nullopt: the title names no unit; each value line must carry its own
  std::size_t line = 0;
};

// "Single-precision compute (GFLOPS)", "Single-precision compute [AVX2+FMA] (GFLOPS)  (continued)",
// "Cooperative-matrix fp8(E4M3)xfp8(E4M3)+fp32 16x16x16 (TFLOPS)", and clpeak 2.1's unit-less
// "Divide and square-root throughput [SSE2]" whose values say "8.48 GFLOPS" themselves. A parenthesised word that is
// not a unit stays part of the name ("Single-precision compute (NEON)"). Any other line without a colon is a title
// too: a note ("No half precision support! Skipped", "Tests skipped") then opens a section that holds no values.
Section section_from_title(std::string_view title) {
  title = trim(title);
  if (title.ends_with("(continued)")) title = trim(title.substr(0, title.size() - 11));
  Section section;
  std::string_view name = title;
  if (title.ends_with(")")) {
    const auto open = title.rfind('(');
    if (open != std::string_view::npos && open > 0) {
      if (auto unit = si_unit(title.substr(open + 1, title.size() - open - 2))) {
        section.unit = *unit;
        name = trim(title.substr(0, open));
      }
    }
  }
  std::string variant;
  if (name.ends_with("]") && name.rfind('[') != std::string_view::npos) {
    const auto bracket = name.rfind('[');
    variant = std::string(name.substr(bracket));
    name = trim(name.substr(0, bracket));
  }
  section.metric = lower(name) + (variant.empty() ? "" : " " + variant);
  return section;
}

// Device names that are CPUs: PoCL ("pthread-...", "cpu-haswell-..."), Intel / AMD / ARM CPU runtimes, llvmpipe.
// PoCL's CPU prefixes decide first ("pthread-AMD Ryzen 7 5800H with Radeon Graphics" is the CPU). Otherwise a
// Vulkan or rusticl iGPU may carry its CPU's name ("AMD Ryzen 9 7900 12-Core Processor (RADV RAPHAEL_MENDOCINO)"):
// a GPU driver or "graphics" in the name wins over the CPU words.
bool names_a_cpu(std::string_view device) {
  const std::string d = lower(device);
  if (d.starts_with("pthread-") || d.starts_with("cpu-") || d.starts_with("basic-")) return true;
  for (const char* hint : {"radv", "radeonsi", "graphics", "gpu", "gfx", "geforce", "radeon", "mali", "adreno"})
    if (d.find(hint) != std::string::npos) return false;
  for (const char* hint : {"cpu", "pthread", "processor", "xeon", "ryzen", "epyc", "core(tm)", "cortex-", "llvmpipe"})
    if (d.find(hint) != std::string::npos) return true;
  return false;
}

// "Device: name", "Device 0: name" (clpeak 2 numbers platforms and devices) and clpeak 2.0's backend-prefixed
// "Vulkan Device: name" / "CUDA Device: name" / "Metal Device: name" (the prefix is returned in *prefix).
std::optional<std::string_view> labelled(std::string_view line, std::string_view label,
                                         std::string_view* prefix = nullptr) {
  std::string_view rest = line;
  const auto space = line.find(' ');
  if (!line.starts_with(label) && prefix && space != std::string_view::npos && space > 0 &&
      line.substr(space + 1).starts_with(label)) {
    const std::string_view word = line.substr(0, space);
    const std::string w = lower(word);
    if (w != "vulkan" && w != "cuda" && w != "metal" && w != "opencl" && w != "rocm" && w != "hip" && w != "oneapi" &&
        w != "sycl" && w != "cpu")
      return std::nullopt;
    *prefix = word;
    rest = line.substr(space + 1);
  }
  if (!rest.starts_with(label)) return std::nullopt;
  rest.remove_prefix(label.size());
  while (!rest.empty() && (rest.front() == ' ' || std::isdigit(static_cast<unsigned char>(rest.front()))))
    rest.remove_prefix(1);
  if (!rest.starts_with(":")) return std::nullopt;
  return trim(rest.substr(1));
}

// clpeak 2.0's "=== Vulkan backend ===": the backend's name.
std::optional<std::string_view> backend_banner(std::string_view line) {
  if (!line.starts_with("===") || !line.ends_with("===")) return std::nullopt;
  std::string_view inner = trim(line.substr(3, line.size() >= 6 ? line.size() - 6 : 0));
  if (!inner.ends_with(" backend")) return std::nullopt;
  inner = trim(inner.substr(0, inner.size() - 8));
  if (inner.empty()) return std::nullopt;
  return inner;
}

class ClpeakParser {
 public:
  explicit ClpeakParser(const std::string& file) : file_(file) {}

  void line(std::string_view raw, std::size_t line_no) {
    line_no_ = line_no;
    const std::string_view text = trim(raw);
    if (text.empty()) return;
    if (auto banner = backend_banner(text)) {
      finish_device();
      backend_ = std::string(*banner);
      platform_.clear();
      return;
    }
    if (auto backend = labelled(text, "Backend")) {
      finish_device();
      backend_ = std::string(*backend);
      platform_.clear();
      return;
    }
    if (auto platform = labelled(text, "Platform")) {
      finish_device();
      platform_ = std::string(*platform);
      platform_line_ = line_no;
      return;
    }
    std::string_view prefix;
    if (auto device = labelled(text, "Device", &prefix)) {
      start_device(*device, prefix);
      return;
    }
    if (device_ < 0) return;  // banners, shell prompts and notes before the first device
    handle_device_line(text);
  }

  ImportBatch finish() {
    finish_device();
    if (devices_seen_ == 0)
      throw ImportError(ImportErrorCategory::MissingField, {file_, platform_line_ > 0 ? platform_line_ : 1, 1, {}},
                        platform_line_ > 0 ? "a platform without any 'Device:' section (no measurements)"
                                           : "no 'Platform:' / 'Device:' section found: not clpeak output");
    if (batch_.result_sets.empty()) {
      // Nothing readable at all. When values were there but none could be read, the first of them is the error.
      if (first_bad_) throw *first_bad_;
      throw ImportError(ImportErrorCategory::MissingField, {file_, last_device_line_, 1, {}},
                        "no device has any measurement (every test was skipped or failed)");
    }
    return std::move(batch_);
  }

 private:
  void warn(std::size_t line, const std::string& what) {
    batch_.warnings.push_back(file_ + ":" + std::to_string(line) + ": " + what);
  }
  void warn(const std::string& what) { warn(line_no_, what); }

  // A value that cannot be a measurement: skipped with a warning naming file:line; kept as the error to report if
  // the file turns out to hold no measurement at all.
  void unreadable(ImportErrorCategory category, std::size_t column, const std::string& field,
                  const std::string& reason) {
    warn(field + ": " + reason + "; skipped");
    if (!first_bad_) first_bad_ = ImportError(category, {file_, line_no_, column, field}, reason);
  }

  ResultSet& device() { return batch_.result_sets[static_cast<std::size_t>(device_)]; }

  void start_device(std::string_view name, std::string_view prefix) {
    finish_device();
    // clpeak 2.0 names the backend on the device line ("Vulkan Device: ..."); a paste may start at "Device:"
    // without the "Platform:" line above it (clpeak 1.x prints the platform once for all its devices).
    if (!prefix.empty() && backend_.empty()) backend_ = std::string(prefix);
    ++devices_seen_;
    last_device_line_ = line_no_;
    ResultSet set;
    set.backend = !prefix.empty() ? std::string(prefix) : backend_.empty() ? "OpenCL" : backend_;
    set.platform = platform_.empty() ? set.backend : platform_;
    set.device = std::string(name);
    set.device_kind = names_a_cpu(name) ? DeviceKind::Cpu : DeviceKind::Gpu;
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
      warn(last_device_line_, "device '" + set.device + "' has no measurements (tests skipped or failed); left out");
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
      if (is_opencl_error(text)) {
        warn("OpenCL error '" + std::string(text) + "' on device '" + device().device + "'; its tests were skipped");
        section_.reset();
        return;
      }
      section_ = section_from_title(text);
      section_->line = line_no_;
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

  void measure_value(const std::string& name, const std::string& metric, const std::optional<SiUnit>& section_unit,
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
    if (value_text.empty()) {
      // clpeak hangs or dies after "Kernel launch latency : " on some drivers.
      unreadable(ImportErrorCategory::MissingField, column, name, "no value (the test did not finish)");
      return;
    }
    std::string_view rest;
    double value = 0;
    if (!leading_number(value_text, &rest, &value)) {
      // A crash message in place of the value ("Speicherzugriffsfehler"), "compile/load failed", ...
      unreadable(ImportErrorCategory::Syntax, column, name,
                 "expected a number, found '" + std::string(value_text) + "'");
      return;
    }
    if (!std::isfinite(value)) {
      // clpeak prints inf when a map/unmap is timed at 0 s.
      unreadable(ImportErrorCategory::InvalidValue, column, name,
                 "'" + std::string(value_text) + "' is not a finite measurement");
      return;
    }
    if (value < 0) {
      // PoCL's CUDA device reports kernel launch latencies of -5189.91 us (timer clock mismatch).
      unreadable(ImportErrorCategory::InvalidValue, column, name,
                 "a measurement cannot be negative (" + std::string(value_text) + ")");
      return;
    }
    // A unit after the number overrides the section's ("Kernel launch latency : 5.32 us", clpeak 2.1's
    // "fdiv fp32 ST : 8.48 GFLOPS"); clpeak 2 may append a baseline comparison "(was 1.00, +3.0% better)".
    std::optional<SiUnit> unit = section_unit;
    if (!rest.empty() && !rest.starts_with("(")) {
      const auto space = rest.find_first_of(" \t");
      if (auto parsed = si_unit(rest.substr(0, space))) unit = *parsed;
    }
    if (!unit) {
      unreadable(ImportErrorCategory::MissingField, column, name,
                 "no unit in the section title or after the value '" + std::string(value_text) + "'");
      return;
    }
    add(name, metric, *unit, value);
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
  std::optional<ImportError> first_bad_;
};

}  // namespace

static int sniff_clpeak_text(std::string_view head, std::string_view) {
  const auto has = [&](std::string_view w) { return head.find(w) != std::string_view::npos; };
  const bool platform = has("Platform: ") || has("Platform 0: ");
  const bool device = has("Device: ") || has("Device 0: ");
  const bool backend = has("Backend: ") || (has("=== ") && has(" backend ==="));
  const bool sections = has("(GFLOPS)") || has("(GBPS)") || has("(GB/s)") || has("(GIOPS)") || has("(GOPS)") ||
                        has("(TFLOPS)") || has("compute (") || has(" GFLOPS\n") || has(" GFLOPS\r\n");
  if (platform && device && sections) return 90;
  if (device && sections) return 80;  // a paste that starts at "Device:", or clpeak 2.0's "Vulkan Device:"
  if ((platform || backend) && (device || sections)) return 50;
  return 0;
}

static ImportBatch parse_clpeak_text(const std::string& text_in, const std::string& file,
                                     const ParseOptions& /*options*/, const ImportLimits& /*limits*/,
                                     const CancelToken& cancel) {
  const std::string_view text = text_in;
  ClpeakParser parser(file);
  std::size_t line_no = 0;
  for (std::size_t pos = 0; pos < text.size();) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    ++line_no;
    if ((line_no & 0xFFF) == 0) cancel.throw_if_cancelled();
    parser.line(text.substr(pos, end - pos), line_no);  // a trailing '\r' (CRLF) is trimmed as whitespace
    pos = end + 1;
  }
  return parser.finish();
}

const FileFormat kClpeakTextFileFormat{"clpeak-text",     "clpeak text output",
                                       sniff_clpeak_text, parse_text_file_with<parse_clpeak_text>,
                                       parse_clpeak_text, ".txt .log"};

}  // namespace bs
