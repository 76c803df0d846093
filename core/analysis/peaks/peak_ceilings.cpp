// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/peaks/peak_ceilings.h"

#include "analysis/peaks/ceiling_check.h"
#include "analysis/stats/stats.h"

namespace bs {

std::vector<EmpiricalCeiling> empirical_ceilings(std::span<const ResultSet> sets) {
  std::vector<EmpiricalCeiling> out;
  for (const ResultSet& s : sets) {
    if (s.source_format != kCeilingSource) continue;
    for (const Measurement& m : s.measurements)
      if (m.metric == kRotationMixMetric && m.unit == "FLOP/s" && !m.values.empty())
        out.push_back({s.platform, s.device, s.backend, summarize(m.values),
                       "rotation mix, measured " + s.provenance.date + " (" + m.name + ")"});
  }
  return out;
}

const EmpiricalCeiling* ceiling_for(std::span<const EmpiricalCeiling> ceilings, const std::string& platform,
                                    const std::string& device, const std::string& backend) {
  const EmpiricalCeiling* same_backend = nullptr;
  const EmpiricalCeiling* highest = nullptr;
  for (const EmpiricalCeiling& c : ceilings) {
    if (c.platform != platform || c.device != device) continue;
    if (c.backend == backend) same_backend = &c;  // later entries are later measurements
    if (!highest || c.flops.mean > highest->flops.mean) highest = &c;
  }
  return same_backend ? same_backend : highest;
}

void apply_empirical_ceilings(std::vector<PeakRow>& rows, std::span<const ResultSet> sets) {
  const std::vector<EmpiricalCeiling> ceilings = empirical_ceilings(sets);
  for (PeakRow& row : rows) {
    const EmpiricalCeiling* c = ceiling_for(ceilings, row.platform, row.device, row.backend);
    std::optional<double> ceiling;
    if (c) {
      ceiling = c->flops.mean;
      row.empirical_ceiling_flops = c->flops.mean;
      row.ceiling_how = c->how;
    }
    const CeilingComparison cmp =
        compare_to_ceilings(row.peak.flops, row.theoretical_flops, ceiling, "The peak", c ? c->how : std::string());
    row.fraction_of_ceiling = cmp.fraction_of_ceiling;
    merge_flags(row.flags, cmp.flags);
  }
}

}  // namespace bs
