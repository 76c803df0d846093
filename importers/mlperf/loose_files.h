// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// MLPerf files as a lab keeps them after a download: side by side in one folder, each run's files named with one
// prefix, whatever the lab called them: "Orin_TRT_MaxQ_resnet50_SingleStream_summary.txt" with "..._detail.txt",
// "..._spl.txt" and its measurements JSON, or "orin-ss-mlperf_log_summary.txt" with "orin-ss-mlperf_log_detail.txt",
// and the system description under any name ("Orin_TRT_MaxQ.system.json", "Orin_TRT_MaxQ.json"). A companion is
// paired with a summary only when the pairing is unambiguous: its name is the summary's with "detail" / "spl" for
// "summary" (a submission's run_1/ is the empty prefix), else it starts with the summary's prefix and names its
// role, and no other summary's longer prefix claims it; two files of one role for one summary pair neither.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/importer.h"

namespace bs::mlperf_loose {

// The part of a summary's file name before "mlperf_log_summary" (else before its last "summary"):
// "Orin_resnet50_SS_" for "Orin_resnet50_SS_summary.txt", "" for "mlperf_log_summary.txt"; nullopt when the name has
// no "summary".
std::optional<std::string> run_prefix(std::string_view file_name);

// What sits beside a loose summary; paths are empty where nothing pairs. The notes say why a role was not paired.
struct LooseFiles {
  std::string detail, spl, system, measurements;
  std::string pairing_note;       // two files could be its detail log or power log: neither taken
  std::string system_note;        // several system descriptions, none named by it
  std::string measurements_note;  // measurements descriptions beside it, none its own
};
LooseFiles loose_files_of(const std::filesystem::path& summary, const ImportLimits& limits);

// "system description" for an MLPerf systems/<system>.json, "measurements description" for a measurements
// <system>_<scenario>.json (by their fields), else "": neither holds a result; both are read with a summary.
std::string description_kind(std::string_view text);

}  // namespace bs::mlperf_loose
