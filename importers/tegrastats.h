// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// NVIDIA tegrastats logs. JetPack 4 style rails "VDD_IN 3981/3981" (mW, current/average; Nano: "POM_5V_IN ..."),
// JetPack 5+ style "VDD_IN 5000mW/5000mW". Every rail becomes a power channel in W, the board input rail
// (VDD_IN / POM_5V_IN / VIN_*) first. Times come from a leading "MM-DD-YYYY HH:MM:SS" when tegrastats printed one
// (newer releases, or --logfile with timestamps), otherwise from the interval (tegrastats' default: 1 s).
#include <string>

#include "importer.h"

namespace bs {

class TegrastatsImporter final : public Importer {
 public:
  std::string_view id() const override { return "tegrastats"; }
  std::string_view description() const override { return "NVIDIA tegrastats log"; }
  int sniff(std::string_view head, std::string_view path) const override;
  ImportBatch parse(const std::string& path, const ImportLimits& limits, const CancelToken& cancel) const override;
};

ImportBatch parse_tegrastats(std::string_view text, const std::string& file, double interval_s = 1.0);

}  // namespace bs
