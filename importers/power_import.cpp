// SPDX-License-Identifier: GPL-3.0-or-later
#include "power_import.h"

#include <algorithm>

#include "nvidia_smi.h"
#include "perf_stat.h"
#include "power_csv.h"
#include "ptd_log.h"
#include "tegrastats.h"

namespace bs {

std::vector<std::unique_ptr<Importer>> make_power_importers() {
  std::vector<std::unique_ptr<Importer>> list;
  list.push_back(std::make_unique<PowerCsvImporter>());
  list.push_back(std::make_unique<TegrastatsImporter>());
  list.push_back(std::make_unique<NvidiaSmiImporter>());
  list.push_back(std::make_unique<PerfStatImporter>());
  list.push_back(std::make_unique<PtdLogImporter>());
  return list;
}

ImportBatch import_power_log(const std::string& path, const PowerImportOptions& options, const CancelToken& cancel,
                             const ImportLimits& limits) {
  const std::string head = read_head(path);
  check_text(head, path);
  std::string_view view = head;
  if (view.starts_with("\xEF\xBB\xBF")) view.remove_prefix(3);
  const int csv = PowerCsvImporter().sniff(view, path);
  const int tegra = TegrastatsImporter().sniff(view, path);
  ImportBatch batch;
  // Measuring tools' own logs (nvidia-smi, perf stat, PTDaemon) out-sniff the generic CSV on their files.
  const int smi = NvidiaSmiImporter().sniff(view, path);
  const int perf = PerfStatImporter().sniff(view, path);
  const int ptd = PtdLogImporter().sniff(view, path);
  if (std::max({smi, perf, ptd}) > std::max(csv, tegra)) {
    if (smi >= perf && smi >= ptd) {
      batch = read_nvidia_smi(path, options, limits, cancel);
      batch.format = "nvidia-smi";
    } else if (perf >= ptd) {
      batch = read_perf_stat(path, options, limits, cancel);
      batch.format = "perf-stat-rapl";
    } else {
      batch = read_ptd_log(path, options, limits, cancel);
      batch.format = "ptdaemon";
    }
  } else if (tegra > 0 && tegra >= csv) {
    batch = read_tegrastats(path, options, limits, cancel);
    batch.format = "tegrastats";
  } else if (csv > 0) {
    batch = read_power_csv(path, options, limits, cancel);
    batch.format = "power-csv";
  } else {
    throw ImportError(ImportErrorCategory::UnknownFormat, {path, 0, 0, {}},
                      "not a power log (expected a CSV with time and current/power columns, a tegrastats, nvidia-smi, perf stat "
                      "RAPL or PTDaemon log)");
  }
  batch.source_path = path;
  return batch;
}

}  // namespace bs
