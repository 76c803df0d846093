// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One MLPerf Inference result as a submission folder holds it: results/<system>/<network>/<scenario>/performance/
// run_1/mlperf_log_summary.txt is the file imported; what sits around it is read when present:
//   run_1/mlperf_log_detail.txt      LoadGen version, test date, query count, power window (loadgen_detail.h)
//   run_1/spl.txt                    the PTDaemon log of a power submission: mean power over LoadGen's power window
//                                    and the energy per query and per sample (power/ptd_log.h reads it)
//   systems/<system>.json            accelerator, host processor, framework, OS, notes, division, submitter
//   measurements/<system>/<network>/<scenario>/*.json   weight and input data types (the precision)
// A lab's own LoadGen run (just the summary and detail, anywhere) imports too. The result becomes one ResultSet
// (source_format "mlperf-loadgen") whose measurements are in SI units (latencies in s, rates in 1/s, energy in J,
// power in W), named "<network> <scenario>", with every stated condition in the provenance settings.
// Importing a folder walks it: accuracy runs, power ranging runs and compliance (audit) runs are not results and
// are passed over (their summaries sniff as no format), and spl.txt files import on their own as power traces.
#include <string>

#include "common/format_importer.h"
#include "mlperf/loadgen_summary.h"

namespace bs {

extern const FileFormat kMlperfLoadgenFileFormat;

// Measurement metric names, shared with the library and the views.
namespace mlperf_metric {
inline constexpr const char* kResult = "result";  // the scenario's headline metric, in its SI unit
inline constexpr const char* kMeanLatency = "mean latency";
inline constexpr const char* kMinLatency = "min latency";
inline constexpr const char* kMaxLatency = "max latency";
inline constexpr const char* kQps = "queries per second";  // without LoadGen overhead where stated
inline constexpr const char* kSamplesPerSecond = "samples per second";
inline constexpr const char* kMeanPower = "mean power";
inline constexpr const char* kEnergyPerQuery = "energy per query";
inline constexpr const char* kEnergyPerSample = "energy per sample";
}  // namespace mlperf_metric

// The summary's text (and, optionally, its companions' texts) to a batch; `file` names the summary in errors.
// Used by the importer, the tests and the fuzz target.
struct MlperfCompanions {
  std::string detail_text, detail_file;
  std::string spl_text, spl_file;
  std::string system_json, system_file;
  std::string measurements_json, measurements_file;
  std::string network, system;    // from the folder layout (or a loose file's name); empty when nothing says
  std::string system_note;        // why no system description was taken, when several lay beside the summary
  std::string measurements_note;  // why no measurements description was taken, when some lay beside it
  std::string pairing_note;       // why a detail log or power log beside it was not paired (two could be its)
  bool loose = false;             // the summary lies outside a submission tree (a lab's download)
};

// The files read with a summary: in a submission tree run_N/'s mlperf_log_detail.txt and spl.txt; loose, the
// detail log, power log, system and measurements JSONs that pair with it (mlperf/loose_files.h). An import reads them
// with their summary, not on their own.
std::vector<std::string> mlperf_companion_paths(const std::string& summary_path);

// The MLPerf benchmark a folder or file name names ("resnet", "ssd-small", "Orin_retinanet_SS") in the
// canonical spelling ("resnet50", "ssd-mobilenet", "retinanet"); "" when it names none.
std::string network_from_name(std::string_view path);
ImportBatch parse_mlperf_summary(const std::string& text, const std::string& file, const MlperfCompanions& with = {},
                                 const ImportLimits& limits = {}, const CancelToken& cancel = CancelToken{});

}  // namespace bs
