// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/shared_traces.h"

#include <utility>

namespace bs::ui {

SharedTraces share_traces(std::vector<StoredPowerTrace> stored) {
  auto set = std::make_shared<LoadedTraces>();
  set->traces.reserve(stored.size());
  set->ids.reserve(stored.size());
  for (StoredPowerTrace& s : stored) {
    set->traces.push_back(std::move(s.trace));
    set->ids.push_back(s.id);
  }
  return set;
}

SharedTraces share_traces(std::vector<PowerTrace> traces) {
  auto set = std::make_shared<LoadedTraces>();
  set->ids.assign(traces.size(), 0);
  set->traces = std::move(traces);
  return set;
}

std::shared_ptr<const PowerTrace> trace_of(const SharedTraces& set, std::size_t i) {
  return std::shared_ptr<const PowerTrace>(set, &set->traces.at(i));
}

}  // namespace bs::ui
