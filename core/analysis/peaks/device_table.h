// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The vendor specifications of common robot computers' CPUs and GPUs (resources/devices/devices.json, format in
// docs/cli.md "Device table" and resources/schema/benchscope-devices-v1.schema.json): FP32 peak FLOPS, memory
// bandwidth and TDP, each entry with its source. Plausibility checks compare measured figures with these.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/flops_run.h"

namespace bs {

// One product of a peak: units x FP32 FLOP per unit per cycle x clock (a heterogeneous CPU has one per cluster).
struct PeakTerm {
  double units = 0;                    // CUDA cores, stream processors, EUs, CPU cores
  std::string unit;                    // what a unit is: "CUDA cores", "EUs", "Cortex-A57 cores"
  double flop_per_unit_per_cycle = 0;  // FP32, an FMA counts 2
  double clock_ghz = 0;
};

struct DeviceSpec {
  std::string id;    // stable, e.g. "intel-iris-plus-650"
  std::string name;  // e.g. "Intel Iris Plus Graphics 650"
  DeviceKind kind = DeviceKind::Other;
  std::vector<std::string> aliases;  // other names the device goes by ("NUC GPU", "GTX1080Ti", "Tegra X2")
  double fp32_peak_flops = 0;        // FLOP/s: units x FP32 FLOP per unit per cycle (FMA = 2) x highest clock
  std::string derivation;            // how fp32_peak_flops was computed, e.g. "48 EUs x 16 ... x 1.15 GHz"
  std::optional<double> memory_bandwidth_bytes_per_s;
  std::optional<double> tdp_w;
  std::string source_title;  // vendor page or datasheet
  std::string source_url;
  std::vector<std::string> source_more_urls;  // further pages that confirm other fields
  std::string note;
  // The terms fp32_peak_flops is the sum of (tests recompute it); empty when the figure is the vendor's own.
  std::vector<PeakTerm> peak_terms;
  // Why fp32_peak_flops is not the sum of peak_terms within 2 %, or why there are no terms; "" when it is.
  std::string peak_exempt;
  // Fields no source confirmed: "units", "flop_per_unit_per_cycle", "clock_ghz" (the peak's terms),
  // "fp32_peak_flops", "memory_bandwidth_bytes_per_s", "tdp_w". Shown with a trailing '?' in devices --table.
  std::vector<std::string> unverified;

  bool is_unverified(std::string_view field) const;
  // fp32_peak_flops or one of its terms unconfirmed.
  bool peak_unverified() const;
  // The sum of peak_terms in FLOP/s (0 without terms).
  double peak_from_terms() const;
};

struct DeviceTable {
  std::string path;  // where it was loaded from ("" for a table parsed from text)
  std::vector<DeviceSpec> devices;
};

// Throws std::runtime_error naming `origin`, the entry and the field for malformed input.
DeviceTable parse_device_table(std::string_view json_text, const std::string& origin);
DeviceTable load_device_table(const std::filesystem::path& path);

// The bundled table (find_resource("devices/devices.json")), loaded once. When it cannot be found or read,
// `table` is empty and `error` says why, so callers can say that no spec check was made instead of staying silent.
struct BundledDeviceTable {
  DeviceTable table;
  std::string error;
};
const BundledDeviceTable& bundled_device_table();

// Lowercase words and numbers: trademarks and vendor words (intel, nvidia, amd, geforce, radeon, core, graphics,
// corporation) dropped, punctuation as spaces, letters and digits split ("GTX1080Ti" -> "gtx 1080 ti").
std::vector<std::string> device_name_tokens(std::string_view name);

// The entry whose name or alias appears, as whole consecutive tokens, in `device`, longest such name first; only
// entries of `kind` unless kind is Other. Two different entries tied for the longest: no match (ambiguous). When the
// device name matches nothing, `platform` is tried the same way (the paper's "Jetson GPU" on platform "Jetson TX2").
const DeviceSpec* match_device(const DeviceTable& table, std::string_view device, DeviceKind kind,
                               std::string_view platform = {});

// The highest TDP among the entries that a platform name matches best, any kind (a "Jetson TX2" names its CPU and
// GPU entries, both the module's 15 W); nullopt when none matches or none has a TDP.
std::optional<double> platform_tdp_w(const DeviceTable& table, std::string_view platform);

}  // namespace bs
