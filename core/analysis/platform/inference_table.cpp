// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/platform/inference_table.h"

#include <limits>

#include "analysis/stats/units.h"
#include "util/text.h"

namespace bs {
namespace {

const char* const kDash = "\xE2\x80\x93";  // en dash: no data

std::string num(double v, const char* fmt) { return v == v ? format_number(fmt, v) : kDash; }  // NaN: no data

}  // namespace

std::string inference_network_text(const DnnRun& r) {
  std::string s = r.model + " (" + r.family + ")";
  if (r.architecture_only) s += ", " + std::string(kArchitectureTimingLabel);
  return s;
}

double inference_value(const DnnRun& r, InferenceColumn c) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const double per_image = r.batch > 0 ? static_cast<double>(r.flops) / r.batch : nan;
  switch (c) {
    case InferenceColumn::TimePerImage:
      return r.inference_s() * 1e3;
    case InferenceColumn::InferencesPerS:
      return r.inferences_per_s();
    case InferenceColumn::Gflops:
      return r.achieved_flops() / 1e9;
    case InferenceColumn::OfCeiling:
      return r.device_peak_flops && *r.device_peak_flops > 0 ? 100 * r.achieved_flops() / *r.device_peak_flops : nan;
    case InferenceColumn::EnergyPerInference:
      return r.energy_per_inference_j ? *r.energy_per_inference_j : nan;
    case InferenceColumn::InferencesPerWh:
      return r.energy_per_inference_j && *r.energy_per_inference_j > 0 ? 3600 / *r.energy_per_inference_j : nan;
    case InferenceColumn::FlopsPerImage:
      return per_image / 1e9;
    default:
      return nan;
  }
}

int inference_better(InferenceColumn c) {
  switch (c) {
    case InferenceColumn::TimePerImage:
    case InferenceColumn::EnergyPerInference:
      return -1;
    case InferenceColumn::InferencesPerS:
    case InferenceColumn::Gflops:
    case InferenceColumn::OfCeiling:
    case InferenceColumn::InferencesPerWh:
      return +1;
    default:
      return 0;
  }
}

ExportTable inference_table(std::span<const DnnRun> runs) {
  ExportTable t;
  t.caption = "Detection network inference (per image; warm-up excluded)";
  t.label = "tab:inference";
  t.header = {"Platform",
              "Network",
              "Input (px, batch)",
              "Target (device)",
              "Time per image (ms)",
              "Inferences per s",
              "Achieved GFLOPS",
              "Of device FP32 ceiling",
              "Energy per inference (J)",
              "Inferences per Wh",
              "GFLOPs per image"};
  t.align = "lllllrrrrrr";
  for (const DnnRun& r : runs) {
    const double b = r.batch > 0 ? r.batch : 1;
    t.rows.push_back(
        {r.platform, inference_network_text(r),
         std::to_string(r.input_width) + "x" + std::to_string(r.input_height) + ", " + std::to_string(r.batch),
         r.backend + " (" + r.device + ")",
         format_mean_sd(r.forward.mean_s * 1e3 / b, r.forward.sd_s * 1e3 / b, r.forward.n, "", 2),
         num(inference_value(r, InferenceColumn::InferencesPerS), "%.2f"),
         num(inference_value(r, InferenceColumn::Gflops), "%.2f"),
         num(inference_value(r, InferenceColumn::OfCeiling), "%.1f %%"),
         num(inference_value(r, InferenceColumn::EnergyPerInference), "%.4f"),
         num(inference_value(r, InferenceColumn::InferencesPerWh), "%.0f"),
         num(inference_value(r, InferenceColumn::FlopsPerImage), "%.2f")});
  }
  if (!runs.empty())
    t.notes.push_back(
        "Time per image: one forward pass of the batch / batch size, mean ± SD (n passes). GFLOPs "
        "count 2 per multiply-add, grouped convolutions per group. Energy: the computer's power during "
        "the timed passes / inferences. Rows marked '" +
        std::string(kArchitectureTimingLabel) +
        "' time a standard architecture with random weights: its cost, not its detections.");
  return t;
}

}  // namespace bs
