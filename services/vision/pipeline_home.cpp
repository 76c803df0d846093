// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/pipeline_home.h"

#include "runs/pipeline_json.h"
#include "store/workspace.h"
#include "util/home_name.h"

namespace bs {

HomeBatch pipeline_home(const PipelineRun& run, const std::optional<PowerTrace>& power, const std::string& where) {
  HomeBatch out;
  out.batch.source_path = home_name(where, run.platform, run.provenance.date);
  out.batch.format = std::string(kPipelineJsonFormat);
  out.batch.pipeline_runs = {run};
  if (power) out.batch.power_traces.push_back(*power);
  out.content_hash = content_hash(write_pipeline_json(run));
  return out;
}

}  // namespace bs
