// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/roofline/roofline.h"

#include <algorithm>

#include "analysis/peaks/ceiling_check.h"
#include "analysis/peaks/flops.h"
#include "analysis/peaks/peak_ceilings.h"
#include "model/measure_class.h"

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
  if (c.empirical_flops && *c.empirical_flops > 0) {
    const double roof =
        c.bandwidth_bps ? std::min(*c.empirical_flops, p.intensity * *c.bandwidth_bps) : *c.empirical_flops;
    if (roof > 0) p.fraction_of_empirical = p.flops / roof;
  }
  return p;
}

double rotation_intensity(int dims, std::int64_t iterations) {
  return 6.0 * dims * static_cast<double>(iterations) / (16.0 * dims + 4.0);
}

std::vector<RooflineCeiling> roofline_ceilings(std::span<const FlopsRun> runs, std::span<const ResultSet> sets) {
  std::vector<RooflineCeiling> out;
  const auto find = [&](const std::string& platform, const std::string& device) -> RooflineCeiling& {
    for (auto& c : out)
      if (c.platform == platform && c.device == device) return c;
    RooflineCeiling c;
    c.platform = platform;
    c.device = device;
    out.push_back(std::move(c));
    return out.back();
  };
  for (const PeakRow& row : peak_table(runs)) {
    RooflineCeiling& c = find(row.platform, row.device);
    if (row.device_kind != DeviceKind::Other) c.kind = row.device_kind;
    if (row.theoretical_flops && *row.theoretical_flops > c.peak_flops) {
      c.peak_flops = *row.theoretical_flops;
      c.peak_source = "theoretical peak (" + row.backend + ")";
    } else if (c.peak_source.rfind("theoretical", 0) != 0 && row.peak.flops > c.peak_flops) {
      c.peak_flops = row.peak.flops;
      c.peak_source = "measured peak of " + row.backend +
                      (row.dims > 0 ? ", D = " + std::to_string(row.dims) : " (" + row.variant + ")");
    }
  }
  for (const ResultSet& s : sets)
    for (const Measurement& m : s.measurements) {
      // Only device-memory bandwidth is the memory ceiling: clpeak's transfer (PCIe), local-memory and image
      // bandwidths are other roofs, and their "best" can be a map call clpeak times as 1e6 GB/s.
      if (m.unit != "B/s" || m.values.empty() || classify_measurement(m).kind != MeasureKind::MemoryBandwidth) continue;
      const double best = *std::max_element(m.values.begin(), m.values.end());
      RooflineCeiling& c = find(s.platform, s.device);
      if (!c.bandwidth_bps || best > *c.bandwidth_bps) {
        c.bandwidth_bps = best;
        c.bandwidth_source = m.name + " (" + s.backend + ", best of " + std::to_string(m.values.size()) + ")";
      }
    }
  std::erase_if(out, [](const RooflineCeiling& c) { return c.peak_flops <= 0; });
  const std::vector<EmpiricalCeiling> empirical = empirical_ceilings(sets);
  for (RooflineCeiling& c : out)
    if (const EmpiricalCeiling* e = ceiling_for(empirical, c.platform, c.device, {})) {
      c.empirical_flops = e->flops.mean;
      c.empirical_source = e->how;
      // A measured mix above the computed peak is flagged with the reason, never drawn silently above it.
      if (c.peak_source.rfind("theoretical", 0) == 0)
        c.flags =
            compare_to_ceilings(e->flops.mean, c.peak_flops, std::nullopt, "The rotation-mix ceiling", e->how).flags;
    }
  return out;
}

}  // namespace bs
