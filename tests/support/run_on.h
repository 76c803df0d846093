// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where a sample run was measured: every run kind (FlopsRun, DnnRun, PipelineRun) names its platform, device and
// backend first, and almost every test that builds one sets those three before the figures it checks. One line for
// them, so a test's sample spells out only what makes it that sample.
#include <string>
#include <utility>

namespace bs::test {

template <class Run>
Run run_on(std::string platform, std::string device, std::string backend) {
  Run r;
  r.platform = std::move(platform);
  r.device = std::move(device);
  r.backend = std::move(backend);
  return r;
}

// ... and of a FlopsRun, the kind of its device (DeviceKind), which the views and the roofline group by.
template <class Run, class Kind>
Run run_on(std::string platform, std::string device, Kind kind, std::string backend) {
  Run r = run_on<Run>(std::move(platform), std::move(device), std::move(backend));
  r.device_kind = kind;
  return r;
}

}  // namespace bs::test
