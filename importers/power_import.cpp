// SPDX-License-Identifier: GPL-3.0-or-later
#include "power_import.h"

#include "power_csv.h"
#include "power_recording.h"
#include "tegrastats.h"

namespace bs {

std::vector<std::unique_ptr<Importer>> make_power_importers() {
  std::vector<std::unique_ptr<Importer>> list;
  list.push_back(std::make_unique<PowerCsvImporter>());
  list.push_back(std::make_unique<TegrastatsImporter>());
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
  if (PowerRecordingImporter().sniff(view, path) > 0) {
    batch = PowerRecordingImporter().parse(path, limits, cancel);  // its own header, not the options
    batch.format = "benchscope-power-recording";
  } else if (tegra > 0 && tegra >= csv) {
    batch = read_tegrastats(path, options, limits, cancel);
    batch.format = "tegrastats";
  } else if (csv > 0) {
    batch = read_power_csv(path, options, limits, cancel);
    batch.format = "power-csv";
  } else {
    throw ImportError(ImportErrorCategory::UnknownFormat, {path, 0, 0, {}},
                      "not a power log (expected a CSV with time and current/power columns, or a tegrastats log)");
  }
  batch.source_path = path;
  return batch;
}

}  // namespace bs
