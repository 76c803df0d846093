// SPDX-License-Identifier: GPL-3.0-or-later
// What goes into a workspace comes back exactly: runs, result sets, power traces, devices and their colours,
// imports; an import is stored whole or not at all (duplicate, bad row, cancel).
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

#include "store/workspace.h"
#include "workspace_test_support.h"

using namespace bs::test;

namespace {

// A Google Benchmark output of the NUC's CPU as its importer gives it: the result sets these tests store.
bs::ResultSet nuc_cpu_set(const bs::Provenance& provenance = {}) {
  return {"NUC", "i7-7567U", bs::DeviceKind::Cpu, "CPU", "google-benchmark-json", {}, provenance};
}

bs::ImportBatch bench_json_of(std::vector<bs::ResultSet> sets) {
  return batch_holding(&bs::ImportBatch::result_sets, std::move(sets), "bench.json", "google-benchmark-json");
}

}  // namespace

class TestWorkspace : public QObject {
  Q_OBJECT
 private slots:
  void round_trip_is_exact_and_ordered() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string path = dir.filePath("w.bsw").toStdString();
    // Input order: device B appears first (colour 0), then A (colour 1).
    std::vector<bs::FlopsRun> in = {make_run("B", "OpenCL", 4, 40, 3), make_run("A", "CUDA", 1, 3, 1),
                                    make_run("B", "CUDA", 2, 5, 2), make_run("B", "OpenCL", 1, 7, 4),
                                    make_run("B", "OpenCL", 1, 2, 1)};
    in[1].device_kind = bs::DeviceKind::Cpu;
    in[1].reported_peak_flops.reset();
    in[1].theoretical_peak_flops = 1.5e12;
    in[2].reported_peak_flops.reset();
    in[2].provenance = bs::Provenance{};  // all empty
    in[3].variant = "float16x4";
    in[3].kernel = "rotation2d-throughput";
    in[3].iterations = std::int64_t{1} << 40;
    in[3].theoretical_peak_flops = 10.5e12;
    // Seconds that only survive bit-exactly if stored as binary doubles: extremes and values without a short
    // decimal form.
    in[4].samples[0].seconds = {std::numeric_limits<double>::denorm_min()};
    in[4].samples[1].seconds = {std::numeric_limits<double>::max()};
    in[3].samples[2].seconds = {0.1, 1e-300, std::nextafter(1.0, 2.0), 1.0 / 7.0};
    std::int64_t import_id = 0;
    {
      bs::Workspace ws(path);
      QCOMPARE(ws.schema_version(), bs::Workspace::kSchemaVersion);
      QCOMPARE(ws.path(), path);
      import_id = ws.add_import(batch_of(in), "hash1");
    }
    const bs::Workspace ws(path);  // reopened: nothing comes from memory
    const auto runs = ws.runs();
    QCOMPARE(runs.size(), in.size());
    // Ordered by colour index, backend, dims, id: B/CUDA/2, B/OpenCL/1 (#3 then #4), B/OpenCL/4, A/CUDA/1.
    const std::size_t expected_order[] = {2, 3, 4, 0, 1};
    const auto devices = ws.devices();
    QCOMPARE(devices.size(), std::size_t{2});
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const bs::FlopsRun& want = in[expected_order[i]];
      QVERIFY2(same_run(runs[i].run, want), qPrintable(QString("run %1 differs").arg(i)));
      QCOMPARE(runs[i].import_id, import_id);
      const auto& dev = devices[static_cast<std::size_t>(runs[i].color_index)];
      QCOMPARE(runs[i].device_id, dev.id);
      QCOMPARE(dev.device, want.device);
    }
    QVERIFY(runs[1].id < runs[2].id);  // equal keys keep insertion order
    QCOMPARE(devices[0].device, std::string("B"));
    QCOMPARE(devices[0].color_index, 0);
    QCOMPARE(devices[0].kind, bs::DeviceKind::Gpu);
    QCOMPARE(devices[1].device, std::string("A"));
    QCOMPARE(devices[1].color_index, 1);
    QCOMPARE(devices[1].kind, bs::DeviceKind::Cpu);
    QCOMPARE(ws.integrity_check(), std::string("ok"));
  }

  void import_records_meta_and_file_markers() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("w.bsw").toStdString();
    bs::Workspace ws(path);
    auto batch = batch_of({make_run("A", "OpenCL", 4, 2, 1), make_run("B", "OpenCL", 4, 2, 1)}, "/data/nuc.json");
    batch.result_sets.push_back({"NUC", "A", bs::DeviceKind::Gpu, "OpenCL", "clpeak-text", {}, {}});
    const auto id1 = ws.add_import(batch, "00000000deadbeef");
    const auto id2 = ws.add_import(batch_of({make_run("C", "CUDA", 1, 1, 1)}, "second.json"), "h2");
    QVERIFY(id2 > id1);
    const auto imports = ws.imports();
    QCOMPARE(imports.size(), std::size_t{2});
    QCOMPARE(imports[0].id, id1);
    QCOMPARE(imports[0].path, std::string("/data/nuc.json"));
    QCOMPARE(imports[0].format, std::string("benchscope-run-v1"));
    QCOMPARE(imports[0].content_hash, std::string("00000000deadbeef"));
    QCOMPARE(imports[0].run_count, std::int64_t{2});
    QCOMPARE(imports[0].result_set_count, std::int64_t{1});
    QVERIFY2(QRegularExpression(R"(^\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ$)")
                 .match(QString::fromStdString(imports[0].imported_at))
                 .hasMatch(),
             imports[0].imported_at.c_str());
    QCOMPARE(imports[1].path, std::string("second.json"));

    RawDb raw(path);
    QCOMPARE(raw.scalar("PRAGMA application_id"), std::to_string(0x42534350));
    QCOMPARE(raw.scalar("PRAGMA user_version"), std::to_string(bs::Workspace::kSchemaVersion));
    QCOMPARE(raw.scalar("PRAGMA journal_mode"), std::string("wal"));
    QCOMPARE(raw.scalar("SELECT value FROM meta WHERE key = 'schema_version'"),
             std::to_string(bs::Workspace::kSchemaVersion));
    QVERIFY(raw.scalar("SELECT value FROM meta WHERE key = 'created_by'").starts_with("benchscope "));
    QVERIFY(QRegularExpression(R"(^\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ$)")
                .match(QString::fromStdString(raw.scalar("SELECT value FROM meta WHERE key = 'created_at'")))
                .hasMatch());
    QCOMPARE(raw.scalar("SELECT COUNT(*) FROM run_samples"), std::string("5"));
    QCOMPARE(raw.scalar("SELECT provenance FROM runs ORDER BY id LIMIT 1").substr(0, 1), std::string("{"));
  }

  void result_sets_round_trip_with_non_finite_values() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("w.bsw").toStdString();
    bs::ResultSet cpu = nuc_cpu_set(full_provenance("gb"));
    cpu.measurements.push_back({"BM_Rotate/4096",
                                "real_time",
                                "s",
                                {1.0 / 3.0, 0.1, 2e-9},
                                {{"mean", 0.14444}, {"median", 0.1}, {"stddev", 1e-12}, {"cv", 0.0}}});
    cpu.measurements.push_back({"BM_Rotate/4096",
                                "items_per_second",
                                "1/s",
                                // NaN keeps a repetition that gave no number; infinities are refused (below).
                                {std::numeric_limits<double>::quiet_NaN(), -0.0, 5e-324},
                                {{"mean", std::numeric_limits<double>::quiet_NaN()}}});
    cpu.measurements.push_back({"BM_Empty", "cpu_time", "s", {}, {}});
    bs::ResultSet gpu{"NVIDIA CUDA", "GTX 1080 Ti", bs::DeviceKind::Gpu, "OpenCL", "clpeak-text", {}, {}};
    gpu.measurements.push_back({"float4", "single-precision compute", "FLOP/s", {1.1e13, 1.2e13}, {}});
    bs::ImportBatch batch = bench_json_of({cpu, gpu});
    batch.runs.push_back(make_run("i7-7567U", "CPU SIMD (AVX2)", 4, 2, 2));
    batch.runs.back().device_kind = bs::DeviceKind::Cpu;  // the same CPU device as the result set
    {
      bs::Workspace ws(path);
      ws.add_import(batch, "h");
    }
    const bs::Workspace ws(path);
    const auto sets = ws.result_sets();
    QCOMPARE(sets.size(), std::size_t{2});
    QVERIFY(same_set(sets[0].set, cpu));
    QVERIFY(same_set(sets[1].set, gpu));
    // The set shares the device (and so the colour) of the run on the same device.
    QCOMPARE(sets[0].device_id, ws.runs()[0].device_id);
    QCOMPARE(sets[0].color_index, 0);
    QCOMPARE(sets[1].color_index, 1);
    QCOMPARE(ws.imports()[0].result_set_count, std::int64_t{2});
    QVERIFY(ws.damage().empty());
  }

  // A value no importer produces (an infinite rate) is written as the workspace always did, but read back it breaks
  // the import rules: the set is left out and named (issue #37).
  void infinite_measurement_is_damage() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("w.bsw").toStdString();
    bs::ResultSet cpu = nuc_cpu_set();
    cpu.measurements.push_back(
        {"BM_Rotate/4096", "items_per_second", "1/s", {1.0, std::numeric_limits<double>::infinity()}, {}});
    bs::Workspace(path).add_import(bench_json_of({cpu}), "h");
    const bs::Workspace ws(path);
    QVERIFY(ws.result_sets().empty());
    QCOMPARE(ws.damage().size(), std::size_t{1});
    QVERIFY2(ws.damage()[0].item.find("result set #1 (NUC / i7-7567U") == 0, ws.damage()[0].item.c_str());
    QVERIFY2(ws.damage()[0].reason.find("measurements.vals: value 1") != std::string::npos,
             ws.damage()[0].reason.c_str());
    QCOMPARE(ws.damage()[0].category, bs::ImportErrorCategory::InvalidValue);
    QVERIFY(ws.read_only());
  }

  void power_traces_round_trip() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("w.bsw").toStdString();
    bs::PowerTrace t;
    t.platform = "NUC";
    t.label = "load";
    t.start_time = "2018-06-01T10:00:00Z";
    t.supply_voltage_v = 16;
    t.time_s = {0, 0.1, 0.25};
    t.channels.push_back({"current_A", bs::PowerQuantity::Current, {2.5, 2.6, 1.0 / 3.0}});
    t.channels.push_back({"VDD_IN", bs::PowerQuantity::Voltage, {19.0, 19.1, 18.9}});
    t.channels.push_back({"power_W", bs::PowerQuantity::Power, {40, 41.6, 16.0 / 3.0}});
    t.provenance = full_provenance("power");
    t.provenance.measurement = bs::MeasurementKind::ExternalMeter;
    t.provenance.sensor = "Keysight N6705C";
    t.provenance.settings = {{"nvp model", "MAXN"}, {"jetson_clocks", "on"}};
    t.total_channel = "power_W";
    t.phases = {{"idle", 0, 0.1}, {"load \"kick\"", 0.1, 0.25}};
    t.channels.push_back({"rail_with_gap", bs::PowerQuantity::Power, {1, std::nan(""), 2}});
    bs::PowerTrace bare;
    bare.platform = "Jetson TX2";
    bare.time_s = {0};
    bare.channels.push_back({"VDD_IN", bs::PowerQuantity::Power, {3.2}});
    bs::ImportBatch b;
    b.source_path = "nuc.csv";
    b.format = "power-csv";
    b.power_traces = {t, bare};
    std::int64_t import_id = 0;
    {
      bs::Workspace ws(path);
      import_id = ws.add_import(b, "trace");
    }
    bs::Workspace ws(path);
    const auto traces = ws.power_traces();
    QCOMPARE(traces.size(), std::size_t{2});
    for (std::size_t i = 0; i < traces.size(); ++i) {
      const bs::PowerTrace& want = b.power_traces[i];
      const bs::PowerTrace& got = traces[i].trace;
      QCOMPARE(traces[i].import_id, import_id);
      QCOMPARE(got.platform, want.platform);
      QCOMPARE(got.label, want.label);
      QCOMPARE(got.start_time, want.start_time);
      QVERIFY(same_bits(got.supply_voltage_v, want.supply_voltage_v));
      QVERIFY(same_bits(got.time_s, want.time_s));
      QVERIFY(same_provenance(got.provenance, want.provenance));
      QCOMPARE(got.total_channel, want.total_channel);
      QCOMPARE(got.phases.size(), want.phases.size());
      for (std::size_t p = 0; p < got.phases.size(); ++p) {
        QCOMPARE(got.phases[p].name, want.phases[p].name);
        QCOMPARE(got.phases[p].start_s, want.phases[p].start_s);
        QCOMPARE(got.phases[p].end_s, want.phases[p].end_s);
      }
      QCOMPARE(got.channels.size(), want.channels.size());
      for (std::size_t c = 0; c < got.channels.size(); ++c) {
        QCOMPARE(got.channels[c].name, want.channels[c].name);
        QCOMPARE(got.channels[c].quantity, want.channels[c].quantity);
        QVERIFY(same_bits(got.channels[c].values, want.channels[c].values));
      }
    }
    QCOMPARE(ws.devices().size(), std::size_t{0});  // power traces belong to platforms, not devices
    ws.remove_import(import_id);
    QCOMPARE(ws.power_traces().size(), std::size_t{0});
    QCOMPARE(row_counts(path)["power_channels"], std::string("0"));
  }

  void colours_are_stable_across_reopen_and_removal() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("w.bsw").toStdString();
    std::int64_t first_import = 0;
    {
      bs::Workspace ws(path);
      first_import = ws.add_import(batch_of({make_run("A", "OpenCL", 4, 20, 3)}), "h1");
      ws.add_import(batch_of({make_run("B", "OpenCL", 4, 2, 1)}), "h2");
    }
    {
      bs::Workspace ws(path);
      ws.remove_import(first_import);
      QCOMPARE(row_counts(path)["run_samples"], std::string("2"));  // A's 60 samples went with its run
      ws.add_import(batch_of({make_run("C", "OpenCL", 4, 2, 1)}), "h3");
    }
    bs::Workspace ws(path);
    ws.add_import(batch_of({make_run("A", "OpenCL", 4, 2, 1), make_run("D", "OpenCL", 4, 2, 1)}), "h4");
    const auto devices = ws.devices();
    QCOMPARE(devices.size(), std::size_t{4});
    const char* names[] = {"A", "B", "C", "D"};
    for (int i = 0; i < 4; ++i) {
      QCOMPARE(devices[static_cast<std::size_t>(i)].device, std::string(names[i]));
      QCOMPARE(devices[static_cast<std::size_t>(i)].color_index, i);
    }
    const auto runs = ws.runs();
    QCOMPARE(runs.size(), std::size_t{4});
    QCOMPARE(runs[0].run.device, std::string("A"));  // A is back, with its old colour 0
    QCOMPARE(runs[0].color_index, 0);
    QCOMPARE(runs[3].color_index, 3);
    // Issue #23.4: the user gives a device another colour; every view reads it from here.
    ws.set_device_color(runs[1].run.platform, "B", 9);
    for (const auto& r : ws.runs())
      if (r.run.device == "B") QCOMPARE(r.color_index, 9);
    QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError, ws.set_device_color(runs[1].run.platform, "no such device", 2));
    QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError, ws.set_device_color(runs[1].run.platform, "B", -1));
    // A new device takes the smallest index nobody has: 1 is free since B moved to 9.
    ws.add_import(batch_of({make_run("E", "OpenCL", 4, 2, 1)}), "h5");
    for (const auto& d : ws.devices())
      if (d.device == "E") QCOMPARE(d.color_index, 1);
  }

  void device_kind_is_learned_but_never_forgotten() {
    QTemporaryDir dir;
    bs::Workspace ws(dir.filePath("w.bsw").toStdString());
    auto unknown = make_run("X", "OpenCL", 4, 1, 1);
    unknown.device_kind = bs::DeviceKind::Other;
    ws.add_import(batch_of({unknown}), "h1");
    QCOMPARE(ws.devices()[0].kind, bs::DeviceKind::Other);
    auto gpu = unknown;
    gpu.device_kind = bs::DeviceKind::Gpu;
    ws.add_import(batch_of({gpu}), "h2");
    QCOMPARE(ws.devices()[0].kind, bs::DeviceKind::Gpu);
    ws.add_import(batch_of({unknown}), "h3");
    QCOMPARE(ws.devices()[0].kind, bs::DeviceKind::Gpu);
    auto cpu = unknown;
    cpu.device_kind = bs::DeviceKind::Cpu;  // a known kind is not overwritten by a different claim
    ws.add_import(batch_of({cpu}), "h4");
    QCOMPARE(ws.devices().size(), std::size_t{1});
    QCOMPARE(ws.devices()[0].kind, bs::DeviceKind::Gpu);
    for (const auto& r : ws.runs()) QCOMPARE(r.run.device_kind, bs::DeviceKind::Gpu);
  }

  void duplicate_import_is_rejected_and_changes_nothing() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("w.bsw").toStdString();
    bs::Workspace ws(path);
    ws.add_import(batch_of({make_run("A", "OpenCL", 4, 3, 2)}, "/lab/first-name.json"), "same");
    const auto before = row_counts(path);
    const std::string when = ws.imports()[0].imported_at;
    try {
      ws.add_import(batch_of({make_run("B", "OpenCL", 4, 3, 1)}, "/lab/renamed.json"), "same");
      QFAIL("duplicate accepted");
    } catch (const bs::WorkspaceError& e) {
      QCOMPARE(e.kind(), bs::WorkspaceError::Kind::Constraint);
      const std::string msg = e.what();
      QVERIFY2(msg.find("/lab/first-name.json") != std::string::npos, e.what());
      QVERIFY2(msg.find(when) != std::string::npos, e.what());
    }
    QVERIFY(row_counts(path) == before);
    QCOMPARE(ws.devices().size(), std::size_t{1});
  }

  void bad_row_rolls_back_the_whole_import() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("w.bsw").toStdString();
    bs::Workspace ws(path);
    ws.add_import(batch_of({make_run("A", "OpenCL", 4, 2, 1)}), "ok");
    const auto before = row_counts(path);
    // A new device and several good runs first, then a run the schema refuses (seconds must be > 0).
    auto bad = make_run("New", "OpenCL", 4, 3, 2);
    bad.samples[2].seconds[1] = 0.0;
    QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError,
                             ws.add_import(batch_of({make_run("New", "CUDA", 1, 50, 3), bad}), "bad"));
    QVERIFY(row_counts(path) == before);
    QCOMPARE(ws.devices().size(), std::size_t{1});
    // The failed hash is not remembered: the fixed file can be imported.
    ws.add_import(batch_of({make_run("New", "CUDA", 1, 50, 3)}), "bad");
    QCOMPARE(ws.devices()[1].color_index, 1);
  }

  void cancelled_import_leaves_nothing() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("w.bsw").toStdString();
    bs::Workspace ws(path);
    ws.add_import(batch_of({make_run("A", "OpenCL", 4, 2, 1)}), "first");
    const auto before = row_counts(path);
    bs::CancelToken cancel;
    cancel.cancel();
    // Large: the cancel is seen while rows are being written (every 1000 rows), 1000 samples into the transaction.
    auto big = batch_of({make_run("B", "OpenCL", 4, 2000, 2)});
    big.result_sets.push_back({"NUC", "C", bs::DeviceKind::Gpu, "OpenCL", "clpeak-text", {}, {}});
    QVERIFY_THROWS_EXCEPTION(bs::Cancelled, ws.add_import(big, "big", &cancel));
    QVERIFY(row_counts(path) == before);
    // Small: fewer rows than the polling interval, so only the final check before COMMIT sees the cancel.
    QVERIFY_THROWS_EXCEPTION(bs::Cancelled, ws.add_import(batch_of({make_run("B", "OpenCL", 4, 3, 1)}), "s", &cancel));
    QVERIFY(row_counts(path) == before);
    QCOMPARE(ws.devices().size(), std::size_t{1});
    // And the workspace still works, with the cancelled hash free again.
    bs::CancelToken fresh;
    ws.add_import(big, "big", &fresh);
    QCOMPARE(ws.runs().size(), std::size_t{2});
    QCOMPARE(ws.devices()[1].device, std::string("B"));
    QCOMPARE(ws.devices()[1].color_index, 1);
  }

  void cancel_from_another_thread_is_all_or_nothing() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("w.bsw").toStdString();
    bs::Workspace ws(path);
    bs::CancelToken cancel;
    const auto batch = batch_of({make_run("A", "OpenCL", 4, 20000, 5)});
    // The cancel lands mid-import or after it, depending on the machine; both outcomes are checked below.
    std::thread canceller([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      cancel.cancel();
    });
    bool cancelled = false;
    try {
      ws.add_import(batch, "h", &cancel);
    } catch (const bs::Cancelled&) {
      cancelled = true;
    }
    canceller.join();
    const auto counts = row_counts(path);
    QCOMPARE(counts.at("run_samples"), std::string(cancelled ? "0" : "100000"));
    QCOMPARE(counts.at("imports"), std::string(cancelled ? "0" : "1"));
  }

  void content_hash_known_answers_and_streaming() {
    // FNV-1a 64-bit reference values.
    QCOMPARE(bs::content_hash(""), std::string("cbf29ce484222325"));
    QCOMPARE(bs::content_hash("a"), std::string("af63dc4c8601ec8c"));
    QCOMPARE(bs::content_hash("foobar"), std::string("85944171f73967e8"));
    QTemporaryDir dir;
    QByteArray big;
    for (int i = 0; i < 300000; ++i) big.append(static_cast<char>((i * 131) & 0xff));  // spans several buffers
    const QString big_path = dir.filePath("big.bin");
    QVERIFY(write_file(big_path, big));
    QCOMPARE(bs::file_content_hash(big_path.toStdString()),
             bs::content_hash(std::string_view(big.constData(), static_cast<std::size_t>(big.size()))));
    QVERIFY(write_file(dir.filePath("empty"), {}));
    QCOMPARE(bs::file_content_hash(dir.filePath("empty").toStdString()), std::string("cbf29ce484222325"));
    const std::string before = bs::file_content_hash(big_path.toStdString());
    big[150000] = static_cast<char>(big[150000] ^ 1);  // one bit, past the first read buffer
    QVERIFY(write_file(big_path, big));
    QVERIFY(bs::file_content_hash(big_path.toStdString()) != before);
    const std::string missing = dir.filePath("missing.json").toStdString();
    try {
      bs::file_content_hash(missing);
      QFAIL("hash of a missing file");
    } catch (const std::runtime_error& e) {
      QVERIFY2(std::string(e.what()).find(missing) != std::string::npos, e.what());
    }
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, bs::file_content_hash(dir.path().toStdString()));  // a directory
  }
};

QTEST_GUILESS_MAIN(TestWorkspace)
#include "test_workspace.moc"
