// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace bs {

// Whether numbers were measured on a real machine, rebuilt from published figures (the paper's), or taken as
// published by others from their own files (MLPerf submissions, clpeak logs: the library, resources/library/).
// Every view and export shows this, so neither reconstructed nor published data can pass for a lab's measurement.
enum class DataOrigin { Unknown, Measured, Reconstructed, Published };

std::string_view to_string(DataOrigin origin);
DataOrigin data_origin_from_string(std::string_view text);  // unknown text -> DataOrigin::Unknown

// How a power or energy number was obtained. Shown beside every power figure: an external meter on the supply, a
// sensor on the board itself (INA3221, RAPL, NVML, hwmon), or a software estimate (a model, not a measurement).
enum class MeasurementKind { Unknown, ExternalMeter, OnBoardSensor, SoftwareEstimate };

std::string_view to_string(MeasurementKind kind);                     // "external meter", "on-board sensor", ...
MeasurementKind measurement_kind_from_string(std::string_view text);  // unknown text -> Unknown

struct Provenance {
  DataOrigin origin = DataOrigin::Unknown;
  std::string host;          // hostname of the machine that measured
  std::string cpu_model;     // e.g. "Intel(R) Core(TM) i7-7567U CPU @ 3.50GHz"
  std::string gpu_model;     // e.g. "Intel Iris Plus Graphics 650"
  std::string os;            // e.g. "Debian GNU/Linux 12"
  std::string compiler;      // e.g. "g++ 12.2.0"
  std::string tool;          // producing tool and version, e.g. "benchscope 0.1.0" or "google-benchmark"
  std::string git_revision;  // of the producing tool, when known
  std::string date;          // ISO 8601 date-time of the measurement
  std::string note;          // free text, e.g. "reconstructed from the paper's reported figures (Table 1)"
  std::string source_file;   // set by the importer: the file this came from
  // Power and energy data: how it was measured, and by what (meter model, "INA3221 VDD_IN", "RAPL package-0").
  MeasurementKind measurement = MeasurementKind::Unknown;
  std::string sensor;
  // Configuration the file states about the measured system, in file order: ("nvp model", "MAXN"),
  // ("jetson_clocks", "on"), ("library_build_type", "debug"), ("num_cpus", "8"), ...
  std::vector<std::pair<std::string, std::string>> settings;
};

}  // namespace bs
