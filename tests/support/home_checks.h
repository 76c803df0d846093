// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What every kind's batch builder must do for #52's one way home, checked the same way for each kind: the same
// measurement built by two front ends is one import (the second store refused as a duplicate), and a power trace
// recorded beside a measurement is stored, and removed, with it. Each kind's test adds what its batch must hold.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <QTemporaryDir>
#include <QTest>

#include "model/power_trace.h"
#include "store/home_batch.h"
#include "store/workspace.h"

namespace bs::test {

inline constexpr const char* kHomeDate = "2026-12-06T10:00:00Z";

// Measured here, on the robot "robot-nuc", at kHomeDate: the provenance every measurement of these tests has.
inline Provenance measured_on_robot() {
  Provenance p;
  p.origin = DataOrigin::Measured;
  p.host = "robot-nuc";
  p.date = kHomeDate;
  return p;
}

// A power trace as the recorder gives it beside a measurement (three samples of one RAPL channel), named `label`.
inline PowerTrace recorded_beside(const std::string& label) {
  PowerTrace t;
  t.platform = "robot-nuc";
  t.label = label;
  t.start_time = kHomeDate;
  t.time_s = {0, 0.1, 0.2};
  t.channels = {{"package-0", PowerQuantity::Power, {12.5, 13.0, 12.75}}};
  t.total_channel = "package-0";
  t.provenance = measured_on_robot();
  t.provenance.measurement = MeasurementKind::OnBoardSensor;
  t.provenance.sensor = "rapl package-0 (rapl:package-0)";
  return t;
}

// The import ids of a workspace's stored rows of one kind (StoredRun, StoredPipelineRun, ...).
template <class Stored>
std::vector<std::int64_t> import_ids(const std::vector<Stored>& rows) {
  std::vector<std::int64_t> ids;
  for (const Stored& r : rows) ids.push_back(r.import_id);
  return ids;
}

// `first` and `second`: one measurement as two front ends build it (the Kernel Runner and `run flops`, ...). The
// hashes match, and a workspace holding the first refuses the second and still holds one import.
inline void same_measurement_is_one_import(const HomeBatch& first, const HomeBatch& second) {
  QCOMPARE(first.content_hash, second.content_hash);
  QTemporaryDir dir;
  Workspace ws(dir.filePath("home.bsw").toStdString());
  bring_home(ws, first);
  try {
    bring_home(ws, second);
    QFAIL("the same measurement was stored twice");
  } catch (const WorkspaceError& e) {
    QCOMPARE(e.kind(), WorkspaceError::Kind::Constraint);
  }
  QCOMPARE(ws.imports().size(), std::size_t{1});
}

// `home` carries one power trace: stored in the same import as the measurement's rows (`rows_of(ws)`: their import
// ids, import_ids(ws.runs()) ...), and gone with them when that import is removed.
template <class RowsOf>
void trace_goes_home_with_it(const HomeBatch& home, RowsOf rows_of) {
  QCOMPARE(home.batch.power_traces.size(), std::size_t{1});
  QTemporaryDir dir;
  Workspace ws(dir.filePath("home.bsw").toStdString());
  const std::int64_t id = bring_home(ws, home);
  const auto traces = ws.power_trace_summaries();
  QCOMPARE(traces.size(), std::size_t{1});
  QCOMPARE(traces[0].import_id, id);
  QCOMPARE(traces[0].trace.label, home.batch.power_traces[0].label);
  const std::vector<std::int64_t> rows = rows_of(ws);
  QVERIFY(!rows.empty());
  for (std::int64_t row_import : rows) QCOMPARE(row_import, id);
  ws.remove_import(id);
  QVERIFY(ws.power_trace_summaries().empty());
  QVERIFY(rows_of(ws).empty());
}

}  // namespace bs::test
