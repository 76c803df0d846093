// SPDX-License-Identifier: GPL-3.0-or-later
// The pipeline JSON writer (declared in pipeline_json.h). Apart from the reader so that the reader's file holds only
// what an import runs (what the fuzz coverage of the pipeline importer measures).
#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "model/provenance_json.h"
#include "runs/pipeline_json.h"

namespace bs {

std::string write_pipeline_json(const PipelineRun& run) {
  using ojson = nlohmann::ordered_json;
  const auto bad = [&](const std::string& what) {
    throw std::invalid_argument("pipeline run of " + run.platform + ": " + what);
  };
  if (run.platform.empty()) bad("platform is empty");
  if (run.stages.empty()) bad("no stages");
  ojson j;
  j["format"] = kPipelineJsonFormat;
  j["platform"] = run.platform;
  j["device"] = run.device.empty() ? run.platform : run.device;
  j["backend"] = run.backend.empty() ? "cpu" : run.backend;
  if (!run.demosaic.empty()) j["demosaic"] = run.demosaic;
  if (!run.detector.empty()) j["detector"] = run.detector;
  if (run.frame_width > 0 && run.frame_height > 0)
    j["frame"] = {{"width", run.frame_width}, {"height", run.frame_height}};
  if (run.throughput_fps) {
    if (!(*run.throughput_fps > 0) || !std::isfinite(*run.throughput_fps)) bad("throughput is not a positive number");
    j["throughput_fps"] = *run.throughput_fps;
  }
  ojson stages = ojson::object();
  for (const StageStats& s : run.stages) {
    if (!is_pipeline_stage(s.stage)) bad("unknown stage '" + s.stage + "'");
    if (s.n == 0) bad(s.stage + ": n is 0");
    ojson o;
    o["n"] = s.n;
    const auto put = [&](const char* key, double v) {
      if (!std::isfinite(v) || v < 0) bad(s.stage + ": " + key + " is negative or not finite");
      o[key] = v;
    };
    put("mean_s", s.mean_s);
    put("sd_s", s.n == 1 ? 0.0 : s.sd_s);
    if (s.min_s) put("min_s", *s.min_s);
    if (s.max_s) put("max_s", *s.max_s);
    if (s.p50_s) put("p50_s", *s.p50_s);
    if (s.p95_s) put("p95_s", *s.p95_s);
    stages[s.stage] = std::move(o);
  }
  j["stages"] = std::move(stages);
  ojson prov;
  const nlohmann::json shared = provenance_to_json(run.provenance, false);  // kept alive while iterating
  for (const auto& [k, v] : shared.items()) prov[k] = v;
  j["provenance"] = std::move(prov);
  return j.dump(2) + "\n";
}

}  // namespace bs
