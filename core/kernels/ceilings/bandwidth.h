// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Memory bandwidth with the STREAM triad (a = b + q c): the roofline's memory ceiling for a device. Stored as a
// result set (source "benchscope-bandwidth", metric "bandwidth" in B/s, one value per repetition) beside the runs.
#include <cstddef>

#include "kernels/backends/backend.h"
#include "kernels/cpu/cpu_info.h"
#include "model/flops_run.h"

namespace bs::kernels {

inline constexpr const char* kBandwidthSource = "benchscope-bandwidth";
inline constexpr const char* kBandwidthMetric = "bandwidth";
// Bytes moved and flops done per triad element (float): read b and c, write a; one multiply and one add.
inline constexpr double kTriadBytesPerElement = 12.0;
inline constexpr double kTriadFlopsPerElement = 2.0;

struct BandwidthSpec {
  std::size_t mib_per_array = 128;  // three arrays; far beyond any cache so the triad streams from memory
  int repeats = 10;
};

// Runs the backend's triad `repeats` times; throws std::invalid_argument when the backend has none, Cancelled.
ResultSet measure_bandwidth(const Backend& backend, const CpuInfo& cpu, const BandwidthSpec& spec,
                            const CancelToken& cancel, const ProgressFn& progress = {});

}  // namespace bs::kernels
