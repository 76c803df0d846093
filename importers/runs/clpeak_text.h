// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// clpeak's plain-text report: "Platform: ..." / "  Device: ..." blocks, device properties ("Compute units : 28"),
// sections titled with a unit ("Single-precision compute (GFLOPS)") holding "float4 : 11437.44" lines, and
// "Kernel launch latency : 4.73 us". One ResultSet per device (platform = OpenCL platform name, or the backend's
// name when the file has none; backend OpenCL unless clpeak 2 names another; device_kind gpu unless the device is
// recognisably a CPU), one Measurement per (variant, section): metric = the section title in lower case without its
// unit, so every precision and kind stays its own metric (model/measure_class.h classifies them), value converted
// to SI: GFLOPS/TFLOPS -> FLOP/s, GBPS -> B/s, GIOPS/GOPS/TOPS -> 1/s (integer operations), us -> s.
#include <string>

#include "common/format_importer.h"

namespace bs {

// Reads what people save and paste: CRLF, tabs, a shell prompt or banner before the output, a paste that starts at
// "Device:" (no "Platform:" line), several platforms and devices, clpeak 2.0 ("=== Vulkan backend ===",
// "Vulkan Device: ...", TFLOPS sections, cooperative-matrix groups) and 2.1 ("Backend: CPU", "Device 0:", units on
// each value line: "fdiv fp32 ST : 8.48 GFLOPS"). Skipped tests ("No half precision support! Skipped", an OpenCL
// error in place of a value, "[skipped]" rows) are warnings. A value that is not a measurement ("inf", a negative
// latency, a crash message, nothing after the colon) is skipped with a warning naming file:line; the rest of the
// file is kept. A device without any measurement is left out with a warning. Only a file without any measurement is
// an error: the first unreadable value when there was one, else a missing-field error. No options or limits (the
// file's size is bounded by ImportLimits::max_json_bytes when it is read).
extern const FileFormat kClpeakTextFileFormat;

}  // namespace bs
