// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/pipeline/pipeline_measure.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "util/host_clock.h"
#include "vision/frames/synthetic.h"
#include "vision/pipeline/detector.h"
#include "vision/pipeline/dnn_architectures.h"
#include "vision/pipeline/pipeline_record.h"
#include "vision/pipeline/threads.h"
#include "vision/reproject/cuda_preprocess.h"
#include "vision/reproject/opencl_preprocess.h"
#include "vision/reproject/preprocess.h"

namespace bs::vision {

bool detector_is_model_file(const std::string& detector) {
  return detector != "hog" && detector != "none" && !architecture_from_string(detector);
}

cv::Mat synthetic_paper_capture() { return mosaic(render_fisheye(Lens::paper()), BayerPattern::BGGR); }

std::optional<PipelineRun> measure_synthetic_pipeline(const SyntheticPipelineOptions& o, const CancelToken& cancel,
                                                      const ProgressFn& progress, PipelineResult* result_out) {
  if (o.frames < 1 || o.frames > 1000000) throw std::invalid_argument("frames must be between 1 and 1,000,000");
  std::string detector_name = o.detector;
  Detector detector;
  if (o.detector == "none") {
    if (!(o.detect_scale > 0 && o.detect_scale <= 1)) throw std::invalid_argument("detect scale must be in (0, 1]");
  } else if (o.detector == "hog") {
    detector = hog_people_detector(o.detect_scale);  // validates the scale
  } else if (const auto arch = architecture_from_string(o.detector)) {
    detector = scaled_detector(architecture_timing_detector(*arch), o.detect_scale);
    detector_name = architecture_detector_name(*arch);
  } else {
    DnnOptions d;
    const auto comma = o.detector.find(',');
    d.model = o.detector.substr(0, comma);
    if (comma != std::string::npos) d.config = o.detector.substr(comma + 1);
    detector = scaled_detector(dnn_detector(d), o.detect_scale);
    detector_name = std::filesystem::path(d.model).filename().string();
  }
  const Lens lens = Lens::paper();
  const View view;
  const cv::Mat raw = synthetic_paper_capture();
  std::string preprocess_device = "CPU (" + std::to_string(opencv_threads()) + " threads)";
  Preprocessor preprocess;
  if (o.backend == "cpu") {
    preprocess = make_preprocessor(lens, view, BayerPattern::BGGR, DemosaicMethod::Bilinear, PreprocessPath::Fused);
  } else if (o.backend == "opencl") {
    OpenClPreprocessorInfo info;
    preprocess = make_opencl_preprocessor(lens, view, BayerPattern::BGGR, &info);
    preprocess_device = info.device + " (OpenCL) preprocessing, CPU detection";
  } else if (o.backend == "cuda") {
    CudaPreprocessorInfo info;
    preprocess = make_cuda_preprocessor(lens, view, BayerPattern::BGGR, &info);
    preprocess_device = info.device + " (CUDA) preprocessing, CPU detection";
  } else {
    throw std::invalid_argument("backend must be cpu, opencl or cuda (got '" + o.backend + "')");
  }
  const FrameSource source = [&](std::size_t i) -> std::optional<cv::Mat> {
    if (i >= o.frames) return std::nullopt;
    if (progress) progress(static_cast<double>(i + 1) / static_cast<double>(o.frames), "capturing");
    return raw;
  };
  PipelineConfig config;
  config.max_frames = o.frames;
  config.detection_workers = o.detection_workers;  // run_pipeline validates it
  const PipelineResult result = run_pipeline(source, preprocess, detector, config, cancel);
  if (result_out) *result_out = result;
  if (result.cancelled) return std::nullopt;

  PipelineRun run = measured_pipeline_run(result, lens);
  run.platform = bs::host_name();
  run.device = preprocess_device;
  if (detector)
    run.device +=
        ", " + std::to_string(o.detection_workers) + " detection worker" + (o.detection_workers == 1 ? "" : "s");
  run.backend = o.backend;
  // The OpenCL path demosaics the whole frame, then reprojects; the CPU and CUDA paths are fused.
  run.demosaic = o.backend == "opencl" ? "bilinear" : "fused";
  run.detector = detector_name;
  run.provenance.tool = o.tool;
  char scale[32];
  std::snprintf(scale, sizeof scale, "%g", o.detect_scale);
  run.provenance.note =
      "synthetic paper capture (test chart, 195 deg lens), " + std::to_string(o.frames) +
      " frames, 1280x1024 150 deg view, policy block, queue 2, " +
      (detector ? std::to_string(o.detection_workers) + " detection workers, detect scale " + scale + ", "
                : std::string()) +
      "preprocessing on " + o.backend + ", detector " + detector_name;
  return run;
}

}  // namespace bs::vision
