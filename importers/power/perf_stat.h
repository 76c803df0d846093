// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// RAPL energy as `perf stat` prints it (events power/energy-pkg/, -cores/, -ram/, -gpu/, -psys/; Joules):
//  - interval CSV: `perf stat -a -e power/energy-pkg/,power/energy-ram/ -I 1000 -x,` -> "time,value,unit,event,..."
//    (per-socket "time,S0,1,value,unit,event,..." too); human interval: "#  time  counts unit events" then
//    "1.001078602  9.93 Joules power/energy-pkg/". Each interval's energy over its length (from the previous
//    timestamp, the first from 0) is its mean power; the interval becomes two samples, at its start and its end,
//    holding that power, so the trapezoidal energy of the trace equals perf's Joules exactly.
//  - the human summary people paste (no -I): "43.26 Joules power/energy-pkg/" and "1.001041336 seconds time
//    elapsed" gives the mean power over the run: a two-sample trace (0 and the elapsed time) per "Performance
//    counter stats" block; `-r N` means per run are kept as they are. Thousands separators and a decimal comma
//    (locale, told by the elapsed time or interval time) are read. CSV without -I has no elapsed time: it is read
//    only with a duration_time event, else the error says to record with -I.
// One Power channel per RAPL domain ("pkg", "ram", per socket "S0 pkg"); "<not counted>" and "<not supported>"
// are missing samples (NaN). The total channel is psys (the whole platform on client parts) when it has readings,
// else pkg (the CPU package: cores, caches, memory controller, integrated GPU; not DRAM). Other events (cycles,
// instructions, MiB) and non-perf lines (the program's own output) are ignored. "# started on <date>" gives the
// absolute start time. Errors: no RAPL events, a value that is not a number, a unit other than Joules, time going
// backwards, interval and summary records mixed.
#include <string>

#include "common/format_importer.h"

namespace bs {

// Streams the file line by line (memory: the parsed samples plus one 1 MiB block).
extern const FileFormat kPerfStatFileFormat;

}  // namespace bs
