// SPDX-License-Identifier: GPL-3.0-or-later
#include "power_import.h"

#include "jtop_csv.h"
#include "nvidia_smi.h"
#include "perf_stat.h"
#include "power_csv.h"
#include "power_recording.h"
#include "ptd_log.h"
#include "tegrastats.h"

namespace bs {
namespace {

// Every power-log format with its reader, in the order that breaks a tie between equal sniff scores: measuring
// tools' own logs first (they out-sniff the generic CSV on their files), tegrastats, then the generic CSV.
using PowerReader = ImportBatch (*)(const std::string&, const PowerImportOptions&, const ImportLimits&,
                                    const CancelToken&);
struct PowerFormat {
  std::unique_ptr<Importer> importer;
  PowerReader read;
};

// BenchScope's own record-power CSV reads its settings from its header comments, not from the options.
ImportBatch read_power_recording(const std::string& path, const PowerImportOptions& /*options*/,
                                 const ImportLimits& limits, const CancelToken& cancel) {
  return PowerRecordingImporter().parse(path, limits, cancel);
}

std::vector<PowerFormat> power_formats() {
  std::vector<PowerFormat> list;
  list.push_back({std::make_unique<PowerRecordingImporter>(), read_power_recording});
  list.push_back({std::make_unique<JtopCsvImporter>(), read_jtop_csv});
  list.push_back({std::make_unique<NvidiaSmiImporter>(), read_nvidia_smi});
  list.push_back({std::make_unique<PerfStatImporter>(), read_perf_stat});
  list.push_back({std::make_unique<PtdLogImporter>(), read_ptd_log});
  list.push_back({std::make_unique<TegrastatsImporter>(), read_tegrastats});
  list.push_back({std::make_unique<PowerCsvImporter>(), read_power_csv});
  return list;
}

}  // namespace

std::vector<std::unique_ptr<Importer>> make_power_importers() {
  std::vector<std::unique_ptr<Importer>> list;
  list.push_back(std::make_unique<PowerCsvImporter>());
  list.push_back(std::make_unique<TegrastatsImporter>());
  list.push_back(std::make_unique<JtopCsvImporter>());
  list.push_back(std::make_unique<NvidiaSmiImporter>());
  list.push_back(std::make_unique<PerfStatImporter>());
  list.push_back(std::make_unique<PtdLogImporter>());
  list.push_back(std::make_unique<PowerRecordingImporter>());
  return list;
}

ImportBatch import_power_log(const std::string& path, const PowerImportOptions& options, const CancelToken& cancel,
                             const ImportLimits& limits) {
  const std::string head = read_head(path);
  check_text(head, path);
  std::string_view view = head;
  if (view.starts_with("\xEF\xBB\xBF")) view.remove_prefix(3);
  const auto formats = power_formats();
  const PowerFormat* best = nullptr;
  int best_score = 0;
  for (const PowerFormat& f : formats)
    if (const int score = f.importer->sniff(view, path); score > best_score) {
      best = &f;
      best_score = score;
    }
  if (!best)
    throw ImportError(ImportErrorCategory::UnknownFormat, {path, 0, 0, {}},
                      "not a power log (expected a CSV with time and current/power columns, a tegrastats log, a jtop "
                      "CSV, or an nvidia-smi, perf stat RAPL or PTDaemon log)");
  ImportBatch batch = best->read(path, options, limits, cancel);
  batch.format = std::string(best->importer->id());
  batch.source_path = path;
  return batch;
}

}  // namespace bs
