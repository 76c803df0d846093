// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// clpeak's plain-text report: "Platform: ..." / "  Device: ..." blocks, device properties ("Compute units : 28"),
// sections titled with a unit ("Single-precision compute (GFLOPS)") holding "float4 : 11437.44" lines, and
// "Kernel launch latency : 4.73 us". One ResultSet per device (platform = OpenCL platform name, backend OpenCL,
// device_kind gpu unless the device is recognisably a CPU), one Measurement per (variant, section) with the value
// converted to SI: GFLOPS -> FLOP/s, GBPS -> B/s, GIOPS -> 1/s (integer operations), us -> s.
#include <string>

#include "importer.h"

namespace bs {

class ClpeakTextImporter final : public Importer {
 public:
  std::string_view id() const override { return "clpeak-text"; }
  std::string_view description() const override { return "clpeak text output"; }
  int sniff(std::string_view head, std::string_view path) const override;
  bool usual_extension(std::string_view path) const override;
  ImportBatch parse(const std::string& path, const ImportLimits& limits, const CancelToken& cancel) const override;
};

// Tolerates CRLF, tabs, skipped tests ("No half precision support! Skipped", an OpenCL error in place of a value,
// clpeak 2's "[skipped]" rows: warnings, not errors) and clpeak 2's "Backend:" / "Device 0:" / "(GB/s)" spelling.
// A device without any measurement is left out with a warning; a file without any device is an error.
ImportBatch parse_clpeak_text(std::string_view text, const std::string& file, const CancelToken* cancel = nullptr);

}  // namespace bs
