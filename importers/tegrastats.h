// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// NVIDIA tegrastats logs, streamed line by line. Rails are "NAME cur/avg" pairs in mW:
//   JetPack 4 (TX2, Nano, Xavier): "VDD_IN 3981/3981 VDD_SYS_CPU 762/762", "POM_5V_IN 2556/2556", AGX Xavier
//   "GPU 0/0 CPU 155/155 SOC 1705/1705 CV 0/0 VDDRQ 310/310 SYS5V 1649/1649";
//   JetPack 5/6 (Orin): "VDD_IN 5000mW/5000mW VDD_CPU_GPU_CV 1000mW/1000mW VDD_SOC 1200mW/1200mW".
// Every rail becomes a Power channel in W holding the instantaneous (first) value, the board input rail
// (VDD_IN / POM_5V_IN / VIN_*) first; a warning says when a board has no single input rail. Times come from a
// leading "MM-DD-YYYY HH:MM:SS" (newer releases, --logfile with timestamps) or else from the interval
// (tegrastats' default 1 s). Lines without rails are skipped with a warning; a cut-off last line too.
// Errors: no rails anywhere, rails that change mid-log, timestamps on some lines only, time going backwards.
#include <string>

#include "importer.h"
#include "power_options.h"

namespace bs {

class TegrastatsImporter final : public Importer {
 public:
  std::string_view id() const override { return "tegrastats"; }
  std::string_view description() const override { return "NVIDIA tegrastats log (Jetson rails)"; }
  int sniff(std::string_view head, std::string_view path) const override;
  ImportBatch parse(const std::string& path, const ImportLimits& limits, const CancelToken& cancel) const override;
};

ImportBatch read_tegrastats(const std::string& path, const PowerImportOptions& options = {},
                            const ImportLimits& limits = {}, const CancelToken& cancel = CancelToken{});
ImportBatch parse_tegrastats(std::string_view text, const std::string& file, double interval_s = 1.0);

}  // namespace bs
