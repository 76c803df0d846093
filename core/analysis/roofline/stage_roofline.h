// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The preprocessing stages (demosaic, reprojection, and the fused demosaic + reprojection) on the roofline: an
// operation and DRAM-byte model per pixel counted in BenchScope's own source, applied to a frame geometry, and
// the measured stage times of stored pipeline runs turned into achieved operations per second and placed under
// each platform's ceiling.
//
// Operations: every integer add, subtract, multiply and shift of the per-pixel arithmetic counts as one op (the
// kernels are integer code: there are no floating-point operations in them, so "FLOP" on the roofline means
// "arithmetic op" for these points). Not counted: clamps/saturation, loads/stores, address arithmetic and loop
// control.
// Bytes: compulsory DRAM traffic of one frame, assuming the caches catch all reuse between neighbouring pixels:
// every mosaic, RGB and LUT byte is read once, every output byte written once; no write-allocate reads (a
// write-allocate cache adds the output's bytes once more as reads). This is a lower bound on traffic, so the
// intensity is an upper bound.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "analysis/roofline/roofline.h"
#include "model/pipeline_run.h"

namespace bs {

// Ops of one pixel of each kernel, as implemented (see stage_roofline.cpp for the derivation, line by line).
struct PixelOps {
  // core/vision/demosaic/bayer_pixel.h demosaic_pixel, 8-bit mosaic; mean over a 2x2 Bayer cell (2 green, 1 red, 1 blue
  // site).
  static constexpr double kBilinearGreenSite = 6, kBilinearRedBlueSite = 10;
  static constexpr double kMhcGreenSite = 27, kMhcRedBlueSite = 23;
  // OpenCV remap, INTER_LINEAR with the fixed-point map (ReprojectionLut::apply): per channel 4 multiplies, 3
  // adds, the rounding add and the shift; 3 channels. The weights come from a table indexed by the fraction.
  static constexpr double kRemapBilinearPerChannel = 9;
  // core/vision/reproject/fused.cpp quad<L>: the two complementary weights (2), the four taps' demosaic times 4 (a
  // green tap 5, a red/blue tap 7; a 2x2 quad has two of each: 24), the blend per channel (2 x (2 mul + 1 add) for the
  // rows, 2 mul + 2 add + 1 shift for the columns: 11; 3 channels: 33).
  static constexpr double kFusedWeights = 2, kFusedGreenTap = 5, kFusedRedBlueTap = 7, kFusedBlendPerChannel = 11;
};

enum class StageKernel { DemosaicBilinear, DemosaicMhc, Reprojection, Fused };
std::string stage_kernel_name(StageKernel k);

// Ops and DRAM bytes per pixel of one kernel: per source (mosaic) pixel for the demosaics, per output pixel for
// the reprojection and the fused path (their source reads are spread over the output pixels by the geometry).
struct KernelCost {
  StageKernel kernel;
  double ops_per_pixel = 0;
  double bytes_per_pixel = 0;  // not counting source reads that depend on the geometry (reprojection, fused)
  std::string ops_note, bytes_note;
};
KernelCost kernel_cost(StageKernel k);

struct FrameGeometry {
  int source_width = 0, source_height = 0;  // the camera's mosaic
  int output_width = 0, output_height = 0;  // the reprojected view
  double source_pixels() const { return static_cast<double>(source_width) * source_height; }
  double output_pixels() const { return static_cast<double>(output_width) * output_height; }
};

// Ops and bytes of one frame through a sequence of kernels (a stage = one or more kernels timed together).
struct StageCost {
  std::string label;  // "demosaic (bilinear) + reprojection (bilinear, fixed-point LUT)"
  std::vector<StageKernel> kernels;
  double ops = 0, bytes = 0;  // per frame
  double intensity() const { return bytes > 0 ? ops / bytes : 0; }
  double ops_per_output_pixel = 0, bytes_per_output_pixel = 0;
};
// Throws std::invalid_argument for an empty geometry or kernel list.
StageCost stage_cost(std::span<const StageKernel> kernels, const FrameGeometry& g);

// The kernels a pipeline run's preprocessing stage ran, from its `demosaic` field: "fused" -> the fused kernel;
// "bilinear"/"opencv" -> bilinear demosaic then reprojection; "mhc" -> MHC then reprojection; empty (unknown,
// e.g. the paper's runs: the paper describes a bilinear demosaic followed by the reprojection) -> bilinear then
// reprojection. nullopt for demosaics without an op model (OpenCV's edge-aware and VNG).
std::optional<std::vector<StageKernel>> preprocessing_kernels(const std::string& demosaic);

// One pipeline run's preprocessing stage placed on a ceiling.
struct StagePlacement {
  std::string platform, device;     // of the ceiling it sits under
  std::string run_device, backend;  // what the run says ran it
  std::string source;               // the run's file, or its note when stored in-process
  DataOrigin origin = DataOrigin::Unknown;
  StageCost cost;
  FrameGeometry geometry;
  bool geometry_assumed = false;      // output view size unknown: taken equal to the camera frame (the paper's case)
  StageStats time;                    // the measured stage (seconds)
  RooflinePoint point;                // achieved ops/s = cost.ops / time.mean_s
  bool memory_ceiling_known = false;  // the device has a measured bandwidth (else the roof is its peak alone)
  std::optional<double> ops_per_s_low, ops_per_s_high;  // at mean + SD and mean - SD (when mean - SD > 0)
};

struct StagePlacements {
  std::vector<StagePlacement> placed;
  std::vector<std::string> skipped;  // "Jetson TX2 (cuda): no roofline ceiling for its device", ...
};

// Places the preprocessing stage of every run that has one: under the ceiling of the same platform whose device
// name the run's device names (longest match), else the platform's only ceiling of the kind the backend implies
// ("cpu" -> a CPU, "opencl"/"cuda" -> a GPU). Runs without a frame size, a known kernel model or a ceiling are
// listed in `skipped` with the reason.
StagePlacements place_preprocessing(std::span<const RooflineCeiling> ceilings, std::span<const PipelineRun> runs);

}  // namespace bs
