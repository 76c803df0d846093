// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/flops_run.h"
#include "model/provenance.h"
#include "util/enum_words.h"

namespace bs {
namespace {

// The words files and the workspace store; a word no line names reads as the unknown value.
constexpr EnumWord<DataOrigin> kDataOriginWords[] = {{DataOrigin::Measured, "measured"},
                                                     {DataOrigin::Reconstructed, "reconstructed"},
                                                     {DataOrigin::Published, "published"},
                                                     {DataOrigin::Unknown, "unknown"}};
static_assert(names_every_value(kDataOriginWords, DataOrigin::Published));
constexpr EnumWord<MeasurementKind> kMeasurementKindWords[] = {{MeasurementKind::ExternalMeter, "external meter"},
                                                               {MeasurementKind::OnBoardSensor, "on-board sensor"},
                                                               {MeasurementKind::SoftwareEstimate, "software estimate"},
                                                               {MeasurementKind::Unknown, "unknown"}};
static_assert(names_every_value(kMeasurementKindWords, MeasurementKind::SoftwareEstimate));
constexpr EnumWord<DeviceKind> kDeviceKindWords[] = {
    {DeviceKind::Cpu, "cpu"}, {DeviceKind::Gpu, "gpu"}, {DeviceKind::Other, "other"}};
static_assert(names_every_value(kDeviceKindWords, DeviceKind::Gpu));

}  // namespace

std::string_view to_string(DataOrigin origin) { return word_of(kDataOriginWords, origin, "unknown"); }

DataOrigin data_origin_from_string(std::string_view text) {
  return parse_word(kDataOriginWords, text).value_or(DataOrigin::Unknown);
}

std::string_view to_string(MeasurementKind kind) { return word_of(kMeasurementKindWords, kind, "unknown"); }

MeasurementKind measurement_kind_from_string(std::string_view text) {
  return parse_word(kMeasurementKindWords, text).value_or(MeasurementKind::Unknown);
}

std::string_view to_string(DeviceKind kind) { return word_of(kDeviceKindWords, kind, "other"); }

DeviceKind device_kind_from_string(std::string_view text) {
  return parse_word(kDeviceKindWords, text).value_or(DeviceKind::Other);
}

}  // namespace bs
