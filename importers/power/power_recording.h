// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// BenchScope's own power recordings (benchscope-cli record-power, run flops --power --out): a power CSV whose
// first line is "# benchscope power recording v1" and whose comment lines say which on-board sensor measured,
// on which host, from when, which channel is the total, and the phases marked during the run
// (core/sensors/recording_csv.h). The columns are read by the power-CSV parser; this importer adds what the
// comments say. Errors: a comment block that names a total channel the columns lack, a phase that ends before
// it starts or is not "NAME = START .. END", a measurement other than an on-board sensor's.
#include <string>

#include "common/format_importer.h"

namespace bs {

// No options: the comment block says what they would.
extern const FileFormat kPowerRecordingFileFormat;

}  // namespace bs
