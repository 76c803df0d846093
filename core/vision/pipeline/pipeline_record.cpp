// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/pipeline/pipeline_record.h"

#include "util/host_clock.h"

namespace bs::vision {

PipelineRun to_pipeline_run(const PipelineResult& result) {
  PipelineRun run;
  for (const StageTiming& t : result.stages) {
    if (t.summary.n == 0) continue;
    const std::string name = t.stage == "preprocessing" ? pipeline_stage::kPreprocess
                             : t.stage == "detection"   ? pipeline_stage::kDetect
                                                        : t.stage;
    constexpr double s = 1e-3;
    run.stages.push_back({name, t.summary.n, t.summary.mean * s, t.summary.sd * s, t.summary.min * s, t.summary.max * s,
                          t.p50 * s, t.p95 * s});
  }
  if (result.throughput_fps > 0) run.throughput_fps = result.throughput_fps;
  return run;
}

PipelineRun measured_pipeline_run(const PipelineResult& result, const Lens& lens) {
  PipelineRun run = to_pipeline_run(result);
  run.frame_width = lens.width;
  run.frame_height = lens.height;
  run.provenance.settings.emplace_back("lens calibration", describe(lens.calibration));
  run.provenance.origin = DataOrigin::Measured;
  run.provenance.host = bs::host_name();
  run.provenance.date = bs::utc_timestamp();
  return run;
}

}  // namespace bs::vision
