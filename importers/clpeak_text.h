// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// clpeak's plain-text report: "Platform: ..." / "  Device: ..." blocks, device properties ("Compute units : 28"),
// sections titled with a unit ("Single-precision compute (GFLOPS)") holding "float4 : 11437.44" lines, and
// "Kernel launch latency : 4.73 us". One ResultSet per device, values converted to SI units.
#include <string>

#include "importer.h"

namespace bs {

class ClpeakTextImporter final : public Importer {
 public:
  std::string_view id() const override { return "clpeak-text"; }
  std::string_view description() const override { return "clpeak text output"; }
  int sniff(std::string_view head, std::string_view path) const override;
  ImportBatch parse(const std::string& path, const ImportLimits& limits, const CancelToken& cancel) const override;
};

ImportBatch parse_clpeak_text(std::string_view text, const std::string& file);

}  // namespace bs
