// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/roofline.h"

#include <algorithm>

#include "analysis/flops.h"

namespace bs {

double RooflineCeiling::attainable(double intensity) const {
  return bandwidth_bps ? std::min(peak_flops, intensity * *bandwidth_bps) : peak_flops;
}

std::optional<double> RooflineCeiling::ridge_intensity() const {
  if (!bandwidth_bps || *bandwidth_bps <= 0) return std::nullopt;
  return peak_flops / *bandwidth_bps;
}

RooflinePoint place_on_roofline(const RooflineCeiling& c, std::string label, double flop_count, double bytes,
                                double seconds) {
  RooflinePoint p;
  p.label = std::move(label);
  p.intensity = bytes > 0 ? flop_count / bytes : 0;
  p.flops = seconds > 0 ? flop_count / seconds : 0;
  p.attainable = c.attainable(p.intensity);
  p.fraction = p.attainable > 0 ? p.flops / p.attainable : 0;
  const auto ridge = c.ridge_intensity();
  p.memory_bound = ridge && p.intensity < *ridge;
  return p;
}

double rotation_intensity(int dims, std::int64_t iterations) {
  return 6.0 * dims * static_cast<double>(iterations) / (16.0 * dims + 4.0);
}

const std::vector<StageCost>& preprocessing_stage_costs() {
  // Demosaic (bilinear, core/vision/bayer.cpp): per pixel two missing channels, each the mean of 2 or 4
  // neighbours (up to 3 adds + 1 scale) = 8 ops; reads 1 byte (neighbours come from cache), writes 3.
  // Reprojection (core/vision/reproject): per output pixel the LUT entry (2 floats = 8 bytes), 4 source pixels
  // (4 x 3 bytes), 3 bytes written; weights 4 ops, 3 channels x 3 lerps x 3 ops = 27, total 31.
  static const std::vector<StageCost> costs{{"demosaic (bilinear)", 8.0, 4.0}, {"reprojection (bilinear, LUT)", 31.0, 23.0}};
  return costs;
}

std::vector<RooflineCeiling> roofline_ceilings(std::span<const FlopsRun> runs, std::span<const ResultSet> sets) {
  std::vector<RooflineCeiling> out;
  const auto find = [&](const std::string& platform, const std::string& device) -> RooflineCeiling& {
    for (auto& c : out)
      if (c.platform == platform && c.device == device) return c;
    out.push_back({platform, device, 0, {}, std::nullopt, {}});
    return out.back();
  };
  for (const PeakRow& row : peak_table(runs)) {
    RooflineCeiling& c = find(row.platform, row.device);
    if (row.theoretical_flops && *row.theoretical_flops > c.peak_flops) {
      c.peak_flops = *row.theoretical_flops;
      c.peak_source = "theoretical peak (" + row.backend + ")";
    } else if (c.peak_source.rfind("theoretical", 0) != 0 && row.peak.flops > c.peak_flops) {
      c.peak_flops = row.peak.flops;
      c.peak_source = "measured peak of " + row.backend + ", D = " + std::to_string(row.dims);
    }
  }
  for (const ResultSet& s : sets)
    for (const Measurement& m : s.measurements) {
      if (m.unit != "B/s" || m.values.empty()) continue;
      const double best = *std::max_element(m.values.begin(), m.values.end());
      RooflineCeiling& c = find(s.platform, s.device);
      if (!c.bandwidth_bps || best > *c.bandwidth_bps) {
        c.bandwidth_bps = best;
        c.bandwidth_source = m.name + " (" + s.backend + ", best of " + std::to_string(m.values.size()) + ")";
      }
    }
  std::erase_if(out, [](const RooflineCeiling& c) { return c.peak_flops <= 0; });
  return out;
}

}  // namespace bs
