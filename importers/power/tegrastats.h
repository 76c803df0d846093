// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// NVIDIA tegrastats logs, streamed line by line. Rails are "NAME reading" pairs, every rail its own Power channel in
// W holding the instantaneous (first) value:
//   JetPack 3/4 (TX1, TX2, Nano, Xavier): "VDD_IN 3981/3981", "POM_5V_IN 2556/2556" (cur/avg, mW without a unit);
//     AGX Xavier "GPU 0/0 CPU 155/155 SOC 1705/1705 CV 0/0 VDDRQ 310/310 SYS5V 1649/1649";
//   JetPack 5/6 (Xavier, Orin): "VDD_IN 5000mW/5000mW", AGX Orin "VDD_GPU_SOC 2798mW/2798mW VDD_CPU_CV ..." (cur/avg);
//   JetPack 7 (Thor, and Orin on 7.2): "VDD_GPU_SOC 4385mW/3787mW/4385mW" (cur/avg/max); Thor also "VIN 26686mW/...".
// The board total (PowerTrace::total_channel, first channel): the input rail VDD_IN / POM_5V_IN / VIN where the board
// has one; else (AGX Xavier, AGX Orin) an added channel "sum of rails", as jetson-stats computes it, with a warning
// and a provenance note: module rails only, a lower bound of the power at the supply. Times come from a leading
// "MM-DD-YYYY HH:MM:SS" (newer releases) or else from the interval (tegrastats' default 1 s; a warning says so).
// Lines without rails are skipped with a warning; a cut-off last line too.
// Beside the trace, the clocks and temperatures of every line become one SustainRun on the trace's time axis
// (tegrastats_sensors.h: CPU [..%@MHz,off,..], GR3D_FREQ, EMC_FREQ, engines, NAME@45.5C; -256C and PMIC are not
// temperatures).
// Errors: no rails anywhere, rails that change mid-log, timestamps on some lines only, time going backwards, a
// reading that does not parse, and one beyond what a rail can read (jetson_rail_limits.h: -2 W to 1 kW), which
// names file:line:column and the rail.
#include <string>

#include "common/format_importer.h"

namespace bs {

// Streams the file line by line (memory: the parsed samples plus one 1 MiB block).
extern const FileFormat kTegrastatsFileFormat;

}  // namespace bs
