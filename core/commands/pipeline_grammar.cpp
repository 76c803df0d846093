// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands/pipeline_grammar.h"

#include <cmath>
#include <stdexcept>

#include "vision/demosaic/bayer.h"
#include "vision/pipeline/pipeline.h"

namespace bs::commands {
namespace {

std::size_t whole_count(const Words& args, const std::string& option, double max, const std::string& max_text) {
  const double v = args.number(option, 1);
  if (v < 1 || v > max || v != std::floor(v))
    throw UsageError(option + " must be a whole number from 1 to " + max_text);
  return static_cast<std::size_t>(v);
}

void refuse_with_synthetic(const PipelineSettings& s) {
  if (!s.frame_files.empty())
    throw UsageError("--synthetic measures the synthetic capture of the paper's camera: give no frame files (got '" +
                     s.frame_files.front() + "')");
  const std::pair<const char*, bool> file_only[] = {{"--demosaic", s.demosaic.has_value()},
                                                    {"--policy", s.policy.has_value()},
                                                    {"--queue", s.queue.has_value()},
                                                    {"--pattern", s.pattern.has_value()},
                                                    {"--out", s.out.has_value()}};
  for (const auto& [option, given] : file_only)
    if (given)
      throw UsageError(std::string("--synthetic runs as the Pipeline tab does (fused demosaic, block policy, queues "
                                   "of 2, BGGR, no figures): leave out ") +
                       option);
  if (s.lens && *s.lens != "paper")
    throw UsageError("--synthetic uses the paper's lens (--lens paper), not '" + *s.lens + "'");
}

void check_with_files(const PipelineSettings& s) {
  if (s.frame_files.empty()) throw UsageError("pipeline needs at least one frame file (or --synthetic)");
  if (!s.lens) throw UsageError("--lens LENS.json is required (or --lens paper for the paper's camera)");
  if (s.demosaic && *s.demosaic != "fused" && *s.demosaic != "bilinear" && *s.demosaic != "mhc" &&
      *s.demosaic != "opencv")
    throw UsageError("--demosaic must be fused, bilinear, mhc or opencv (got '" + *s.demosaic + "')");
  const std::string demosaic = s.demosaic.value_or(s.backend == "opencl" ? "bilinear" : "fused");
  if (s.backend != "cpu" && demosaic != "fused" && demosaic != "bilinear")
    throw UsageError("--backend " + s.backend + " demosaics bilinearly: use --demosaic bilinear (got '" + demosaic +
                     "')");
  if (s.policy && *s.policy != "block" && *s.policy != "drop-oldest")
    throw UsageError("--policy must be block or drop-oldest");
  if (s.pattern) {
    try {
      vision::bayer_pattern_from_string(*s.pattern);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--pattern: ") + e.what());
    }
  }
}

}  // namespace

std::optional<std::size_t> read_detect_workers(const Words& args) {
  const auto w = args.value("--detect-workers");
  if (!w) return std::nullopt;
  const double v = args.number("--detect-workers", 1);
  if (!(v >= 1 && v <= static_cast<double>(vision::kMaxDetectionWorkers)) || v != std::floor(v))
    throw UsageError("--detect-workers must be a whole number from 1 to " +
                     std::to_string(vision::kMaxDetectionWorkers) + " (got '" + *w + "')");
  return static_cast<std::size_t>(v);
}

double read_detect_scale(const Words& args) {
  const double s = args.number("--detect-scale", 0.5);
  if (!(s > 0 && s <= 1))
    throw UsageError(
        "--detect-scale must be greater than 0 and at most 1, the factor the frame is shrunk by before "
        "detection (got '" +
        args.value("--detect-scale").value_or("") + "')");
  return s;
}

std::vector<std::string> to_words(const PipelineSettings& s) {
  std::vector<std::string> a = {"pipeline"};
  if (s.synthetic) a.push_back("--synthetic");
  if (s.frames) a.insert(a.end(), {"--frames", std::to_string(*s.frames)});
  if (s.detect_workers) a.insert(a.end(), {"--detect-workers", std::to_string(*s.detect_workers)});
  a.insert(a.end(), {"--detect-scale", number_word(s.detect_scale), "--backend", s.backend, "--detector", s.detector});
  write_option(a, "--lens", s.lens);
  write_option(a, "--demosaic", s.demosaic);
  write_option(a, "--policy", s.policy);
  if (s.queue) a.insert(a.end(), {"--queue", std::to_string(*s.queue)});
  write_option(a, "--pattern", s.pattern);
  write_option(a, "--platform", s.platform);
  write_option(a, "--out", s.out);
  write_option(a, "--workspace", s.workspace);
  if (s.json) a.push_back("--json");
  write_power(s.power, a);
  if (!s.frame_files.empty()) a.push_back("--");  // a frame named "-x.png" stays a frame
  a.insert(a.end(), s.frame_files.begin(), s.frame_files.end());
  return a;
}

PipelineSettings pipeline_from_words(const std::vector<std::string>& words) {
  std::set<std::string> valued = {
      "--lens",      "--demosaic", "--backend",  "--detector", "--frames",         "--policy",      "--out",
      "--workspace", "--pattern",  "--platform", "--queue",    "--detect-workers", "--detect-scale"};
  valued.insert(kPowerWordOptions.begin(), kPowerWordOptions.end());
  const Words args = read_words(words, {"--json", "--synthetic"}, valued);
  PipelineSettings s;
  s.synthetic = args.has("--synthetic");
  s.frame_files = args.positional;
  s.lens = args.value("--lens");
  s.demosaic = args.value("--demosaic");
  s.backend = args.value("--backend").value_or("cpu");
  s.detector = args.value("--detector").value_or("hog");
  s.policy = args.value("--policy");
  s.pattern = args.value("--pattern");
  s.platform = args.value("--platform");
  s.out = args.value("--out");
  s.workspace = args.value("--workspace");
  s.json = args.has("--json");
  s.power = read_power(args);
  // The queue is read here, before --synthetic refuses the options it does not take.
  if (args.value("--queue")) {
    const double q = args.number("--queue", 2);
    if (q < 1 || q > 1024 || q != std::floor(q)) throw UsageError("--queue must be between 1 and 1024");
    s.queue = static_cast<std::size_t>(q);
  }
  if (s.synthetic) refuse_with_synthetic(s);
  if (s.backend != "cpu" && s.backend != "opencl" && s.backend != "cuda")
    throw UsageError("--backend must be cpu, opencl or cuda (got '" + s.backend + "')");
  if (!s.synthetic) check_with_files(s);
  if (args.value("--frames"))
    s.frames = s.synthetic ? whole_count(args, "--frames", 1e6, "1,000,000")
                           : whole_count(args, "--frames", 1e7, "10,000,000");
  s.detect_workers = read_detect_workers(args);
  s.detect_scale = read_detect_scale(args);
  return s;
}

PipelineSettings robot_pipeline_settings(const vision::SyntheticPipelineOptions& o, const std::string& platform,
                                         bool record_power) {
  if (vision::detector_is_model_file(o.detector))
    throw std::invalid_argument("the detector '" + o.detector +
                                "' is a model file on this computer; a robot runs hog, none or a built-in "
                                "architecture (mobilenet-ssd, yolo-n): copy the model there and run "
                                "`benchscope-cli pipeline` on the robot to use it");
  PipelineSettings s;
  s.synthetic = true;
  s.frames = o.frames;
  s.detect_workers = o.detection_workers;
  s.detect_scale = o.detect_scale;
  s.backend = o.backend;
  s.detector = o.detector;
  if (!platform.empty()) s.platform = platform;
  if (record_power) s.power.sensor = "auto";
  return s;
}

}  // namespace bs::commands
