// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// jetson-stats (jtop) CSV logs, as its examples/jtop_logger.py writes them: Python csv.DictWriter over the
// jetson.stats dictionary, one row per jtop update, header = the keys in order:
//   time,uptime,CPU1,...,RAM,SWAP,EMC,GPU,<engines>,Fan pwmfan0,Temp cpu,...,Power VDD_CPU_GPU_CV,Power VDD_SOC,
//   Power TOT,jetson_clocks,nvp model
// "time" is str(datetime) ("2025-12-16 17:14:33.703152"), "uptime" str(timedelta) ("3 days, 0:07:35.540000", quoted
// because of its comma), powers are integers in mW, temperatures in degC with -256 for an absent sensor, CPU loads
// and engines "OFF" when off.
// What is read: every "Power <rail>" column as a Power channel in W; the total is "Power TOT" (PowerTrace::
// total_channel), the value jetson-stats computes (the input rail VDD_IN / POM_5V_IN where the board has one, else
// the sum of the rails): it is never added to the rails or they to it. jetson-stats up to 4.1 wrote only the total,
// as "power cur" (its running average "power avg" is not a sample and is not imported). "nvp model" and
// "jetson_clocks" go into Provenance::settings (a change during the log is a warning and both values are kept).
// Times from "time" (absolute; start_time is kept), else from "uptime". Loads and fan are not imported.
// Temperatures and engine clocks (#53) make one SustainRun on the trace's time axis: every "Temp <sensor>" column
// in C (-256 = no sensor: NaN; "Temp PMIC" is not a measurement and is left out) and the engine columns (APE, NVENC,
// NVDEC, NVJPG, VIC, OFA, SE, DLA*, PVA*: "OFF" = NaN; kHz since jetson-stats 4.2, MHz in the older "power cur"
// logs). The CPU, GPU and EMC columns are loads, not clocks: the record says it has no CPU or GPU clock. A
// temperature or clock cell that does not parse is a warning naming file:line:column and the column, and NaN.
// Errors (file:line:column and column name): no time/uptime or no total column, a row with more or fewer cells
// than the header, an unterminated quote, a time or power cell that is not a number, a power reading outside what a
// rail can read (jetson_rail_limits.h), time going backwards. An empty power cell is a missing sample (NaN,
// counted in a warning); a cut-off last row is skipped with a warning.
#include <string>

#include "common/format_importer.h"

namespace bs {

// Streams the file line by line (memory: the parsed samples plus one 1 MiB block).
extern const FileFormat kJtopCsvFileFormat;

}  // namespace bs
