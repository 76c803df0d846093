// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a power log cannot say about itself. The Importer interface has no options, so import_file() uses the
// defaults below (and what the file's own "# platform:" / "# supply_voltage_V:" comments say); callers that know
// more (the CLI's --supply-volts, a GUI dialog) call read_power_csv() / read_tegrastats() with these.
#include <optional>
#include <string>

namespace bs {

struct PowerImportOptions {
  // Supply voltage of a current-only log, used to turn current into power. Overrides a "# supply_voltage_V:"
  // comment. Left empty, such a trace keeps supply_voltage_v empty (power unknown until a platform gives it).
  std::optional<double> supply_voltage_v;
  // Seconds between tegrastats lines that carry no timestamp (tegrastats --interval, default 1000 ms).
  double interval_s = 1.0;
  // Platform name when the file does not name one ("# platform: NUC"); tegrastats logs default to "Jetson".
  std::string platform;
};

// The longest line a power log may have: anything longer is not a log line, and the streaming reader's buffer
// never grows beyond it.
inline constexpr std::size_t kMaxPowerLogLineBytes = std::size_t{1} << 20;

}  // namespace bs
