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

#include "common/importer.h"

namespace bs {

class PtdLogImporter final : public Importer {
 public:
  std::string_view id() const override { return "ptdaemon"; }
  std::string_view description() const override { return "SPEC PTDaemon power log (MLPerf spl.txt)"; }
  int sniff(std::string_view head, std::string_view path) const override;
  // Streams the file line by line (memory: the parsed samples plus one 1 MiB block).
  ImportBatch parse(const std::string& path, const ParseOptions& options, const ImportLimits& limits,
                    const CancelToken& cancel) const override;
};

// The same parser over text in memory (tests, fuzzing); `file` names it in errors.
ImportBatch parse_ptd_log(const std::string& text, const std::string& file, const ParseOptions& options = {},
                          const ImportLimits& limits = {}, const CancelToken& cancel = CancelToken{});

}  // namespace bs
