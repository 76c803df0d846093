// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/platform/platform_table.h"

#include "analysis/peaks/flag_notes.h"
#include "analysis/stats/units.h"
#include "util/text.h"

namespace bs {
namespace {

const char* const kDash = "\xE2\x80\x93";  // en dash: no data

std::string num(std::optional<double> v, const char* fmt = "%.2f") { return v ? format_number(fmt, *v) : kDash; }

std::string ms(const std::optional<Summary>& s) {
  if (!s) return kDash;
  return format_mean_sd(s->mean, s->sd, s->n, "", 2);
}

// GPU peaks in TFLOPS and CPU peaks in GFLOPS, as the paper's Tables 1 and 2 and the Peak FLOPS table give them.
std::string peak(const std::optional<PeakRow>& p, double scale, const char* fmt) {
  if (!p) return kDash;
  return num(p->peak.flops / scale, fmt) + " (" + p->device + ", " + p->backend + ")";
}

std::string fraction(const PlatformRow& r) {
  for (const auto* p : {&r.gpu, &r.cpu})
    if (*p && (*p)->fraction_of_theoretical) return num(100 * *(*p)->fraction_of_theoretical, "%.0f %%");
  return kDash;
}

}  // namespace

std::vector<std::string> platform_table_columns(bool with_verdicts) {
  std::vector<std::string> c{"platform",
                             column::kGpuPeak,
                             column::kCpuPeak,
                             "theoretical",
                             column::kPipeline,
                             "detect",
                             column::kPower,
                             "max_power",
                             "gflops_w_paper",
                             "gflops_w_mean",
                             column::kEnergyPerFrame,
                             column::kEnergyPerStage,
                             column::kEnergyPerStage,
                             "battery",
                             "frames_per_wh"};
  if (with_verdicts) {
    c.push_back("meets");
    c.push_back("failed");
  }
  return c;
}

ExportTable platform_table(std::span<const PlatformRow> rows, std::span<const PlatformVerdict> verdicts) {
  ExportTable t;
  t.caption = "Platform comparison";
  t.label = "tab:platforms";
  t.header = {"Platform",
              "GPU peak (TFLOPS)",
              "CPU peak (GFLOPS)",
              "Of theoretical peak",
              "Preprocessing (ms)",
              "Detection (ms)",
              "Mean power (W)",
              "Max power (W)",
              "GFLOPS/W (paper: peak / max power)",
              "GFLOPS/W (peak / mean power)",
              "Energy per frame (J)",
              "Energy per preprocessed frame (J)",
              "Energy per inference (J)",
              "Battery runtime (min)",
              "Frames per Wh"};
  const bool with_verdicts = verdicts.size() == rows.size() && !rows.empty();
  if (with_verdicts) {
    t.header.push_back("Meets constraints");
    t.header.push_back("Failed (margin)");
  }
  const std::vector<std::string> columns = platform_table_columns(with_verdicts);
  FlagNotes notes;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const PlatformRow& r = rows[i];
    std::vector<std::string> cells{
        r.platform,
        peak(r.gpu, 1e12, "%.2f"),
        peak(r.cpu, 1e9, "%.1f"),
        fraction(r),
        ms(r.preprocess_ms),
        ms(r.detect_ms),
        num(r.mean_power_w),
        num(r.max_power_w),
        num(r.gflops_per_watt_paper),
        num(r.gflops_per_watt_mean),
        num(r.energy_per_frame_j, "%.3f"),
        num(r.energy_per_preprocess_j, "%.3f"),
        num(r.energy_per_inference_j, "%.3f"),
        num(r.battery_runtime_h ? std::optional<double>(*r.battery_runtime_h * 60) : std::nullopt),
        num(r.frames_per_wh, "%.0f")};
    // Flagged cells get a footnote marker; the notes go under the table (analysis/flag_notes.h).
    for (std::size_t c = 0; c < cells.size() && c < columns.size(); ++c)
      if (const auto f = r.flags.find(columns[c]); f != r.flags.end()) cells[c] = notes.mark(cells[c], f->second);
    if (with_verdicts) {
      const PlatformVerdict& v = verdicts[i];
      cells.push_back(v.recommended ? "yes (recommended)" : v.meets_all && v.note.empty() ? "yes" : "no");
      std::string failed;
      for (const ConstraintCheck& k : v.checks) {
        if (k.met) continue;
        if (!failed.empty()) failed += "; ";
        failed += k.name + (k.actual ? " (" + num(k.margin, "%+.2f") + " " + k.unit + ")" : " (no data)");
      }
      if (failed.empty() && !v.note.empty()) failed = v.note;
      cells.push_back(failed.empty() ? kDash : failed);
    }
    t.rows.push_back(std::move(cells));
  }
  notes.add_to(t);
  return t;
}

}  // namespace bs
