// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/bench_dnn.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <ostream>
#include <random>

#include <unistd.h>
#include <nlohmann/json.hpp>
#include <opencv2/dnn.hpp>

#include "analysis/power/phase_energy.h"
#include "analysis/power/power_stats.h"
#include "analysis/stats/stats.h"
#include "commands/bench_dnn_grammar.h"
#include "common/args.h"
#include "common/bench_host.h"
#include "common/signals.h"
#include "common/text_table.h"
#include "kernels/backends/backend.h"
#include "kernels/cpu/cpu_info.h"
#include "power/power_args.h"
#include "store/home_batch.h"
#include "store/workspace.h"
#include "util/host_clock.h"
#include "util/text.h"
#include "vision/dnn_home.h"
#include "vision/pipeline/detector.h"
#include "vision/pipeline/dnn_architectures.h"
#include "vision/pipeline/dnn_bench.h"

namespace bs::cli {
namespace {

using namespace bs::vision;

// The network to time: built in code or read from files, with what the output and the views need to know.
struct Network {
  cv::dnn::Net net;
  std::string model, hash, family;
  bool architecture_only = false;
  cv::Size input;
  double scale = 1;
  cv::Scalar mean;
  double published_gflops = 0;
  std::string published_note;
};

// `input`: the --input size, empty for the network's own.
Network built_in(DnnArchitecture a, cv::Size input) {
  constexpr unsigned kSeed = 1;
  const cv::Size size = !input.empty()                       ? input
                        : a == DnnArchitecture::MobileNetSsd ? cv::Size(300, 300)
                                                             : cv::Size(640, 640);
  BuiltNetwork b;
  try {
    b = build_architecture(a, size, kSeed);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--input: ") + e.what());
  }
  Network n;
  n.net = std::move(b.net);
  n.model = to_string(a);
  n.hash = std::string("builtin:") + to_string(a) + ":seed" + std::to_string(kSeed);
  n.family = a == DnnArchitecture::MobileNetSsd ? "SSD" : "YOLOv8";
  n.architecture_only = true;
  n.input = size;
  const bool yolo = a == DnnArchitecture::YoloN;
  n.scale = yolo ? 1.0 / 255 : 1.0 / 127.5;
  n.mean = yolo ? cv::Scalar::all(0) : cv::Scalar::all(127.5);
  n.published_gflops = b.published_gflops;
  n.published_note = b.published_note;
  return n;
}

Network from_files(const std::string& spec, cv::Size input) {
  const auto comma = spec.find(',');
  const std::string model = spec.substr(0, comma), config = comma == std::string::npos ? "" : spec.substr(comma + 1);
  for (const std::string& f : {model, config})
    if (!f.empty() && !std::filesystem::is_regular_file(f))
      throw std::runtime_error(f + ": no such model file (--model takes MODEL[,CONFIG])");
  Network n;
  n.net = read_detector_network(model, config);
  DnnOptions o;
  if (!input.empty()) o.input_size = input;
  const DnnDetectorInfo info = probe_detector_network(n.net, o, model);
  n.model = std::filesystem::path(model).filename().string();
  n.hash = file_content_hash(model) + (config.empty() ? "" : "+" + file_content_hash(config));
  n.family = info.family;
  n.input = info.input_size;
  n.scale = info.scale;
  n.mean = info.mean;
  return n;
}

// The device's FP32 ceiling from the FLOPS kernels' backends: the CPU's for the cpu target, the OpenCL or CUDA
// device's of the same name otherwise; empty when unknown.
std::optional<double> device_ceiling(const DnnTarget& t, const kernels::CpuInfo& cpu,
                                     const std::vector<kernels::Backend>& backends) {
  if (t.id == "cpu") return cpu.peak_flops > 0 ? std::optional(cpu.peak_flops) : std::nullopt;
  for (const kernels::Backend& b : backends)
    if (b.id.starts_with(t.id) && b.theoretical_peak_flops > 0 && t.device.starts_with(b.device_name))
      return b.theoretical_peak_flops;
  return std::nullopt;
}

// OpenCV prints OpenCL program build logs with printf, on stdout. With --json stdout holds the document alone, so
// while networks are built and timed file descriptor 1 is pointed at stderr; restore() points it back.
class StdoutToStderr {
 public:
  StdoutToStderr() {
    std::cout.flush();
    std::fflush(stdout);
    saved_ = ::dup(STDOUT_FILENO);
    if (saved_ >= 0 && ::dup2(STDERR_FILENO, STDOUT_FILENO) < 0) {
      ::close(saved_);
      saved_ = -1;
    }
  }
  ~StdoutToStderr() { restore(); }
  StdoutToStderr(const StdoutToStderr&) = delete;
  StdoutToStderr& operator=(const StdoutToStderr&) = delete;
  void restore() {
    if (saved_ < 0) return;
    std::cout.flush();
    std::fflush(stdout);
    ::dup2(saved_, STDOUT_FILENO);
    ::close(saved_);
    saved_ = -1;
  }

 private:
  int saved_ = -1;
};

// A number, or null where there is none (JSON has no NaN).
nlohmann::json number_or_null(const std::optional<double>& v) {
  return v && std::isfinite(*v) ? nlohmann::json(*v) : nlohmann::json();
}

// One row of the table (one network on one target) as benchscope-dnn-bench v1 JSON: seconds, FLOPs and joules
// as measured, nothing rounded; null where a value is not known (no ceiling, no power recorded).
// `published`: the published count of the network a built-in architecture follows, at its standard input (GFLOPs
// per image) and what it counts; 0 and empty for a model file.
nlohmann::json run_json(const DnnRun& r, double cores_busy, double published_gflops,
                        const std::string& published_note) {
  const double per_image_flops = r.batch > 0 ? static_cast<double>(r.flops) / r.batch : 0;
  std::optional<double> ceiling_gflops, fraction, per_wh;
  if (r.device_peak_flops && *r.device_peak_flops > 0) {
    ceiling_gflops = *r.device_peak_flops / 1e9;
    fraction = r.achieved_flops() / *r.device_peak_flops;
  }
  if (r.energy_per_inference_j && *r.energy_per_inference_j > 0) per_wh = 3600.0 / *r.energy_per_inference_j;
  return nlohmann::json{
      {"platform", r.platform},
      {"backend", r.backend},
      {"device", r.device},
      {"model", r.model},
      {"model_hash", r.model_hash},
      {"family", r.family},
      {"architecture_only", r.architecture_only},
      {"label", r.architecture_only ? nlohmann::json(kArchitectureTimingLabel) : nlohmann::json()},
      {"input", {{"width", r.input_width}, {"height", r.input_height}}},
      {"batch", r.batch},
      {"n", r.forward.n},
      {"forward_s",
       {{"mean", r.forward.mean_s},
        {"sd", r.forward.sd_s},
        {"p50", number_or_null(r.forward.p50_s)},
        {"p95", number_or_null(r.forward.p95_s)},
        {"min", number_or_null(r.forward.min_s)},
        {"max", number_or_null(r.forward.max_s)}}},
      {"per_image_s", r.inference_s()},
      {"inferences_per_s", r.inferences_per_s()},
      {"flops_per_image", per_image_flops},
      {"flops", r.flops},
      {"opencv_flops", r.opencv_flops},
      {"published", published_gflops > 0
                        ? nlohmann::json{{"gflops_per_image", published_gflops}, {"note", published_note}}
                        : nlohmann::json()},
      {"achieved_gflops", r.achieved_flops() / 1e9},
      {"ceiling_gflops", number_or_null(ceiling_gflops)},
      {"fraction_of_ceiling", number_or_null(fraction)},
      {"cores_busy", r.backend == "cpu" ? number_or_null(cores_busy) : nlohmann::json()},
      {"energy_per_inference_j", number_or_null(r.energy_per_inference_j)},
      {"inferences_per_wh", number_or_null(per_wh)},
      {"mean_power_w", number_or_null(r.mean_power_w)},
      {"date", r.provenance.date},
  };
}

}  // namespace

int bench_dnn(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err) {
  const commands::BenchDnnSettings settings = commands::bench_dnn_from_words(raw);
  const bool json = settings.json;
  std::optional<StdoutToStderr> quiet_stdout;
  if (json) quiet_stdout.emplace();
  std::ostream& text = json ? err : out;  // --json keeps stdout to the document alone
  const int runs = settings.runs, batch = settings.batch;
  constexpr int kWarmup = 2;
  // An empty size, not std::optional<cv::Size>, for "not given": GCC 11 (JetPack 6's compiler) reports copies of
  // that optional as reads of an uninitialised payload at -O2 (-Wmaybe-uninitialized, a false positive), and -Werror
  // stops the build. The grammar gives sides of at least 32 px or none.
  const cv::Size input(settings.input_width, settings.input_height);
  const std::vector<DnnTarget> targets =
      settings.backend == "all" ? dnn_targets() : std::vector<DnnTarget>{dnn_target(settings.backend)};

  std::vector<Network> networks;
  if (settings.model) {
    networks.push_back(from_files(*settings.model, input));
  } else if (settings.arch) {
    networks.push_back(built_in(*architecture_from_string(*settings.arch), input));  // checked by the grammar
  } else {
    networks.push_back(built_in(DnnArchitecture::MobileNetSsd, input));
    networks.push_back(built_in(DnnArchitecture::YoloN, input));
  }

  const kernels::CpuInfo cpu = kernels::detect_cpu();
  const std::vector<kernels::Backend> backends = kernels::available_backends(cpu);
  const std::string platform = settings.platform.value_or(bs::host_name());
  const std::string load_before = load_average_text();
  text << "CPU: " << cpu.model << ", " << cpu.threads << " threads, FP32 ceiling " << fixed(cpu.peak_flops / 1e9, 1)
       << " GFLOPS (" << cpu.simd.name << ", " << fixed(cpu.clock_hz / 1e9, 3) << " GHz measured); OpenCV " CV_VERSION
       << ", " << cv::getNumThreads() << " dnn threads\nload average before: " << load_before << "\n";
  for (const DnnTarget& t : targets)
    if (!t.available) text << "target " << t.id << ": not available: " << t.why_not << "\n";
  if (std::none_of(targets.begin(), targets.end(), [](const DnnTarget& t) { return t.available; })) {
    err << "benchscope-cli: no requested dnn target is available here\n";
    return 1;
  }

  const auto power = start_power(settings.power, err, false);
  std::vector<DnnRun> stored;
  std::vector<double> cores_of;  // per stored run, for --json
  std::vector<const Network*> network_of;
  const CancelToken& cancel = interrupt_token();
  for (Network& n : networks) {
    const cv::dnn::MatShape shape{batch, 3, n.input.height, n.input.width};
    const DnnFlops flops = count_flops(n.net, shape);
    text << "\n"
         << n.model << " (" << n.family << " output), input " << n.input.width << "x" << n.input.height << ", batch "
         << batch << (n.architecture_only ? std::string(": ") + kArchitectureTimingLabel : std::string())
         << "\n  FLOPs per image: " << fixed(static_cast<double>(flops.counted) / batch / 1e9, 3)
         << " G (2 per multiply-add, grouped convolutions per group); OpenCV 4.6 Net::getFLOPS: "
         << fixed(static_cast<double>(flops.opencv) / batch / 1e9, 3) << " G\n";
    if (n.published_gflops > 0)
      text << "  published: " << n.published_note << "; counted here at this input / published = "
           << fixed(static_cast<double>(flops.counted) / batch / 1e9 / n.published_gflops, 3) << "\n";
    // The images: a fixed pseudo-random colour picture (the same every run and machine) made at the input size, so
    // no resize or letterbox is part of the timed pass.
    std::vector<cv::Mat> images;
    std::mt19937 rng(7);
    for (int i = 0; i < batch; ++i) {
      cv::Mat img(n.input, CV_8UC3);
      for (auto it = img.begin<cv::Vec3b>(); it != img.end<cv::Vec3b>(); ++it)
        *it = cv::Vec3b(static_cast<uchar>(rng()), static_cast<uchar>(rng()), static_cast<uchar>(rng()));
      images.push_back(img);
    }
    const cv::Mat blob = cv::dnn::blobFromImages(images, n.scale, n.input, n.mean, true, false);
    TextTable table({"target", "device", "n", "forward mean ± SD (ms)", "p50 (ms)", "p95 (ms)", "per image (ms)",
                     "inferences/s", "GFLOPS", "ceiling (GFLOPS)", "% ceiling", "cores busy"});
    for (const DnnTarget& t : targets) {
      if (!t.available) continue;
      const std::string phase = n.model + " " + t.id;
      // The cores the process got while timing (CPU time / wall time): on a shared machine this says when a
      // neighbour took some, which the time per pass alone does not.
      double cpu0 = 0;
      std::chrono::steady_clock::time_point wall0;
      const std::vector<double> s = time_forward(n.net, t, blob, kWarmup, runs, cancel, [&] {
        if (power) power->begin_phase(phase);
        cpu0 = process_cpu_seconds();
        wall0 = std::chrono::steady_clock::now();
      });
      const double cores = (process_cpu_seconds() - cpu0) /
                           std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
      if (power) power->end_phase();
      if (cancel.cancelled() || s.empty()) {
        err << "benchscope-cli: bench dnn cancelled; nothing stored\n";
        return 1;
      }
      const Summary sum = summarize(s);
      const Percentiles pct = percentiles(s);
      DnnRun r;
      r.platform = platform;
      r.device = t.device;
      r.backend = t.id;
      r.model = n.model;
      r.model_hash = n.hash;
      r.family = n.family;
      r.architecture_only = n.architecture_only;
      r.input_width = n.input.width;
      r.input_height = n.input.height;
      r.batch = batch;
      r.flops = flops.counted;
      r.opencv_flops = flops.opencv;
      r.forward = {"inference", sum.n, sum.mean, sum.sd, sum.min, sum.max, pct.p50, pct.p95};
      r.device_peak_flops = device_ceiling(t, cpu, backends);
      r.provenance = kernels::measured_provenance(cpu, backends.front());
      r.provenance.date = bs::utc_timestamp();
      r.provenance.tool = std::string("benchscope-cli ") + BENCHSCOPE_VERSION;
      r.provenance.note = "benchscope-cli bench dnn: " + std::to_string(runs) + " timed forward passes after " +
                          std::to_string(kWarmup) + " warm-up passes, OpenCV " CV_VERSION " dnn target " + t.id +
                          (n.architecture_only ? std::string(", ") + kArchitectureTimingLabel : std::string());
      stored.push_back(r);
      cores_of.push_back(cores);
      network_of.push_back(&n);
      table.add({t.id, t.device, std::to_string(sum.n), fixed(sum.mean * 1e3, 2) + " ± " + fixed(sum.sd * 1e3, 2),
                 fixed(pct.p50 * 1e3, 2), fixed(pct.p95 * 1e3, 2), fixed(r.inference_s() * 1e3, 2),
                 fixed(r.inferences_per_s(), 2), fixed(r.achieved_flops() / 1e9, 2),
                 r.device_peak_flops ? fixed(*r.device_peak_flops / 1e9, 1) : "–",
                 r.device_peak_flops ? fixed(100 * r.achieved_flops() / *r.device_peak_flops, 1) + "%" : "–",
                 t.id == "cpu" ? fixed(cores, 2) : "–"});
    }
    table.print(text);
    text << "  (cores busy: process CPU time / wall time over the timed passes, of " << cpu.threads << " threads)\n";
  }
  std::optional<PowerTrace> trace;
  if (power) {
    trace = power->finish("bench dnn " + platform + " " + bs::utc_timestamp());
    trace->platform = platform;
    const std::vector<PhaseEnergy> phases = phase_energies(*trace);
    text << "\nenergy per inference (" << to_string(trace->provenance.measurement) << ", " << trace->provenance.sensor
         << "; whole-computer power during the timed passes):\n";
    for (DnnRun& r : stored) {
      const std::string phase = r.model + " " + r.backend;
      for (const PhaseEnergy& e : phases)
        if (e.name == phase) {
          const auto inferences = static_cast<std::size_t>(r.forward.n) * static_cast<std::size_t>(r.batch);
          r.energy_per_inference_j = e.energy_j / static_cast<double>(inferences);
          r.mean_power_w = e.mean_power_w;
          text << "  " << phase << ": " << fixed(*r.energy_per_inference_j, 4) << " J per inference, "
               << fixed(3600.0 / *r.energy_per_inference_j, 0) << " inferences per Wh, mean "
               << fixed(e.mean_power_w, 2) << " W over " << fixed(e.end_s - e.start_s, 2) << " s (" << e.samples
               << " samples)\n";
        }
    }
  }
  const std::string load_after = load_average_text();
  text << "\nload average after: " << load_after << "\n";
  if (const auto& ws_path = settings.workspace) {
    const std::int64_t id = bring_home(*ws_path, dnn_home(stored, trace, "benchscope-cli bench dnn"));
    text << "stored " << stored.size() << " run" << (stored.size() == 1 ? "" : "s") << " in " << *ws_path << " (import "
         << id << ")\n";
  }
  if (json) {
    quiet_stdout->restore();
    nlohmann::json rows = nlohmann::json::array(), unavailable = nlohmann::json::array();
    for (std::size_t i = 0; i < stored.size(); ++i)
      rows.push_back(run_json(stored[i], cores_of[i], network_of[i]->published_gflops, network_of[i]->published_note));
    for (const DnnTarget& t : targets)
      if (!t.available) unavailable.push_back({{"backend", t.id}, {"why_not", t.why_not}});
    out << nlohmann::json{{"format", "benchscope-dnn-bench"},
                          {"version", 1},
                          {"platform", platform},
                          {"opencv", CV_VERSION},
                          {"cpu",
                           {{"model", cpu.model},
                            {"threads", cpu.threads},
                            {"ceiling_gflops", cpu.peak_flops / 1e9},
                            {"clock_ghz", cpu.clock_hz / 1e9},
                            {"simd", cpu.simd.name},
                            {"dnn_threads", cv::getNumThreads()}}},
                          {"warmup_passes", kWarmup},
                          {"load_average_before", load_before},
                          {"load_average_after", load_after},
                          {"power_sensor", trace ? nlohmann::json(trace->provenance.sensor) : nlohmann::json()},
                          {"unavailable", unavailable},
                          {"runs", rows}}
               .dump(2)
        << '\n';
  }
  return 0;
}

}  // namespace bs::cli
