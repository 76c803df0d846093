// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The roofline model (Williams, Waterman, Patterson 2009): attainable FLOP/s = min(peak, intensity x bandwidth).
// Ceilings come from a device's stated or measured peak and its measured memory bandwidth (STREAM triad from
// `run bandwidth`, or clpeak's global memory bandwidth); kernels are placed by arithmetic intensity (FLOP/byte)
// and measured throughput.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "analysis/peaks/plausibility.h"
#include "model/flops_run.h"

namespace bs {

struct RooflineCeiling {
  std::string platform, device;
  double peak_flops = 0;                // compute ceiling, FLOP/s
  std::string peak_source;              // "theoretical", "measured peak of <backend>", ...
  std::optional<double> bandwidth_bps;  // memory ceiling, B/s (best repetition)
  std::string bandwidth_source;
  DeviceKind kind = DeviceKind::Other;  // of the device's FLOPS runs
  // The rotation kernel's instruction mix measured on the device (analysis/peak_ceilings.h), when stored, and the
  // flags of comparing it with the computed peak (above it: the model understates the core).
  std::optional<double> empirical_flops;
  std::string empirical_source;
  std::vector<PlausibilityFlag> flags;
  double attainable(double intensity) const;      // min(peak, I x bandwidth); peak when the bandwidth is unknown
  std::optional<double> ridge_intensity() const;  // peak / bandwidth: where memory-bound turns compute-bound
};

struct RooflinePoint {
  std::string label;
  double intensity = 0;                         // FLOP/byte
  double flops = 0;                             // achieved FLOP/s
  double attainable = 0;                        // the roof above it
  double fraction = 0;                          // flops / attainable
  bool memory_bound = false;                    // left of the ridge
  std::optional<double> fraction_of_empirical;  // flops / min(empirical ceiling, intensity x bandwidth)
};

// Place a kernel that did `flop_count` operations moving `bytes` in `seconds`.
RooflinePoint place_on_roofline(const RooflineCeiling& ceiling, std::string label, double flop_count, double bytes,
                                double seconds);

// The rotation kernel's intensity: 6 D N flops per worker against its D points read and written once (2 floats
// each way) and one float output: 6DN / (16D + 4) FLOP/byte.
double rotation_intensity(int dims, std::int64_t iterations);

// The preprocessing stages (demosaic, reprojection, fused) have their own op/byte model: stage_roofline.h.

// One ceiling per (platform, device): the highest theoretical peak of its runs (else its measured peak) and the
// best bandwidth among its result-set measurements in B/s.
std::vector<RooflineCeiling> roofline_ceilings(std::span<const FlopsRun> runs, std::span<const ResultSet> sets);

}  // namespace bs
