// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// nvidia-smi query logs: `nvidia-smi --query-gpu=timestamp,name,pci.bus_id,power.draw,... --format=csv[,noheader]
// [,nounits] -l 1 | -lms 100`, parsed in one streaming pass.
//  - Header names are nvidia-smi's field names, the unit in brackets ("power.draw [W]"); cells carry the unit too
//    ("285.43 W") unless nounits. power.draw, power.draw.instant and power.draw.average become Power channels in W;
//    the total channel is power.draw, else .instant, else .average. driver_version and power.limit of the first
//    row become settings. Other columns (utilization, memory, pstate) are ignored, named once in a warning.
//  - Clocks and temperatures (#53) make one SustainRun per GPU on its trace's time axis: clocks.sm / .gr / .mem /
//    .video (also clocks.current.*) in MHz, with the maximum from clocks.max.* of the same clock where queried;
//    temperature.gpu and temperature.memory in C. clocks_throttle_reasons.* / clocks_event_reasons.* ("Active",
//    or the .active bit mask, its "GPU idle" bit not counted) are summed up in the record's provenance note
//    (active in N of M samples, first at t s). A cell of these that does not parse is a warning and NaN.
//  - One PowerTrace per GPU: rows of several GPUs interleave and are told apart by pci.bus_id, else uuid, else
//    index, else name. gpu_model = the name column; the label names the GPU when the log holds several.
//  - timestamp "2023/10/05 14:31:02.123" (or ISO 8601) gives the times and the absolute start_time; a log without
//    a timestamp column is an error (the sampling interval of -l is not in the file).
//  - "[N/A]", "[Not Supported]", "[Unknown Error]" and any other bracketed cell are missing samples (NaN), never 0.
//  - noheader: read only when the columns can be inferred safely (a "YYYY/MM/DD HH:MM:SS.mmm" cell and exactly one
//    cell in W); otherwise the error says to keep the header.
//  - A repeated header line (logs appended run after run) is skipped with a warning; a cut-off last line too.
// Errors: no power.draw column, unknown unit, rows with a different number of cells, time going backwards for a
// GPU, a number that does not parse.
#include <string>

#include "common/format_importer.h"

namespace bs {

// Streams the file line by line (memory: the parsed samples plus one 1 MiB block).
extern const FileFormat kNvidiaSmiFileFormat;

}  // namespace bs
