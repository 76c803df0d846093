// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// BenchScope's own power recordings (benchscope-cli record-power, run flops --power --out): a power CSV whose
// first line is "# benchscope power recording v1" and whose comment lines say which on-board sensor measured,
// on which host, from when, which channel is the total, and the phases marked during the run
// (core/sensors/recording_csv.h). The columns are read by the power-CSV parser; this importer adds what the
// comments say. Errors: a comment block that names a total channel the columns lack, a phase that ends before
// it starts or is not "NAME = START .. END", a measurement other than an on-board sensor's.
#include <string>

#include "common/importer.h"

namespace bs {

class PowerRecordingImporter final : public Importer {
 public:
  std::string_view id() const override { return "benchscope-power-recording"; }
  std::string_view description() const override { return "BenchScope on-board sensor power recording (CSV)"; }
  int sniff(std::string_view head, std::string_view path) const override;
  bool usual_extension(std::string_view path) const override;
  ImportBatch parse(const std::string& path, const ParseOptions& options, const ImportLimits& limits,
                    const CancelToken& cancel) const override;
};

// The same over text in memory (tests, fuzzing); `file` names it in errors. No options: the comment block says
// what they would.
ImportBatch parse_power_recording(const std::string& text, const std::string& file, const ParseOptions& options = {},
                                  const ImportLimits& limits = {}, const CancelToken& cancel = CancelToken{});

}  // namespace bs
