// SPDX-License-Identifier: GPL-3.0-or-later
#include "workspace/registry.h"

#include "frames/frame_codec.h"
#include "frames/frame_pnm.h"
#include "frames/frame_raw.h"
#include "headroom/cyclictest_json.h"
#include "headroom/cyclictest_text.h"
#include "headroom/performance_test_csv.h"
#include "headroom/performance_test_json.h"
#include "headroom/rttest_log.h"
#include "headroom/rttest_statistics.h"
#include "mlperf/mlperf_submission.h"
#include "power/jtop_csv.h"
#include "power/nvidia_smi.h"
#include "power/perf_stat.h"
#include "power/power_csv.h"
#include "power/power_recording.h"
#include "power/ptd_log.h"
#include "power/tegrastats.h"
#include "ros2/robotperf_yaml.h"
#include "ros2/ros2_benchmark_json.h"
#include "runs/clpeak_text.h"
#include "runs/google_benchmark_json.h"
#include "runs/pipeline_json.h"
#include "runs/run_json.h"

namespace bs {
namespace {

std::vector<std::unique_ptr<Importer>> make_importers() {
  return importers_of({&kRunJsonFileFormat,
                       &kPipelineJsonFileFormat,
                       &kGoogleBenchmarkJsonFileFormat,
                       &kClpeakTextFileFormat,
                       &kPowerRecordingFileFormat,
                       &kPowerCsvFileFormat,
                       &kTegrastatsFileFormat,
                       &kJtopCsvFileFormat,
                       &kNvidiaSmiFileFormat,
                       &kPerfStatFileFormat,
                       &kPtdLogFileFormat,
                       &kCyclictestTextFileFormat,
                       &kCyclictestJsonFileFormat,
                       &kRttestLogFileFormat,
                       &kRttestStatisticsFileFormat,
                       &kPerformanceTestCsvFileFormat,
                       &kPerformanceTestJsonFileFormat,
                       &kMlperfLoadgenFileFormat,
                       &kRos2BenchmarkJsonFileFormat,
                       &kRobotperfYamlFileFormat,
                       &kRawBayerFileFormat,
                       &kPnmFileFormat,
                       &kPngFileFormat,
                       &kTiffFileFormat});
}

// The chosen importer's parse with the default options, the batch labelled with its file and format.
ImportBatch parse_as(const Importer& importer, const std::string& path, const ImportLimits& limits,
                     const CancelToken& cancel) {
  cancel.throw_if_cancelled();
  ImportBatch batch = importer.parse(path, ParseOptions{}, limits, cancel);
  batch.source_path = path;
  batch.format = std::string(importer.id());
  return batch;
}

}  // namespace

const std::vector<std::unique_ptr<Importer>>& all_importers() {
  static const auto importers = make_importers();
  return importers;
}

const Importer* find_importer(std::string_view id) {
  for (const auto& imp : all_importers())
    if (imp->id() == id) return imp.get();
  return nullptr;
}

// The binary (or the text) importer whose sniff claims `head` most strongly; null when none claims it. Content
// decides; the usual extension only breaks a tie (score * 2 + 1 can never beat a higher score).
static const Importer* best_sniffed(bool binary, std::string_view head, const std::string& path) {
  const Importer* best = nullptr;
  int best_score = 0;
  for (const auto& imp : all_importers()) {
    if (imp->binary() != binary) continue;
    const int content = imp->sniff(head, path);
    if (content <= 0) continue;
    const int score = content * 2 + (imp->usual_extension(path) ? 1 : 0);
    if (score > best_score) {
      best_score = score;
      best = imp.get();
    }
  }
  return best;
}

ImportBatch import_file(const std::string& path, const CancelToken& cancel, const ImportLimits& limits) {
  std::string head = read_head(path);
  // Binary formats (frames) first, on the raw head: their magic bytes (or a .raw sidecar) would fail the text
  // checks below. A file no binary importer claims goes on to the text formats.
  if (const Importer* binary = best_sniffed(true, head, path)) return parse_as(*binary, path, limits, cancel);
  check_text(head, path);
  const Importer* best = best_sniffed(false, strip_utf8_bom(head), path);
  if (!best) {
    std::string tried;
    for (const auto& imp : all_importers()) tried += (tried.empty() ? "" : ", ") + std::string(imp->description());
    throw ImportError(ImportErrorCategory::UnknownFormat, {path, 0, 0, {}},
                      "not a format BenchScope reads (tried: " + tried + ")");
  }
  return parse_as(*best, path, limits, cancel);
}

ImportBatch import_file_with_raw_geometry(const std::string& path, const std::optional<RawFrameOptions>& raw_geometry,
                                          const CancelToken& cancel, const std::string& geometry_source) {
  if (raw_geometry && raw_without_sidecar(path)) {
    ImportBatch b = read_raw_frame(path, *raw_geometry, {}, cancel, geometry_source);
    b.source_path = path;
    b.format = "raw-bayer";
    return b;
  }
  return import_file(path, cancel);
}

}  // namespace bs
