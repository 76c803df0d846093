// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Importing a power log with the ParseOptions the generic import_file() does not pass (supply voltage, tegrastats
// interval, platform): the same text checks and sniffing, restricted to the power formats.
#include <memory>
#include <string>
#include <vector>

#include "common/importer.h"

namespace bs {

// The power-log importers ("benchscope-power-recording", "jtop-csv", "nvidia-smi", "perf-stat-rapl", "ptdaemon",
// "tegrastats", "power-csv"), in the order import_power_log() breaks a tie between equal sniff scores.
std::vector<std::unique_ptr<Importer>> make_power_importers();

// Rejects empty / binary / UTF-16 files like import_file(), picks the power format by content and parses
// with `options`. UnknownFormat when the file is neither.
ImportBatch import_power_log(const std::string& path, const ParseOptions& options = {},
                             const CancelToken& cancel = CancelToken{}, const ImportLimits& limits = {});

}  // namespace bs
