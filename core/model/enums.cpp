// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/flops_run.h"
#include "model/provenance.h"

namespace bs {

std::string_view to_string(DataOrigin origin) {
  switch (origin) {
    case DataOrigin::Measured:
      return "measured";
    case DataOrigin::Reconstructed:
      return "reconstructed";
    case DataOrigin::Published:
      return "published";
    case DataOrigin::Unknown:
      break;
  }
  return "unknown";
}

DataOrigin data_origin_from_string(std::string_view text) {
  if (text == "measured") return DataOrigin::Measured;
  if (text == "reconstructed") return DataOrigin::Reconstructed;
  if (text == "published") return DataOrigin::Published;
  return DataOrigin::Unknown;
}

std::string_view to_string(MeasurementKind kind) {
  switch (kind) {
    case MeasurementKind::ExternalMeter:
      return "external meter";
    case MeasurementKind::OnBoardSensor:
      return "on-board sensor";
    case MeasurementKind::SoftwareEstimate:
      return "software estimate";
    case MeasurementKind::Unknown:
      break;
  }
  return "unknown";
}

MeasurementKind measurement_kind_from_string(std::string_view text) {
  if (text == "external meter") return MeasurementKind::ExternalMeter;
  if (text == "on-board sensor") return MeasurementKind::OnBoardSensor;
  if (text == "software estimate") return MeasurementKind::SoftwareEstimate;
  return MeasurementKind::Unknown;
}

std::string_view to_string(DeviceKind kind) {
  switch (kind) {
    case DeviceKind::Cpu:
      return "cpu";
    case DeviceKind::Gpu:
      return "gpu";
    case DeviceKind::Other:
      break;
  }
  return "other";
}

DeviceKind device_kind_from_string(std::string_view text) {
  if (text == "cpu") return DeviceKind::Cpu;
  if (text == "gpu") return DeviceKind::Gpu;
  return DeviceKind::Other;
}

}  // namespace bs
