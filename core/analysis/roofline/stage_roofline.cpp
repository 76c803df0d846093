// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/roofline/stage_roofline.h"

#include <algorithm>
#include <stdexcept>

#include "util/enum_words.h"

namespace bs {
namespace {

// Derivation of the per-site counts in PixelOps (core/vision/demosaic/bayer_pixel.h, demosaic_pixel, the scalar
// definition that the SIMD path equals; the counts are of that definition, not of the vector code):
//  bilinear, green site:   (w + e + 1) >> 1 and (n + s + 1) >> 1: 2 adds + 1 shift each            = 6
//  bilinear, red/blue:     (n + s + w + e + 2) >> 2 and the 4 diagonals + 2 >> 2: 4 adds + 1 shift = 10
//  MHC, both sites:        n2 = N2 + S2, w2 = W2 + E2 (2 adds), d = the 4 diagonals (3 adds)        = 5, then
//   green site:  (10 v + 8 (w + e) - 2 d - 2 w2 + n2 + 8) >> 4: 4 mul, 6 add/sub, 1 shift = 11, twice = 22 -> 27
//   red/blue:    (4 v + 2 (n + s + w + e) - n2 - w2 + 4) >> 3: 2 mul, 7 add/sub, 1 shift              = 10
//                (12 v + 4 d - 3 (n2 + w2) + 8) >> 4: 3 mul, 4 add/sub, 1 shift                        = 8  -> 23
// A Bayer cell has 2 green and 2 red/blue sites, so the mean per pixel is the mean of the two.
constexpr double cell_mean(double green, double red_blue) { return (2 * green + 2 * red_blue) / 4; }

constexpr double kMosaicByte = 1;  // 8-bit mosaic
constexpr double kRgbBytes = 3;    // 8-bit BGR
// ReprojectionLut::apply: cv::convertMaps' CV_16SC2 (x, y) + CV_16UC1 fraction index per output pixel.
constexpr double kRemapLutBytes = 4 + 2;
// FusedTable's scalar entry (int32 offset + 3 bytes, padded to 8). The AVX-512 kernel reads 4 bytes per pixel
// plus an 8-byte block record per 16 pixels (4.5 B); the scalar size is used, the kernel a run took is not stored.
constexpr double kFusedLutBytes = 8;

}  // namespace

std::string stage_kernel_name(StageKernel k) {
  constexpr EnumWord<StageKernel> kNames[] = {{StageKernel::DemosaicBilinear, "demosaic (bilinear)"},
                                              {StageKernel::DemosaicMhc, "demosaic (Malvar-He-Cutler)"},
                                              {StageKernel::Reprojection, "reprojection (bilinear, fixed-point LUT)"},
                                              {StageKernel::Fused, "fused demosaic + reprojection"}};
  static_assert(names_every_value(kNames, StageKernel::Fused));
  return std::string(word_of(kNames, k, "?"));
}

KernelCost kernel_cost(StageKernel k) {
  switch (k) {
    case StageKernel::DemosaicBilinear:
      return {k, cell_mean(PixelOps::kBilinearGreenSite, PixelOps::kBilinearRedBlueSite), kMosaicByte + kRgbBytes,
              "per mosaic pixel: green site 6, red/blue site 10 integer ops (adds + shifts), cell mean 8",
              "per mosaic pixel: 1 B mosaic read (neighbour rows cached), 3 B RGB written"};
    case StageKernel::DemosaicMhc:
      return {k, cell_mean(PixelOps::kMhcGreenSite, PixelOps::kMhcRedBlueSite), kMosaicByte + kRgbBytes,
              "per mosaic pixel: green site 27, red/blue site 23 integer ops (adds, multiplies, shifts), cell mean 25",
              "per mosaic pixel: 1 B mosaic read (5 neighbour rows cached), 3 B RGB written"};
    case StageKernel::Reprojection:
      return {k, 3 * PixelOps::kRemapBilinearPerChannel, kRemapLutBytes + kRgbBytes,
              "per output pixel: 3 channels x (4 mul + 3 add + rounding add + shift) = 27 integer ops",
              "per output pixel: 6 B LUT (int16 x, y + uint16 fraction) read, 3 B RGB written; plus the RGB source "
              "read once (3 B per source pixel)"};
    case StageKernel::Fused:
      return {k,
              PixelOps::kFusedWeights + 2 * PixelOps::kFusedGreenTap + 2 * PixelOps::kFusedRedBlueTap +
                  3 * PixelOps::kFusedBlendPerChannel,
              kFusedLutBytes + kRgbBytes,
              "per output pixel: weights 2 + four taps' demosaic 2 x 5 + 2 x 7 + blend 3 x 11 = 59 integer ops",
              "per output pixel: 8 B table entry read, 3 B RGB written; plus the mosaic read once (1 B per source "
              "pixel); no RGB intermediate"};
  }
  throw std::invalid_argument("unknown stage kernel");
}

StageCost stage_cost(std::span<const StageKernel> kernels, const FrameGeometry& g) {
  if (kernels.empty()) throw std::invalid_argument("a stage needs at least one kernel");
  if (g.source_width <= 0 || g.source_height <= 0 || g.output_width <= 0 || g.output_height <= 0)
    throw std::invalid_argument("frame geometry must be positive");
  StageCost c;
  c.kernels.assign(kernels.begin(), kernels.end());
  for (StageKernel k : kernels) {
    const KernelCost kc = kernel_cost(k);
    c.label += (c.label.empty() ? "" : " + ") + stage_kernel_name(k);
    switch (k) {
      case StageKernel::DemosaicBilinear:
      case StageKernel::DemosaicMhc:
        c.ops += kc.ops_per_pixel * g.source_pixels();
        c.bytes += kc.bytes_per_pixel * g.source_pixels();
        break;
      case StageKernel::Reprojection:
        c.ops += kc.ops_per_pixel * g.output_pixels();
        c.bytes += kc.bytes_per_pixel * g.output_pixels() + kRgbBytes * g.source_pixels();
        break;
      case StageKernel::Fused:
        c.ops += kc.ops_per_pixel * g.output_pixels();
        c.bytes += kc.bytes_per_pixel * g.output_pixels() + kMosaicByte * g.source_pixels();
        break;
    }
  }
  c.ops_per_output_pixel = c.ops / g.output_pixels();
  c.bytes_per_output_pixel = c.bytes / g.output_pixels();
  return c;
}

std::optional<std::vector<StageKernel>> preprocessing_kernels(const std::string& demosaic) {
  if (demosaic == "fused") return std::vector<StageKernel>{StageKernel::Fused};
  if (demosaic.empty() || demosaic == "bilinear" || demosaic == "opencv")
    return std::vector<StageKernel>{StageKernel::DemosaicBilinear, StageKernel::Reprojection};
  if (demosaic == "mhc") return std::vector<StageKernel>{StageKernel::DemosaicMhc, StageKernel::Reprojection};
  return std::nullopt;
}

namespace {

const RooflineCeiling* ceiling_for(std::span<const RooflineCeiling> ceilings, const PipelineRun& run) {
  const RooflineCeiling* best = nullptr;
  for (const RooflineCeiling& c : ceilings)
    if (c.platform == run.platform && !c.device.empty() && run.device.find(c.device) != std::string::npos &&
        (!best || c.device.size() > best->device.size()))
      best = &c;
  if (best) return best;
  const DeviceKind kind = run.backend == "cpu"                               ? DeviceKind::Cpu
                          : run.backend == "opencl" || run.backend == "cuda" ? DeviceKind::Gpu
                                                                             : DeviceKind::Other;
  if (kind == DeviceKind::Other) return nullptr;
  for (const RooflineCeiling& c : ceilings) {
    if (c.platform != run.platform || c.kind != kind) continue;
    if (best) return nullptr;  // ambiguous
    best = &c;
  }
  return best;
}

}  // namespace

StagePlacements place_preprocessing(std::span<const RooflineCeiling> ceilings, std::span<const PipelineRun> runs) {
  StagePlacements out;
  for (const PipelineRun& run : runs) {
    const StageStats* stage = run.stage(pipeline_stage::kPreprocess);
    if (!stage || !(stage->mean_s > 0)) continue;
    const std::string who = run.platform + " (" + (run.backend.empty() ? "?" : run.backend) + ")";
    if (run.frame_width <= 0 || run.frame_height <= 0) {
      out.skipped.push_back(who + ": the run does not say its frame size");
      continue;
    }
    const auto kernels = preprocessing_kernels(run.demosaic);
    if (!kernels) {
      out.skipped.push_back(who + ": no operation model for demosaic '" + run.demosaic + "'");
      continue;
    }
    const RooflineCeiling* c = ceiling_for(ceilings, run);
    if (!c) {
      out.skipped.push_back(who + ": no roofline ceiling (FLOPS run) for its device '" + run.device + "'");
      continue;
    }
    StagePlacement p;
    p.platform = c->platform;
    p.device = c->device;
    p.run_device = run.device;
    p.backend = run.backend;
    p.source = run.provenance.source_file.empty() ? run.provenance.note : run.provenance.source_file;
    p.origin = run.provenance.origin;
    // The pipeline record keeps the camera frame only; the view is taken to be the same size (the paper's
    // 1280x1024 in and out, and `benchscope-cli pipeline`'s default view).
    p.geometry = {run.frame_width, run.frame_height, run.frame_width, run.frame_height};
    p.geometry_assumed = true;
    p.cost = stage_cost(*kernels, p.geometry);
    p.time = *stage;
    p.point = place_on_roofline(*c, run.platform + " preprocessing", p.cost.ops, p.cost.bytes, stage->mean_s);
    p.memory_ceiling_known = c->bandwidth_bps.has_value();
    p.ops_per_s_low = p.cost.ops / (stage->mean_s + stage->sd_s);
    if (stage->mean_s - stage->sd_s > 0) p.ops_per_s_high = p.cost.ops / (stage->mean_s - stage->sd_s);
    out.placed.push_back(std::move(p));
  }
  return out;
}

}  // namespace bs
