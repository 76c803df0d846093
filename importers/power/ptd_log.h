// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// SPEC PTDaemon power logs as the MLPerf power client/server writes them (spl.txt, *_power.txt):
//   Time,12-23-2020 10:21:51.496,Watts,23.430000,Volts,228.370000,Amps,0.204280,PF,0.502300,Mark,testing
// followed, on multi-channel analyzers, by groups "Ch1,Watts,..,Volts,..,Amps,..,PF,..". Each line is one sample;
// the channels are power (W, the total), voltage (V) and current (A), and "Ch1 power" etc. for channel groups;
// the power factor is not kept. A run of lines with the same Mark becomes a named phase (PowerTrace::phases, from
// its first to its last sample): "ranging" and "testing" are MLPerf's. The date is MM-DD-YYYY as PTDaemon writes
// it; a log whose dates only fit DD-MM-YYYY is read so. -1 is PTDaemon's "no reading": a missing sample (NaN).
// Lines that are not "Time," samples (PTDaemon messages) are skipped with a warning; merged multi-analyzer lines
// are read up to the first ",AnalyzerN," group. Errors: a malformed time or number, channel groups that change
// mid-log, time going backwards.
#include <string>

#include "common/format_importer.h"

namespace bs {

// Streams the file line by line (memory: the parsed samples plus one 1 MiB block).
extern const FileFormat kPtdLogFileFormat;

}  // namespace bs
