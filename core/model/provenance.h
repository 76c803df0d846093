// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <string_view>

namespace bs {

// Whether numbers were measured on a real machine or rebuilt from published figures. Every view and export
// shows this, so reconstructed data can never pass for a measurement.
enum class DataOrigin { Unknown, Measured, Reconstructed };

std::string_view to_string(DataOrigin origin);
DataOrigin data_origin_from_string(std::string_view text);  // unknown text -> DataOrigin::Unknown

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
};

}  // namespace bs
