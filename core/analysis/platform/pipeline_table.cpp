// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/platform/pipeline_table.h"

#include <algorithm>
#include <cstdio>

#include "util/text.h"

namespace bs {
namespace {

std::string stage_label(const std::string& s) {
  if (s == pipeline_stage::kPreprocess) return "Preprocessing (demosaic + reprojection)";
  if (s == pipeline_stage::kDetect) return "Detection";
  if (s == pipeline_stage::kEndToEnd) return "End to end";
  return s;
}

int decimals(double ms) { return ms >= 100 ? 0 : ms >= 10 ? 1 : 2; }

std::string provenance_text(const PipelineRun& r) {
  const Provenance& p = r.provenance;
  std::string s = std::string(to_string(p.origin));
  if (!p.note.empty()) s += ": " + p.note;
  if (!p.host.empty()) s += "; host " + p.host;
  if (!p.date.empty()) s += "; " + p.date;
  if (!p.tool.empty()) s += "; " + p.tool;
  if (!p.source_file.empty()) s += "; file " + p.source_file;
  return s;
}

}  // namespace

int pipeline_stage_order(const std::string& s) {
  return s == pipeline_stage::kPreprocess ? 0
         : s == pipeline_stage::kDetect   ? 1
         : s == pipeline_stage::kEndToEnd ? 2
                                          : 3;
}

std::string format_ms(double ms) { return fixed(ms, decimals(ms)); }

std::string PipelineTableRow::time_text() const {
  const int d = decimals(mean_ms);
  return fixed(mean_ms, d) + " ± " + fixed(sd_ms, d) + " ms (n = " + std::to_string(n) + ")";
}

std::string PipelineTableRow::p95_text() const { return p95_ms ? format_ms(*p95_ms) : "–"; }

std::vector<PipelineTableRow> pipeline_table_rows(std::span<const PipelineRun> runs) {
  std::vector<PipelineTableRow> rows;
  for (const PipelineRun& r : runs)
    for (const StageStats& s : r.stages) {
      PipelineTableRow row;
      row.stage = s.stage;
      row.stage_label = stage_label(s.stage);
      row.platform = r.platform;
      row.device = r.device;
      row.backend = r.backend;
      row.n = s.n;
      row.mean_ms = s.mean_s * 1e3;
      row.sd_ms = s.sd_s * 1e3;
      if (s.p95_s) row.p95_ms = *s.p95_s * 1e3;
      if (s.mean_s > 0 && s.stage != pipeline_stage::kEndToEnd) row.stage_fps = 1.0 / s.mean_s;
      row.throughput_fps = r.throughput_fps;
      row.origin = r.provenance.origin;
      row.provenance = provenance_text(r);
      for (const auto& [key, value] : r.provenance.settings)
        if (key == "lens calibration") row.lens_calibration = value;
      rows.push_back(std::move(row));
    }
  std::stable_sort(rows.begin(), rows.end(), [](const PipelineTableRow& a, const PipelineTableRow& b) {
    const int sa = pipeline_stage_order(a.stage), sb = pipeline_stage_order(b.stage);
    return sa != sb ? sa < sb : a.platform < b.platform;
  });
  return rows;
}

ExportTable pipeline_table(std::span<const PipelineRun> runs) {
  ExportTable t;
  t.caption = "Vision pipeline stage times per platform: mean ± SD (n frames); p95 where measured.";
  t.label = "tab:pipeline";
  t.header = {"Stage", "Platform", "Time", "p95 (ms)", "Stage rate (fps)", "Data"};
  t.align = "llrrrl";
  for (const PipelineTableRow& r : pipeline_table_rows(runs)) {
    char fps[32] = "–";
    if (r.stage_fps) std::snprintf(fps, sizeof fps, "%.1f", *r.stage_fps);
    t.rows.push_back({r.stage_label, r.platform, r.time_text(), r.p95_text(), fps, std::string(to_string(r.origin))});
  }
  return t;
}

}  // namespace bs
