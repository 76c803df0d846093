// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Current / voltage / power logs as delimited text: separator sniffed (, ; tab), decimal comma with ; or tab, UTF-8
// BOM, '#' comment lines (a '#'-prefixed first line that names columns is the header, as Joulescope writes it),
// header aliases with units from the name ("current_mA", "Current (A)", "[mW]", "millis", "Timestamp (s)").
// Comment lines "# platform: NUC" and "# supply_voltage_V: 16" set the platform and the supply of current-only logs.
// Covers generic loggers, Joulescope and Otii CSV exports and INA219-style logger CSVs.
#include <string>

#include "importer.h"

namespace bs {

class PowerCsvImporter final : public Importer {
 public:
  std::string_view id() const override { return "power-csv"; }
  std::string_view description() const override { return "current/power log (CSV)"; }
  int sniff(std::string_view head, std::string_view path) const override;
  ImportBatch parse(const std::string& path, const ImportLimits& limits, const CancelToken& cancel) const override;
};

ImportBatch parse_power_csv(std::string_view text, const std::string& file, const CancelToken& cancel = CancelToken{});

}  // namespace bs
