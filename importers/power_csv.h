// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Current / voltage / power logs as delimited text, parsed in one streaming pass:
//  - separator sniffed from the header (, ; tab); decimal comma accepted with ; or tab; UTF-8 BOM; CRLF;
//  - '#' comment lines; a '#'-prefixed line that names a time column is the header (Joulescope writes it so);
//  - header aliases with units from the name: "time_s", "Time [s]", "time_ms", "millis", "Timestamp (s)",
//    "current_A", "Current (mA)", "I", "mA", "voltage", "bus_V", "power_mW", "Main current (A)", German
//    "Zeit/Strom/Spannung/Leistung"; an unknown unit in brackets is an error, never a silent factor;
//  - a time column of numbers (relative seconds, or ms/us by unit) or ISO 8601 date-times (start_time is kept);
//  - "# platform: NUC" and "# supply_voltage_V: 16" comments name what the columns cannot say.
// Joulescope exports (#time,current,voltage,power[,charge,energy]), Otii exports ("Timestamp (s),Main current
// (A),Main voltage (V)") and INA219-style logger CSVs (millis,shunt_mV,bus_V,current_mA,power_mW) are header
// presets of this one parser, not copies of it.
// Errors (bs::ImportError, each naming file:line:column and column name): no header, no time or no
// current/power column, header without rows, a non-numeric or empty cell, a row with too few or too many cells,
// mixed separators, negative time, time going backwards. Warnings: ignored columns, current without a supply.
#include <string>

#include "importer.h"
#include "power_options.h"

namespace bs {

class PowerCsvImporter final : public Importer {
 public:
  std::string_view id() const override { return "power-csv"; }
  std::string_view description() const override { return "current/power log (CSV: generic, Joulescope, Otii, INA219)"; }
  int sniff(std::string_view head, std::string_view path) const override;
  bool usual_extension(std::string_view path) const override;
  ImportBatch parse(const std::string& path, const ImportLimits& limits, const CancelToken& cancel) const override;
};

// Streams the file at `path` (memory: the parsed columns plus one 1 MiB block).
ImportBatch read_power_csv(const std::string& path, const PowerImportOptions& options = {},
                           const ImportLimits& limits = {}, const CancelToken& cancel = CancelToken{});
// The same parser over text already in memory; `file` names it in errors.
ImportBatch parse_power_csv(std::string_view text, const std::string& file, const CancelToken& cancel = CancelToken{},
                            const PowerImportOptions& options = {}, const ImportLimits& limits = {});

}  // namespace bs
