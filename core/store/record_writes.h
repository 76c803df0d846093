// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Each record kind's rows, written inside an import's transaction through its tables' descriptions (store/tables.h),
// the same ones the reader checks them with. One function per kind, named by its descriptor (store/record_kinds.h);
// store/workspace_write.cpp opens the transaction, writes the import's row and calls them in turn.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "store/import_batch.h"
#include "util/cancel.h"

namespace bs {
namespace sqlite {
class Db;
}

namespace store {

struct DeviceIds;

// One import being written: where, under which import row, and what the kinds share (the devices of runs and result
// sets, cancellation).
struct ImportWrite {
  ImportWrite(const sqlite::Db& db, std::int64_t import_id, const ImportBatch& batch, const std::string& content_hash,
              const CancelToken* cancel);
  ~ImportWrite();
  const sqlite::Db& db;
  std::int64_t import_id;
  const ImportBatch& batch;
  const std::string& content_hash;
  const CancelToken* cancel;
  std::unique_ptr<DeviceIds> devices;
  int rows = 0;
  void poll();   // every 1000 rows: throws Cancelled when asked to stop
  void check();  // now: throws Cancelled when asked to stop
};

void write_runs(ImportWrite& w, const std::vector<FlopsRun>& runs);
void write_result_sets(ImportWrite& w, const std::vector<ResultSet>& sets);
void write_power_logs(ImportWrite& w, const std::vector<PowerTrace>& traces);
void write_frames(ImportWrite& w, const std::vector<Frame>& frames);
void write_pipeline_runs(ImportWrite& w, const std::vector<PipelineRun>& runs);
void write_inference_runs(ImportWrite& w, const std::vector<DnnRun>& runs);
void write_headroom(ImportWrite& w, const std::vector<headroom::HeadroomMeasurement>& measurements);
void write_sustained_runs(ImportWrite& w, const std::vector<SustainRun>& runs);

}  // namespace store
}  // namespace bs
