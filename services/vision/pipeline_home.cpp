// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/pipeline_home.h"

#include "runs/pipeline_json.h"
#include "store/workspace.h"
#include "util/home_name.h"

namespace bs {

HomeBatch pipeline_home(const PipelineRun& run, const std::optional<PowerTrace>& power, const std::string& where) {
  HomeBatch out = measured_home(home_name(where, run.platform, run.provenance.date), std::string(kPipelineJsonFormat),
                                power, write_pipeline_json(run));
  out.batch.pipeline_runs = {run};
  return out;
}

}  // namespace bs
