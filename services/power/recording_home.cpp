// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/recording_home.h"

#include <sstream>

#include "power/power_recording.h"
#include "sensors/recording_csv.h"
#include "store/workspace.h"
#include "util/home_name.h"

namespace bs {

HomeBatch recording_home(const PowerTrace& trace, const std::string& where) {
  HomeBatch out;
  out.batch.source_path = home_name(where, trace.platform, trace.provenance.date);
  out.batch.format = std::string(kPowerRecordingFileFormat.id);
  out.batch.power_traces = {trace};
  std::ostringstream csv;
  sensors::write_recording_csv(csv, trace);
  out.content_hash = content_hash(csv.str());
  return out;
}

}  // namespace bs
