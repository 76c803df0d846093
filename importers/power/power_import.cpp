// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/power_import.h"

#include "power/jtop_csv.h"
#include "power/nvidia_smi.h"
#include "power/perf_stat.h"
#include "power/power_csv.h"
#include "power/power_recording.h"
#include "power/ptd_log.h"
#include "power/tegrastats.h"

namespace bs {

// Every power-log format, in the order that breaks a tie between equal sniff scores: measuring tools' own logs first
// (they out-sniff the generic CSV on their files), tegrastats, then the generic CSV. BenchScope's own record-power CSV
// reads its settings from its header comments, not from the options.
std::vector<std::unique_ptr<Importer>> make_power_importers() {
  return importers_of({&kPowerRecordingFileFormat, &kJtopCsvFileFormat, &kNvidiaSmiFileFormat, &kPerfStatFileFormat,
                       &kPtdLogFileFormat, &kTegrastatsFileFormat, &kPowerCsvFileFormat});
}

ImportBatch import_power_log(const std::string& path, const ParseOptions& options, const CancelToken& cancel,
                             const ImportLimits& limits) {
  const std::string head = read_head(path);
  check_text(head, path);
  const std::string_view view = strip_utf8_bom(head);
  const auto formats = make_power_importers();
  const Importer* best = nullptr;
  int best_score = 0;
  for (const auto& f : formats)
    if (const int score = f->sniff(view, path); score > best_score) {
      best = f.get();
      best_score = score;
    }
  if (!best)
    throw ImportError(ImportErrorCategory::UnknownFormat, {path, 0, 0, {}},
                      "not a power log (expected a CSV with time and current/power columns, a tegrastats log, a jtop "
                      "CSV, or an nvidia-smi, perf stat RAPL or PTDaemon log)");
  ImportBatch batch = best->parse(path, options, limits, cancel);
  batch.format = std::string(best->id());
  batch.source_path = path;
  return batch;
}

}  // namespace bs
