// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli pipeline: runs the paper's vision pipeline (capture -> demosaic + reprojection -> detection, one
// thread each for capture and preprocessing, --detect-workers threads for detection) on frame files, prints per-stage
// timings, writes the figure-3 images and can store the run.

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "analysis/power/phase_energy.h"
#include "commands/pipeline_grammar.h"
#include "common/args.h"
#include "common/command.h"
#include "common/signals.h"
#include "common/text_table.h"
#include "image_files/image_files.h"
#include "power/power_args.h"
#include "runs/pipeline_json.h"
#include "sensors/recording_csv.h"
#include "store/home_batch.h"
#include "store/workspace.h"
#include "util/host_clock.h"
#include "vision/frames/frame_file.h"
#include "vision/pipeline/detector.h"
#include "vision/pipeline/dnn_architectures.h"
#include "vision/pipeline/pipeline.h"
#include "vision/pipeline/pipeline_measure.h"
#include "vision/pipeline/pipeline_record.h"
#include "vision/pipeline/threads.h"
#include "vision/pipeline_home.h"
#include "vision/reproject/cuda_preprocess.h"
#include "vision/reproject/opencl_preprocess.h"
#include "vision/reproject/preprocess.h"

namespace bs::cli {
namespace {

using namespace bs::vision;

// A lens file (format benchscope-lens), or a raw frame's sidecar that carries one under "lens" (synth-frame
// writes that), or the word "paper" for the paper's camera.
// Energy of the pipeline from the on-board sensors: the whole run's energy per frame through the pipeline, and,
// as the Platforms view computes them, the mean power during the run x each stage's mean time (per
// preprocessed frame, per inference).
void print_pipeline_energy(std::ostream& out, const PowerTrace& trace, const PipelineRun& run, std::size_t frames) {
  print_phase_energies(out, trace);
  const auto energies = phase_energies(trace);
  if (energies.empty()) return;
  const PhaseEnergy& e = energies.front();
  char line[256];
  if (const auto per = joules_per_item(e, frames)) {
    std::snprintf(line, sizeof line, "energy per frame through the pipeline: %.4f J (%zu frames, %.3f J over %.3f s)\n",
                  *per, frames, e.energy_j, e.end_s - e.start_s);
    out << line;
  }
  if (const StageStats* pre = run.stage(pipeline_stage::kPreprocess)) {
    std::snprintf(line, sizeof line, "energy per preprocessed frame: %.4f J (mean %.3f W x %.3f ms)\n",
                  e.mean_power_w * pre->mean_s, e.mean_power_w, pre->mean_s * 1e3);
    out << line;
  }
  if (const StageStats* det = run.stage(pipeline_stage::kDetect)) {
    std::snprintf(line, sizeof line, "energy per inference: %.4f J (mean %.3f W x %.3f ms)\n",
                  e.mean_power_w * det->mean_s, e.mean_power_w, det->mean_s * 1e3);
    out << line;
  }
  out << "(" << to_string(trace.provenance.measurement) << ": " << trace.provenance.sensor << ")\n";
}

std::pair<Lens, View> load_lens(const std::string& arg) {
  if (arg == "paper") return {Lens::paper(), View{}};
  std::ifstream f(arg);
  if (!f) throw std::runtime_error(arg + ": cannot open lens file");
  const nlohmann::json j = nlohmann::json::parse(f, nullptr, false);
  if (j.is_discarded()) throw std::runtime_error(arg + ": lens file is not valid JSON");
  try {
    if (j.is_object() && j.contains("lens") && j["lens"].is_object() && j["lens"].contains("format"))
      return lens_from_json(j["lens"]);
    return lens_from_json(j);
  } catch (const std::exception& e) {
    throw std::runtime_error(arg + ": " + e.what());
  }
}

struct Demosaic {
  DemosaicMethod method;
  PreprocessPath path;
};

Demosaic demosaic_option(const std::string& s) {
  if (s == "fused") return {DemosaicMethod::Bilinear, PreprocessPath::Fused};
  if (s == "bilinear") return {DemosaicMethod::Bilinear, PreprocessPath::Separate};
  if (s == "mhc") return {DemosaicMethod::MalvarHeCutler, PreprocessPath::Separate};
  if (s == "opencv") return {DemosaicMethod::OpenCvBilinear, PreprocessPath::Separate};
  throw UsageError("--demosaic must be fused, bilinear, mhc or opencv (got '" + s + "')");
}

// --detector MODEL[,CONFIG]: a detection network cv::dnn reads (ONNX, Caffe .caffemodel + .prototxt, TensorFlow
// .pb + .pbtxt, Darknet .weights + .cfg) with SSD, YOLOv5 or YOLOv8 outputs; its files named before any frame runs.
DnnOptions model_files(const std::string& s) {
  DnnOptions o;
  const auto comma = s.find(',');
  o.model = s.substr(0, comma);
  if (comma != std::string::npos) o.config = s.substr(comma + 1);
  for (const std::string& file : {o.model, o.config})
    if (!file.empty() && !std::filesystem::is_regular_file(file))
      throw std::runtime_error(file +
                               ": no such model file (--detector takes hog, none, mobilenet-ssd, yolo-n or "
                               "MODEL[,CONFIG])");
  return o;
}

Detector detector_option(const std::string& s, double scale) {
  if (s == "none") return {};
  if (s == "hog") return hog_people_detector(scale);
  if (const auto arch = architecture_from_string(s)) return scaled_detector(architecture_timing_detector(*arch), scale);
  return scaled_detector(dnn_detector(model_files(s)), scale);
}

std::string scale_text(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", s);
  return b;
}

std::string ms(double seconds) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3f", seconds * 1e3);
  return b;
}

void print_table(const PipelineRun& run, const PipelineResult& r, std::ostream& out) {
  TextTable t({"stage", "n", "mean ± SD (ms)", "p50 (ms)", "p95 (ms)", "min (ms)", "max (ms)"});
  for (const StageStats& s : run.stages)
    t.add({s.stage, std::to_string(s.n), ms(s.mean_s) + " ± " + ms(s.sd_s), s.p50_s ? ms(*s.p50_s) : "–",
           s.p95_s ? ms(*s.p95_s) : "–", s.min_s ? ms(*s.min_s) : "–", s.max_s ? ms(*s.max_s) : "–"});
  t.print(out);
  char line[256];
  std::snprintf(line, sizeof line,
                "\nthroughput: %.2f fps (%zu frames processed in %.3f s; %zu captured, %zu dropped)\n",
                r.throughput_fps, r.processed, r.wall_s, r.captured, r.dropped);
  out << line;
  if (r.detection_workers > 0) {
    std::snprintf(line, sizeof line, "detection on %zu worker thread%s\n", r.detection_workers,
                  r.detection_workers == 1 ? "" : "s");
    out << line;
  }
  // The stages overlap on their threads; run one after another they would take the sum of their means.
  double sequential_s = 0;
  for (const StageStats& s : run.stages)
    if (s.stage != pipeline_stage::kEndToEnd) sequential_s += s.mean_s;
  if (sequential_s > 0 && r.throughput_fps > 0) {
    std::snprintf(line, sizeof line,
                  "stages in sequence would give %.2f fps (1 / sum of stage means as measured here, while the stages "
                  "shared the cores); concurrent / sequential = %.2fx (bench pipeline measures both)\n",
                  1.0 / sequential_s, r.throughput_fps * sequential_s);
    out << line;
  }
}

void write_figures(const std::string& dir, const FrameFile& frame, const cv::Mat& mosaic8, const Demosaic& d,
                   const Preprocessor& preprocess, const Detector& detector, std::ostream& out) {
  std::filesystem::create_directories(dir);
  const auto save = [&](const std::string& name, const cv::Mat& img) {
    const std::string path = (std::filesystem::path(dir) / name).string();
    if (!bs::image_files::write(path, img)) throw std::runtime_error(path + ": cannot write image");
    out << "wrote " << path << '\n';
  };
  // Figure 3 of the paper: the raw mosaic shown as grey | demosaiced | reprojected (here with the detections).
  save("fig3-raw.png", mosaic8);
  const DemosaicMethod shown = d.path == PreprocessPath::Fused ? DemosaicMethod::Bilinear : d.method;
  save("fig3-demosaiced.png", demosaic(mosaic8, frame.pattern, shown));
  const cv::Mat view = preprocess(mosaic8);
  save("fig3-reprojected.png", detector ? draw_detections(view, detector(view)) : view);
}

// The run's ending, shared by frame files and the synthetic capture: the power trace closed, the table or JSON
// printed, figure 3 written (frame files only), the run and its trace stored as one import.
int finish_run(const commands::PipelineSettings& settings, const PipelineRun& run, const PipelineResult& result,
               sensors::PowerRecorder* power, const std::function<void(std::ostream&)>& figures, std::ostream& out,
               std::ostream& err) {
  const std::string json_text = write_pipeline_json(run);
  std::optional<PowerTrace> trace;
  if (power) {
    power->end_phase();
    trace = power->finish("pipeline " + run.platform + " " + run.backend + " " + run.provenance.date);
    trace->platform = run.platform;  // the Platforms view pairs traces and runs by platform
  }
  // --json keeps stdout to the document alone; the rest goes where the command's messages go.
  std::ostream& info = settings.json ? err : out;
  if (settings.json)
    out << json_text;
  else
    print_table(run, result, out);
  if (trace) print_pipeline_energy(info, *trace, run, result.processed);
  if (figures) figures(info);
  if (const auto& ws_path = settings.workspace) {
    // With --power the trace goes into the same import as the run (stored and removed together).
    const std::int64_t id = bring_home(*ws_path, pipeline_home(run, trace, "benchscope-cli pipeline"));
    info << "stored the run in " << *ws_path << " (import " << id << ")\n";
  }
  return 0;
}

// pipeline --synthetic: the Pipeline tab's measurement (the paper camera's synthetic capture through the fused
// preprocessing and the detector), which a robot can run without any file from the desk.
int run_synthetic(const commands::PipelineSettings& settings, std::ostream& out, std::ostream& err) {
  vision::SyntheticPipelineOptions o;
  o.frames = settings.frames.value_or(20);
  o.detection_workers = settings.detect_workers.value_or(vision::default_detection_workers());
  o.detect_scale = settings.detect_scale;
  o.backend = settings.backend;
  o.detector = settings.detector;
  if (vision::detector_is_model_file(o.detector)) model_files(o.detector);
  o.tool = std::string("benchscope-cli ") + BENCHSCOPE_VERSION;
  const auto power = start_power(settings.power, err, settings.json);
  if (power) power->begin_phase("pipeline");
  // Progress at every tenth of the frames (a robot's desk shows these lines as they come).
  std::atomic<int> reported{0};
  const ProgressFn progress = [&](double f, std::string_view) {
    const int tenth = static_cast<int>(f * 10);
    if (tenth > reported.exchange(tenth))
      err << "captured " << static_cast<std::size_t>(f * static_cast<double>(o.frames) + 0.5) << " of " << o.frames
          << " frames\n"
          << std::flush;
  };
  PipelineResult result;
  std::optional<PipelineRun> run = vision::measure_synthetic_pipeline(o, interrupt_token(), progress, &result);
  if (!run) {
    err << "benchscope-cli: pipeline cancelled after " << result.processed << " frames; nothing stored\n";
    return 1;
  }
  run->platform = settings.platform.value_or(bs::host_name());
  run->provenance.compiler = BENCHSCOPE_COMPILER;
  return finish_run(settings, *run, result, power.get(), {}, out, err);
}

int run_pipeline_cmd(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err) {
  const commands::PipelineSettings settings = commands::pipeline_from_words(raw);
  if (settings.synthetic) return run_synthetic(settings, out, err);
  const std::string& lens_arg = *settings.lens;
  const std::string& backend = settings.backend;
  const std::string demosaic_name = settings.demosaic.value_or(backend == "opencl" ? "bilinear" : "fused");
  const Demosaic dm = demosaic_option(demosaic_name);
  const std::size_t frames_arg = settings.frames.value_or(50);
  const std::size_t queue = settings.queue.value_or(2);
  const std::string policy = settings.policy.value_or("block");
  const std::size_t detect_workers = settings.detect_workers.value_or(vision::default_detection_workers());
  const double detect_scale = settings.detect_scale;
  const BayerPattern default_pattern =
      settings.pattern ? bayer_pattern_from_string(*settings.pattern) : BayerPattern::BGGR;

  const auto [lens, view] = load_lens(lens_arg);
  std::vector<FrameFile> files;
  std::vector<cv::Mat> mosaics;
  for (const std::string& path : settings.frame_files) {
    files.push_back(read_frame_file(path, default_pattern));
    const FrameFile& f = files.back();
    if (f.mosaic.cols != lens.width || f.mosaic.rows != lens.height)
      throw std::runtime_error(path + ": frame is " + std::to_string(f.mosaic.cols) + "x" +
                               std::to_string(f.mosaic.rows) + " but the lens is for " + std::to_string(lens.width) +
                               "x" + std::to_string(lens.height));
    if (f.pattern != files.front().pattern)
      throw std::runtime_error(path + ": Bayer pattern " + std::string(to_string(f.pattern)) + " differs from " +
                               settings.frame_files.front() + " (" + std::string(to_string(files.front().pattern)) +
                               ")");
    mosaics.push_back(to_8bit(f.mosaic, f.bit_depth));
  }
  const BayerPattern pattern = files.front().pattern;
  const std::string& detector_name = settings.detector;
  const Detector detector = detector_option(detector_name, detect_scale);
  Preprocessor preprocess;
  OpenClPreprocessorInfo cl_info;
  CudaPreprocessorInfo cuda_info;
  try {
    // The CUDA path says why it cannot run (no nvcc at build time, no GPU) before any frame is read.
    preprocess = backend == "opencl" ? make_opencl_preprocessor(lens, view, pattern, &cl_info)
                 : backend == "cuda" ? make_cuda_preprocessor(lens, view, pattern, &cuda_info)
                                     : make_preprocessor(lens, view, pattern, dm.method, dm.path);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(lens_arg + ": " + e.what());
  }

  PipelineConfig config;
  config.max_frames = frames_arg;
  config.queue_capacity = queue;
  config.policy = policy == "block" ? QueuePolicy::Block : QueuePolicy::DropOldest;
  config.detection_workers = detect_workers;
  // The frame files play the camera, over and over until --frames frames were captured.
  const FrameSource source = [&](std::size_t i) -> std::optional<cv::Mat> { return mosaics[i % mosaics.size()]; };
  const CancelToken& cancel = interrupt_token();
  const auto power = start_power(settings.power, err, settings.json);
  if (power) power->begin_phase("pipeline");
  const PipelineResult result = run_pipeline(source, preprocess, detector, config, cancel);
  if (result.cancelled) {
    err << "benchscope-cli: pipeline cancelled after " << result.processed << " frames; nothing stored\n";
    return 1;
  }

  // How the lens was obtained travels with the timings (the Pipeline view's Lens column).
  PipelineRun run = measured_pipeline_run(result, lens);
  run.platform = settings.platform.value_or(bs::host_name());
  run.device = backend == "opencl" ? cl_info.device + " (OpenCL) preprocessing, CPU detection"
               : backend == "cuda" ? cuda_info.device + " (CUDA) preprocessing, CPU detection"
                                   : "CPU (" + std::to_string(opencv_threads()) + " threads)";
  if (detector)
    run.device += ", " + std::to_string(detect_workers) + " detection worker" + (detect_workers == 1 ? "" : "s");
  run.backend = backend;
  run.demosaic = demosaic_name;
  run.detector = detector_name == "hog" || detector_name == "none" ? detector_name
                 : architecture_from_string(detector_name)
                     ? architecture_detector_name(*architecture_from_string(detector_name))
                     : std::filesystem::path(detector_name.substr(0, detector_name.find(','))).filename().string();
  run.provenance.tool = std::string("benchscope-cli ") + BENCHSCOPE_VERSION;
  run.provenance.compiler = BENCHSCOPE_COMPILER;
  run.provenance.note =
      "benchscope-cli pipeline on " + std::to_string(settings.frame_files.size()) + " frame file(s), " +
      std::to_string(view.width) + "x" + std::to_string(view.height) + " view, policy " + policy + ", queue " +
      std::to_string(config.queue_capacity) +
      (detector ? ", " + std::to_string(detect_workers) + " detection workers, detect scale " + scale_text(detect_scale)
                : std::string());
  const auto figures = [&](std::ostream& info) {
    if (const auto& dir = settings.out)
      write_figures(*dir, files.front(), mosaics.front(), dm, preprocess, detector, info);
  };
  return finish_run(settings, run, result, power.get(), figures, out, err);
}

const CommandRegistrar registrar({
    "pipeline",
    "run the vision pipeline (demosaic + reprojection, detection) on frames; timings, figure 3, store",
    "usage: benchscope-cli pipeline FRAME... --lens LENS.json|paper [--demosaic fused|bilinear|mhc|opencv]\n"
    "       benchscope-cli pipeline --synthetic [--frames N] [--backend B] [--detector D] [--detect-workers W]\n"
    "         [--detect-scale S] [--platform NAME] [--workspace WS] [--json] [--power SENSOR|auto|none]\n"
    "         [--backend cpu|opencl|cuda] [--detector hog|none|mobilenet-ssd|yolo-n|MODEL[,CONFIG]] [--frames N]\n"
    "         [--policy block|drop-oldest] [--queue N] [--detect-workers W] [--detect-scale S]\n"
    "         [--pattern BGGR|RGGB|GRBG|GBRG] [--platform NAME]\n"
    "         [--out DIR] [--workspace WS] [--json] [--power SENSOR|auto|none] [--power-interval-ms M] [--sysfs-root "
    "DIR]\n"
    "  Runs capture -> preprocessing (demosaic + reprojection) -> detection, capture and preprocessing on a thread\n"
    "  each, detection on W worker threads (--detect-workers, default this machine's threads), with\n"
    "  bounded queues (--queue frames each, default 2; --policy block, or drop-oldest like a live camera), over N\n"
    "  frames (default 50) taken from the FRAME files in turn. Frames: PNG/PGM/TIFF (one channel: the raw mosaic,\n"
    "  pattern from --pattern, default BGGR) or raw Bayer FILE.raw with a FILE.json sidecar {width, height, pattern,\n"
    "  bit_depth, endianness} as `synth-frame` writes. --lens takes a lens file, a sidecar that holds one, or paper.\n"
    "  --demosaic fused (default) samples the bilinear demosaic only where the reprojection reads it, in one pass.\n"
    "  --detector hog: OpenCV's HOG people detector; MODEL[,CONFIG]: a network via cv::dnn (ONNX, Caffe, TensorFlow,\n"
    "  Darknet) with SSD, YOLOv5 or YOLOv8 outputs (YOLO inputs letterboxed, SSD stretched), decoded with its\n"
    "  confidence threshold and NMS; mobilenet-ssd, yolo-n: a built-in architecture with random weights\n"
    "  (architecture timing: no detections). The detector sees the view shrunk by --detect-scale S (0 < S <= 1,\n"
    "  default 0.5); its boxes are mapped back to the full view.\n"
    "  Prints per stage n, mean ± SD, p50, p95, min, max (ms) and the throughput; --json prints the run as\n"
    "  benchscope-pipeline-v1 JSON (docs/pipeline-json-v1.md) instead. --out DIR writes the paper's figure 3 for\n"
    "  the first frame: fig3-raw.png (mosaic as grey), fig3-demosaiced.png, fig3-reprojected.png (with boxes).\n"
    "  --workspace WS stores the run (measured, this host's provenance) for the Pipeline and Platforms views.\n"
    "  --backend opencl runs demosaic (bilinear) + reprojection as OpenCL kernels on the first OpenCL device (GPU\n"
    "  preferred); detection stays on the CPU. --backend cuda runs the fused demosaic (bilinear) + reprojection\n"
    "  kernel on the first CUDA GPU (bit-identical to the CPU's fused path); without nvcc at build time or without\n"
    "  a GPU it stops at once saying why.\n"
    "  --power records the on-board sensors during the run (phase \"pipeline\"): energy per frame through the\n"
    "  pipeline, per preprocessed frame and per inference (mean power x stage mean time); --workspace stores the\n"
    "  trace in the same import as the run.\n"
    "  --synthetic measures as the GUI's Pipeline tab does, on the synthetic capture of the paper's camera (the\n"
    "  test chart through the 195 degree lens, 1280x1024 BGGR; default 20 frames; fused demosaic, block policy,\n"
    "  queues of 2): no frame file is needed, so a robot runs it as it is (`remote ROBOT pipeline --synthetic`).",
    run_pipeline_cmd,
});

}  // namespace
}  // namespace bs::cli
