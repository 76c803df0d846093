// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The paper's pipeline timings table (stage x platform): mean ± SD (n) in ms, p95 where known, the rate a stage
// alone sustains and the pipeline's measured throughput, each row with its provenance. Shared by the Pipeline
// view and the LaTeX/CSV export so they show the same numbers.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "model/pipeline_run.h"
#include "util/table_export.h"

namespace bs {

struct PipelineTableRow {
  std::string stage;        // canonical name (pipeline_stage::k...)
  std::string stage_label;  // "Preprocessing (demosaic + reprojection)", "Detection", "End to end"
  std::string platform, device, backend;
  std::size_t n = 0;
  double mean_ms = 0, sd_ms = 0;
  std::optional<double> p95_ms;
  // 1000 / mean ms: frames per second this stage alone keeps up with. None for end to end: that is a latency
  // (queueing included), and the run's throughput says the rate.
  std::optional<double> stage_fps;
  std::optional<double> throughput_fps;  // of the whole run, when measured
  DataOrigin origin = DataOrigin::Unknown;
  std::string provenance;         // one paragraph: origin, note, host, date, file
  std::string lens_calibration;   // how the run's lens was obtained (vision::describe); empty: not recorded
  std::string time_text() const;  // "6.21 ± 0.99 ms (n = 500)": SD to the mean's decimals
  std::string p95_text() const;   // "8.10", "–" when unknown
};

// Three significant figures like the paper's 6.21 ms (0 to 2 decimals by magnitude, never exponents).
std::string format_ms(double ms);
// Position of a stage in the pipeline (preprocess 0, detect 1, end-to-end 2, others 3), for sorting.
int pipeline_stage_order(const std::string& stage);

// Rows ordered by stage (preprocessing, detection, end to end), then platform, as in the paper's text.
std::vector<PipelineTableRow> pipeline_table_rows(std::span<const PipelineRun> runs);

// The same rows as an export table (LaTeX booktabs / CSV).
ExportTable pipeline_table(std::span<const PipelineRun> runs);

}  // namespace bs
