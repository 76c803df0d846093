// SPDX-License-Identifier: GPL-3.0-or-later
#include "kernels/ceilings/bandwidth.h"
#include "util/host_clock.h"

#include <stdexcept>
#include <string>

namespace bs::kernels {

ResultSet measure_bandwidth(const Backend& backend, const CpuInfo& cpu, const BandwidthSpec& spec,
                            const CancelToken& cancel, const ProgressFn& progress) {
  if (!backend.run_triad) throw std::invalid_argument(backend.id + " has no bandwidth kernel");
  if (spec.repeats < 1 || spec.repeats > 1000) throw std::invalid_argument("repeats must be 1 to 1000");
  if (spec.mib_per_array < 1 || spec.mib_per_array > 16384)
    throw std::invalid_argument("MiB per array must be 1 to 16384");
  const std::size_t elements = spec.mib_per_array * (std::size_t{1} << 20) / sizeof(float);
  ResultSet set;
  set.platform = bs::host_name();
  set.device = backend.device_name;
  set.device_kind = backend.kind;
  set.backend = backend.label;
  set.source_format = kBandwidthSource;
  set.provenance = measured_provenance(cpu, backend);
  Measurement m;
  m.name = "stream-triad/" + std::to_string(spec.mib_per_array) + "MiB";
  m.metric = kBandwidthMetric;
  m.unit = "B/s";
  for (int r = 0; r < spec.repeats; ++r) {
    if (progress) progress(static_cast<double>(r) / spec.repeats, "triad " + std::to_string(r + 1));
    cancel.throw_if_cancelled();
    const double seconds = backend.run_triad(elements, cancel);
    m.values.push_back(kTriadBytesPerElement * static_cast<double>(elements) / seconds);
  }
  if (progress) progress(1.0, "done");
  set.measurements.push_back(std::move(m));
  return set;
}

}  // namespace bs::kernels
