// SPDX-License-Identifier: GPL-3.0-or-later
// Google Benchmark JSON: repetitions, aggregates, counters and their units, error/skipped rows, NaN/Infinity.
#include <QTest>

#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "analysis/peaks/flops.h"
#include "analysis/peaks/foreign_sweeps.h"
#include "runs/google_benchmark_json.h"

#include "../../support/file_text.h"
#include "../../support/import_errors.h"
#include "../../support/importer_parse.h"
#include "../../support/near.h"
#include "../../support/public_data.h"
#include "../../support/result_set_lookup.h"

using bs::test::file_text;
using bs::test::find_measurement;
using bs::test::near;
using bs::test::parse_with;
using bs::test::setting;

namespace {
const std::string kData = BENCHSCOPE_TEST_DATA_DIR "/importers/google-benchmark/";
const std::string kRealFolder = "tests/data/importers/google-benchmark";

double aggregate(const bs::Measurement& m, const std::string& name) {
  for (const auto& [key, value] : m.reported_aggregates)
    if (key == name) return value;
  return -1;
}

// The ImportError of parsing `text`, or a failure when it was accepted.
bs::ImportError error_of(const std::string& text) {
  return bs::test::import_error_of([&] { return bs::parse_google_benchmark_json(text, "e.json"); });
}

// One document with the given rows, each row's text given without braces.
std::string with_rows(const std::vector<std::string>& rows) {
  std::string out = "{\"context\": {\"host_name\": \"h\"},\n\"benchmarks\": [";
  for (std::size_t i = 0; i < rows.size(); ++i) out += (i ? ",\n{" : "\n{") + rows[i] + "}";
  return out + "]}";
}

bs::ImportBatch parse_file(const std::string& name) {
  return parse_with(bs::kGoogleBenchmarkJsonFileFormat, kData + name);
}

// A real output: a third-party file of tests/data/importers/google-benchmark/ in the shared folder (SOURCES there).
bs::ImportBatch parse_real(const std::string& name) {
  return parse_with(bs::kGoogleBenchmarkJsonFileFormat, bs::test::public_data(kRealFolder + ("/" + name)));
}

// A one-row document with the given counters, for unit inference.
std::string with_counters(const std::string& counters) {
  return "{\"context\":{\"host_name\":\"h\"},\"benchmarks\":[{\"name\":\"BM\",\"run_type\":\"iteration\","
         "\"real_time\":2,\"cpu_time\":1,\"time_unit\":\"ns\"," +
         counters + "}]}";
}
}  // namespace

class TestGoogleBenchmarkJson : public QObject {
  Q_OBJECT
 private slots:
  void parses_repetitions_aggregates_and_counters() {
    const auto batch = parse_file("rotation-repetitions.json");
    QCOMPARE(batch.result_sets.size(), std::size_t{1});
    const bs::ResultSet& s = batch.result_sets[0];
    QCOMPARE(s.platform, std::string("robot-nuc"));
    QCOMPARE(s.device, std::string("CPU (4 x 3500 MHz)"));
    QCOMPARE(s.device_kind, bs::DeviceKind::Cpu);
    QCOMPARE(s.backend, std::string("Google Benchmark"));
    QCOMPARE(s.source_format, std::string("google-benchmark-json"));
    QCOMPARE(s.provenance.tool, std::string("google-benchmark v1.7.1"));
    QCOMPARE(s.provenance.origin, bs::DataOrigin::Measured);
    QCOMPARE(s.provenance.host, std::string("robot-nuc"));
    QCOMPARE(s.provenance.date, std::string("2026-11-21T14:02:11+00:00"));
    const auto* real = find_measurement(s, "BM_Rotate/4096", "real_time");
    QVERIFY(real);
    QCOMPARE(real->unit, std::string("s"));
    QCOMPARE(real->values.size(), std::size_t{3});  // one per repetition
    QVERIFY(near(real->values[0], 13.280e-3));      // ms -> s
    QVERIFY(near(real->values[2], 13.442e-3));
    QCOMPARE(real->reported_aggregates.size(), std::size_t{4});  // mean, (repetitions 3), stddev, cv
    QCOMPARE(aggregate(*real, "repetitions"), 3.0);
    QCOMPARE(real->reported_aggregates[0].first, std::string("mean"));
    QVERIFY(near(aggregate(*real, "mean"), 13.341e-3));
    QVERIFY(near(aggregate(*real, "stddev"), 8.7e-5));
    QVERIFY(near(aggregate(*real, "cv"), 6.5e-3));  // a ratio, not scaled
    const auto* cpu = find_measurement(s, "BM_Rotate/4096", "cpu_time");
    QVERIFY(cpu && near(cpu->values[1], 13.296e-3));
    const auto* flops = find_measurement(s, "BM_Rotate/4096", "FLOPS");
    QVERIFY(flops);
    QCOMPARE(flops->unit, std::string("FLOP/s"));
    QCOMPARE(flops->values, (std::vector<double>{2.9612e10, 2.9565e10, 2.9255e10}));
    QCOMPARE(find_measurement(s, "BM_Rotate/4096", "items_per_second")->unit, std::string("1/s"));
    const auto* copy = find_measurement(s, "BM_Copy/1048576", "bytes_per_second");
    QVERIFY(copy);
    QCOMPARE(copy->unit, std::string("B/s"));
    QVERIFY(near(find_measurement(s, "BM_Copy/1048576", "real_time")->values[0], 206.4e-6));  // us -> s
    QVERIFY(!find_measurement(s, "BM_Rotate/4096", "iterations"));  // bookkeeping, not a counter
    QVERIFY(!find_measurement(s, "BM_Broken", "real_time"));
    QCOMPARE(batch.warnings.size(), std::size_t{1});
    QVERIFY(batch.warnings[0].find("OpenCL device not found") != std::string::npos);
    QVERIFY(batch.warnings[0].starts_with(kData + "rotation-repetitions.json:"));
    QVERIFY(batch.warnings[0].find("/benchmarks/7") != std::string::npos);
  }

  void aggregates_only_with_nan_and_skipped_rows() {
    const auto batch = parse_file("aggregates-only-nan.json");
    const bs::ResultSet& s = batch.result_sets.at(0);
    QCOMPARE(s.platform, std::string("jetson-tx2"));
    QCOMPARE(s.device, std::string("CPU (6 x 2035 MHz)"));
    QCOMPARE(s.provenance.tool, std::string("google-benchmark v1.8.3"));
    QVERIFY(s.provenance.note.find("scaling was on") != std::string::npos);
    const std::string run = "BM_RotateNeon/16384/threads:4";
    const auto* real = find_measurement(s, run, "real_time");
    QVERIFY(real);
    QVERIFY(real->values.empty());  // --benchmark_report_aggregates_only: no repetitions, only aggregates
    QVERIFY(near(aggregate(*real, "mean"), 4.83125e-3));
    QVERIFY(near(aggregate(*real, "median"), 4.829e-3));
    QVERIFY(near(aggregate(*real, "cv"), 2.5873221216041399e-03));
    const auto* gflops = find_measurement(s, run, "GFLOPS");
    QVERIFY(gflops);
    QCOMPARE(gflops->unit, std::string("FLOP/s"));
    QVERIFY(near(aggregate(*gflops, "mean"), 8.1401e9));  // GFLOPS -> FLOP/s
    QVERIFY(near(aggregate(*gflops, "cv"), 2.5798208866475845e-03));
    // Infinity / NaN counters are left out with a warning naming the line; the times of that row stay.
    QVERIFY(find_measurement(s, "BM_Idle", "real_time"));
    QVERIFY(!find_measurement(s, "BM_Idle", "bytes_per_second"));
    QVERIFY(!find_measurement(s, "BM_Idle", "items_per_second"));
    QVERIFY(!find_measurement(s, "BM_NeedsGpu", "real_time"));
    QCOMPARE(batch.warnings.size(), std::size_t{3});
    QVERIFY(batch.warnings[0].find(":106:") != std::string::npos);  // "bytes_per_second": Infinity
    QVERIFY(batch.warnings[0].find("/benchmarks/4/bytes_per_second") != std::string::npos);
    QVERIFY(batch.warnings[2].find("no CUDA device") != std::string::npos);
  }

  void counter_units_from_names() {
    const auto batch = bs::parse_google_benchmark_json(
        with_counters("\"flop_count\":5,\"MFLOP/s\":3,\"flops_per_second\":7,\"TFLOPS\":2,\"cache_misses\":9"),
        "u.json");
    const bs::ResultSet& s = batch.result_sets[0];
    QCOMPARE(s.platform, std::string("h"));
    QCOMPARE(s.device, std::string("CPU"));  // no num_cpus / mhz_per_cpu
    QCOMPARE(find_measurement(s, "BM", "flop_count")->unit, std::string(""));
    QCOMPARE(find_measurement(s, "BM", "MFLOP/s")->unit, std::string("FLOP/s"));
    QCOMPARE(find_measurement(s, "BM", "MFLOP/s")->values[0], 3e6);
    QCOMPARE(find_measurement(s, "BM", "flops_per_second")->values[0], 7.0);
    QCOMPARE(find_measurement(s, "BM", "TFLOPS")->values[0], 2e12);
    QCOMPARE(find_measurement(s, "BM", "cache_misses")->unit, std::string(""));
    QCOMPARE(find_measurement(s, "BM", "real_time")->values[0], 2e-9);
  }

  void bad_time_unit_names_the_field() {
    try {
      bs::parse_google_benchmark_json(
          "{\"context\":{},\n\"benchmarks\":[{\"name\":\"a\",\"real_time\":1,\"cpu_time\":1,\"time_unit\":"
          "\"fortnights\"}]}",
          "g.json");
      QFAIL("accepted");
    } catch (const bs::ImportError& e) {
      QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
      QCOMPARE(e.location().field, std::string("/benchmarks/0/time_unit"));
      QCOMPARE(e.location().line, std::size_t{2});
    }
  }

  void structural_errors() {
    auto category = [](const std::string& text) {
      try {
        bs::parse_google_benchmark_json(text, "g.json");
      } catch (const bs::ImportError& e) {
        return e.category();
      }
      return bs::ImportErrorCategory::Io;
    };
    QCOMPARE(category("{\"context\":{}}"), bs::ImportErrorCategory::MissingField);
    QCOMPARE(category("{\"benchmarks\":[]}"), bs::ImportErrorCategory::MissingField);
    QCOMPARE(category("{\"context\":{},\"benchmarks\":[]}"), bs::ImportErrorCategory::InvalidValue);  // nothing
    QCOMPARE(category("{\"context\":{},\"benchmarks\":[{\"name\":\"a\",\"cpu_time\":1}]}"),
             bs::ImportErrorCategory::MissingField);
    QCOMPARE(category("{\"context\":{},\"benchmarks\":[{\"name\":\"a\",\"real_time\":-1,\"cpu_time\":1}]}"),
             bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(category("{\"context\":{},\"benchmarks\":[{\"name\":\"a\",\"real_time\":1e999,\"cpu_time\":1}]}"),
             bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(category("{\"context\":{},\"benchmarks\":[{\"name\":\"a\",\"run_type\":\"x\",\"real_time\":1,"
                      "\"cpu_time\":1}]}"),
             bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(category("{\"context\":{},\"benchmarks\":["), bs::ImportErrorCategory::Syntax);
  }

  // Real output of library v1.9.3 (SOURCES): 30 repetitions and their aggregates. The mean aggregate is the mean
  // of the 30 repetition rows: their real_time sum is 1903746.0999979884 us, / 30 = 63458.203333 us, as the file's
  // _mean row says; the sample SD of the 30 is 23701.5236 us, as its _stddev row says.
  void real_repetitions_v1_9_3() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kRealFolder);
    const auto batch = parse_real("spla-repetitions-v1.9.3.json");
    const bs::ResultSet& s = batch.result_sets.at(0);
    QCOMPARE(s.platform, std::string("LEGION"));
    QCOMPARE(s.device, std::string("CPU (12 x 2994 MHz)"));
    QCOMPARE(s.provenance.tool, std::string("google-benchmark v1.9.3"));
    QCOMPARE(
        setting(s.provenance, "caches"),
        std::string("L1 Data 32 KiB (x2), L1 Instruction 32 KiB (x2), L2 Unified 512 KiB (x2), L3 Unified 4 MiB (x6)"));
    QCOMPARE(setting(s.provenance, "num_cpus"), std::string("12"));
    QCOMPARE(setting(s.provenance, "library_build_type"), std::string("release"));
    QCOMPARE(setting(s.provenance, "executable"), std::string("bin\\spla-measure.exe"));
    QCOMPARE(setting(s.provenance, "workers from"), std::string("threads"));
    const std::string run = "Burkhardt/Amazon0302.txt/iterations:1";
    const auto* real = find_measurement(s, run, "real_time");
    QVERIFY(real);
    QCOMPARE(real->values.size(), std::size_t{30});
    QVERIFY(near(real->values[0], 31080.099999599042e-6));
    QVERIFY(near(aggregate(*real, "mean"), 63458.203333266283e-6));
    QCOMPARE(aggregate(*real, "repetitions"), 30.0);
    const auto summary = bs::summarize_measurement(*real);
    QVERIFY(summary);
    QCOMPARE(summary->n, std::size_t{30});
    QVERIFY(near(summary->mean, 63458.203333266283e-6));
    QVERIFY(near(summary->sd, 23701.523609235577e-6));
    QVERIFY(near(summary->min, 17028.600000230654e-6));  // repetition 2
    QVERIFY(near(summary->max, 117996.89999952534e-6));  // repetition 6
    QVERIFY(find_measurement(s, run, "triangles"));      // a user counter without a unit
    QVERIFY(batch.warnings.empty());
    QVERIFY(bs::foreign_sweeps(s).empty());  // no FLOP/s counter: nothing for the FLOPS view
  }

  // Real output of library v1.9.4 built as DEBUG (SOURCES): the importer repeats Google Benchmark's warning, and a
  // threads:1..32 sweep of items_per_second stays a throughput result (items are not FLOPs).
  void real_debug_build_threads_sweep_v1_9_4() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kRealFolder);
    const auto batch = parse_real("malloc-threads-debug-v1.9.4.json");
    QCOMPARE(batch.warnings.size(), std::size_t{1});
    QVERIFY(batch.warnings[0].find("***WARNING*** Library was built as DEBUG") != std::string::npos);
    QVERIFY(batch.warnings[0].find("malloc-threads-debug-v1.9.4.json:") != std::string::npos);
    QVERIFY(batch.warnings[0].find("/context/library_build_type") != std::string::npos);
    const bs::ResultSet& s = batch.result_sets.at(0);
    QCOMPARE(setting(s.provenance, "library_build_type"), std::string("debug"));
    QCOMPARE(setting(s.provenance, "load_avg"), std::string("24.8516 12.5483 7.1123"));
    // num_sharing 0 on this Mac: no "(x0)".
    QCOMPARE(setting(s.provenance, "caches"), std::string("L1 Data 64 KiB, L1 Instruction 128 KiB, L2 Unified 4 MiB"));
    const auto* items = find_measurement(s, "BM_AllocationThroughput/64/threads:32", "items_per_second");
    QVERIFY(items);
    QCOMPARE(items->unit, std::string("1/s"));
    QCOMPARE(items->values, std::vector<double>{1.0817681500412426e+06});
    QVERIFY(bs::foreign_sweeps(s).empty());
  }

  // Real output of library v1.9.1 (SOURCES): threads fields agree with the names; no FLOPS, no sweep.
  void real_threads_sweep_v1_9_1() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kRealFolder);
    const auto batch = parse_real("proto-threads-v1.9.1.json");
    const bs::ResultSet& s = batch.result_sets.at(0);
    QCOMPARE(s.platform, std::string("liuly-PC-2024"));
    QCOMPARE(s.measurements.size(), std::size_t{36});  // 12 benchmarks x (real_time, cpu_time, bytes)
    QVERIFY(near(find_measurement(s, "BM_ConcurrentParseText/threads:20", "real_time")->values.at(0),
                 3.5429222517930748e-06));
    QVERIFY(s.provenance.note.find("scaling was on") != std::string::npos);
    QVERIFY(batch.warnings.empty());
  }

  // BM_Rotation/threads:1..8, 3 repetitions each. FLOPS per point, by hand from the repetitions:
  //   1: (9.0 + 9.2 + 8.8) / 3 = 9.0 G, SD sqrt((0 + 0.04 + 0.04) / 2) = 0.2 G
  //   2: (17.5 + 18 + 18.5) / 3 = 18 G, SD 0.5 G
  //   4: (30 + 30 + 36) / 3 = 32 G, SD sqrt((4 + 4 + 16) / 2) = sqrt(12) = 3.4641 G
  //   8: 33 G three times, SD 0
  // The peak is the highest mean, 33 G at 8 threads with n = 3 and SD 0, not the best repetition (36 G at 4).
  void threads_sweep_becomes_a_flops_run() {
    const auto batch = parse_file("rotation-threads-sweep.json");
    const bs::ResultSet& s = batch.result_sets.at(0);
    const std::vector<bs::FlopsRun> runs = bs::foreign_sweeps(s);
    QCOMPARE(runs.size(), std::size_t{1});
    const bs::FlopsRun& run = runs[0];
    QCOMPARE(run.platform, std::string("robot-nuc"));
    QCOMPARE(run.device, std::string("CPU (8 x 3500 MHz)"));
    QCOMPARE(run.device_kind, bs::DeviceKind::Cpu);
    QCOMPARE(run.kernel, std::string("google-benchmark"));
    QCOMPARE(run.variant, std::string("BM_Rotation (FLOPS)"));
    QCOMPARE(run.dims, 0);
    QCOMPARE(run.iterations, std::int64_t{0});
    QCOMPARE(run.provenance.tool, std::string("google-benchmark v1.8.3"));
    QVERIFY(bs::is_foreign_sweep(run));
    const auto curve = bs::flops_curve(run);
    QCOMPARE(curve.size(), std::size_t{4});
    const std::vector<std::int64_t> workers{1, 2, 4, 8};
    const std::vector<double> mean{9e9, 18e9, 32e9, 33e9}, sd{0.2e9, 0.5e9, std::sqrt(12.0) * 1e9, 0.0};
    for (std::size_t i = 0; i < 4; ++i) {
      QCOMPARE(curve[i].workers, workers[i]);
      QCOMPARE(curve[i].flops.n, std::size_t{3});
      QVERIFY(near(curve[i].flops.mean, mean[i]));
      QVERIFY(std::abs(curve[i].flops.sd - sd[i]) < 1e-6 * mean[i]);
    }
    QCOMPARE(curve[2].flops.max, 36e9);  // the best single repetition is kept as the range, not the peak
    const auto rows = bs::peak_table(runs);
    QCOMPARE(rows.size(), std::size_t{1});
    QVERIFY(near(rows[0].peak.flops, 33e9));
    QCOMPARE(rows[0].peak.workers, std::int64_t{8});
    QCOMPARE(rows[0].peak.at_peak.n, std::size_t{3});
    QCOMPARE(rows[0].peak.at_peak.sd, 0.0);
    for (const auto& m : s.measurements)
      if (m.unit == "FLOP/s") QVERIFY(bs::is_swept(s, m));
  }

  // --benchmark_context=benchscope_workers_argument=0: BM_RotationTasks/W/real_time is a sweep over W.
  // FLOPS 4.1, 8.0, 15.2, 14.9 G at W = 1, 2, 4, 8 (one repetition each): peak 15.2 G at 4.
  void argument_sweep_from_the_context_key() {
    const auto batch = parse_file("rotation-argument-sweep.json");
    const bs::ResultSet& s = batch.result_sets.at(0);
    QCOMPARE(setting(s.provenance, "workers from"), std::string("argument 0"));
    QCOMPARE(setting(s.provenance, "benchscope_workers_argument"), std::string("0"));
    const auto runs = bs::foreign_sweeps(s);
    QCOMPARE(runs.size(), std::size_t{1});
    QCOMPARE(runs[0].variant, std::string("BM_RotationTasks/*/real_time (FLOPS)"));
    QCOMPARE(runs[0].samples.size(), std::size_t{4});
    QCOMPARE(runs[0].samples[3].workers, std::int64_t{8});
    const auto peak = bs::find_peak(runs[0]);
    QVERIFY(peak && near(peak->flops, 15.2e9) && peak->workers == 4 && peak->at_peak.n == 1);
    // The caller's option wins over the file; argument 1 does not exist, so nothing is swept (with a warning).
    const std::string text = file_text(kData + "rotation-argument-sweep.json");
    bs::ParseOptions options;
    options.workers_argument = 1;
    const auto other = bs::parse_google_benchmark_json(text, "a.json", options);
    QCOMPARE(setting(other.result_sets[0].provenance, "workers from"), std::string("argument 1"));
    QVERIFY(bs::foreign_sweeps(other.result_sets[0]).empty());
    QCOMPARE(other.warnings.size(), std::size_t{4});
    QVERIFY(other.warnings[0].find("has no argument 1") != std::string::npos);
  }

  // Names to sweeps: threads:N, arguments, named arguments and Google Benchmark's own options.
  void sweep_points_from_names() {
    auto p = bs::sweep_point("BM_X/4096/real_time/threads:8", std::nullopt);
    QVERIFY(p && p->family == "BM_X/4096/real_time" && p->workers == 8);
    p = bs::sweep_point("BM_X/4096", std::nullopt);
    QVERIFY(p && p->family == "BM_X/4096" && p->workers == 1);
    p = bs::sweep_point("BM_X/iterations:10/4/repeats:3/size:16/real_time", 1);
    QVERIFY(p && p->family == "BM_X/iterations:10/4/repeats:3/size:*/real_time" && p->workers == 16);
    QVERIFY(!bs::sweep_point("BM_X/4/real_time", 1));  // no second argument
    QVERIFY(!bs::sweep_point("BM_X/0/real_time", 0));  // 0 workers is no worker count
    QVERIFY(!bs::sweep_point("BM_X/-2", 0));
    QVERIFY(!bs::sweep_point("BM_X/threads:x", std::nullopt));
  }

  // Aggregates only (--benchmark_report_aggregates_only): the point is the _mean aggregate, SD the _stddev one,
  // n the rows' repetitions. GFLOPS 8.1401 +- 0.021 over 5 repetitions at 4 threads.
  void aggregates_only_sweep_uses_mean_and_stddev() {
    const auto batch = parse_file("aggregates-only-nan.json");
    const auto runs = bs::foreign_sweeps(batch.result_sets.at(0));
    QCOMPARE(runs.size(), std::size_t{1});
    QCOMPARE(runs[0].variant, std::string("BM_RotateNeon/16384 (GFLOPS)"));
    const auto curve = bs::flops_curve(runs[0]);
    QCOMPARE(curve.size(), std::size_t{1});
    QCOMPARE(curve[0].workers, std::int64_t{4});
    QCOMPARE(curve[0].flops.n, std::size_t{5});
    QVERIFY(near(curve[0].flops.mean, 8.1401e9));
    QVERIFY(near(curve[0].flops.sd, 0.021e9));
  }

  // A file with repetitions and a FLOPS counter but no threads: one point at 1 worker, the mean of the file's
  // _mean row (2.9612 + 2.9565 + 2.9255) / 3 = 2.94773e10, its _stddev 1.9e8 and n = 3; the best repetition
  // (2.9612e10) is no longer the peak.
  void repetitions_peak_is_the_mean_not_the_best() {
    const auto batch = parse_file("rotation-repetitions.json");
    const auto runs = bs::foreign_sweeps(batch.result_sets.at(0));
    QCOMPARE(runs.size(), std::size_t{1});
    const auto peak = bs::find_peak(runs[0]);
    QVERIFY(peak);
    QVERIFY(near(peak->flops, 2.9477e10));
    QVERIFY(near(peak->at_peak.sd, 1.9e8));
    QCOMPARE(peak->at_peak.n, std::size_t{3});
    QCOMPARE(peak->workers, std::int64_t{1});
  }

  void bad_iterations_threads_and_conflicts_name_the_field() {
    const std::string head = "\"name\":\"BM/threads:2\",\"run_type\":\"iteration\",\"real_time\":1,\"cpu_time\":1";
    auto e = error_of(with_rows({head + ",\"threads\":2,\"iterations\":-5"}));
    QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(e.location().field, std::string("/benchmarks/0/iterations"));
    QCOMPARE(e.location().line, std::size_t{3});
    e = error_of(with_rows({head + ",\"threads\":2,\"iterations\":5.5"}));
    QCOMPARE(e.category(), bs::ImportErrorCategory::WrongType);
    e = error_of(with_rows({head + ",\"threads\":2,\"iterations\":Infinity"}));
    QVERIFY(std::string(e.what()).find("not a finite number") != std::string::npos);
    e = error_of(with_rows({head + ",\"threads\":2,\"iterations\":1e30"}));
    QVERIFY(std::string(e.what()).find("out of range") != std::string::npos);
    e = error_of(with_rows({head + ",\"threads\":\"2\""}));
    QCOMPARE(e.category(), bs::ImportErrorCategory::WrongType);
    QCOMPARE(e.location().field, std::string("/benchmarks/0/threads"));
    e = error_of(with_rows({head + ",\"threads\":3"}));
    QVERIFY(std::string(e.what()).find("disagrees with the name") != std::string::npos);
    e = error_of(with_rows({head + ",\"threads\":0"}));
    QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
    // The same repetition twice with different data; the same row twice is skipped with a warning.
    const std::string rep0 = head + ",\"repetition_index\":0,\"FLOPS\":5";
    e = error_of(with_rows({rep0, head + ",\"repetition_index\":0,\"FLOPS\":6"}));
    QCOMPARE(e.location().field, std::string("/benchmarks/1"));
    QCOMPARE(e.location().line, std::size_t{4});
    QVERIFY(std::string(e.what()).find("e.json:3:1: /benchmarks/0") != std::string::npos);  // names the first row
    const auto twice = bs::parse_google_benchmark_json(with_rows({rep0, rep0}), "t.json");
    QCOMPARE(twice.result_sets[0].measurements.at(0).values.size(), std::size_t{1});
    QCOMPARE(twice.warnings.size(), std::size_t{1});
    QVERIFY(twice.warnings[0].find("t.json:4:1: /benchmarks/1") != std::string::npos);
    // One benchmark, two thread counts (rows of versions without repetition_index).
    const std::string plain = "\"name\":\"BM\",\"real_time\":1,\"cpu_time\":1,\"threads\":";
    e = error_of(with_rows({plain + "1", plain + "2"}));
    QVERIFY(std::string(e.what()).find("one benchmark has one thread count") != std::string::npos);
    // Duplicate keys in a row, different values.
    e = error_of(with_rows({head + ",\"threads\":2,\"FLOPS\":1,\"FLOPS\":2"}));
    QCOMPARE(e.location().field, std::string("/benchmarks/0/FLOPS"));
  }

  // items_per_second is a FLOP rate only when the context says an item is a FLOP (SetItemsProcessed(flops)).
  void items_are_flop_only_when_the_file_says_so() {
    const std::string rows =
        "\"benchmarks\":[{\"name\":\"BM/threads:2\",\"threads\":2,\"real_time\":1,\"cpu_time\":1,"
        "\"items_per_second\":3e9}]}";
    auto batch = bs::parse_google_benchmark_json("{\"context\":{\"benchscope_item\":\"flop\"}," + rows, "i.json");
    QCOMPARE(find_measurement(batch.result_sets[0], "BM/threads:2", "items_per_second")->unit, std::string("FLOP/s"));
    const auto runs = bs::foreign_sweeps(batch.result_sets[0]);
    QVERIFY(runs.size() == 1 && runs[0].samples.at(0).workers == 2 && runs[0].variant == "BM (items_per_second)");
    batch = bs::parse_google_benchmark_json("{\"context\":{}," + rows, "i.json");
    QCOMPARE(find_measurement(batch.result_sets[0], "BM/threads:2", "items_per_second")->unit, std::string("1/s"));
    QVERIFY(bs::foreign_sweeps(batch.result_sets[0]).empty());
    QCOMPARE(error_of("{\"context\":{\"benchscope_item\":\"byte\"}," + rows).location().field,
             std::string("/context/benchscope_item"));
  }

  // A NaN FLOPS counter is missing data: no point, never a 0 FLOPS point.
  void nan_flops_is_missing_not_zero() {
    const std::string row =
        "\"name\":\"BM/threads:%\",\"run_type\":\"iteration\",\"threads\":%,\"real_time\":1,"
        "\"cpu_time\":1,\"FLOPS\":";
    auto r = [&](const char* threads, const std::string& flops) {
      std::string s = row;
      for (auto at = s.find('%'); at != std::string::npos; at = s.find('%')) s.replace(at, 1, threads);
      return s + flops;
    };
    const auto batch =
        bs::parse_google_benchmark_json(with_rows({r("1", "2e9"), r("2", "NaN"), r("4", "7e9")}), "n.json");
    const auto runs = bs::foreign_sweeps(batch.result_sets.at(0));
    QCOMPARE(runs.size(), std::size_t{1});
    QCOMPARE(runs[0].samples.size(), std::size_t{2});
    QCOMPARE(runs[0].samples[1].workers, std::int64_t{4});
    QCOMPARE(batch.warnings.size(), std::size_t{1});
    QVERIFY(batch.warnings[0].find("missing data") != std::string::npos);
  }

  // Before version 1.5 rows had no run_type: "BM_X_mean" after rows "BM_X" is their aggregate.
  void aggregates_without_run_type() {
    const std::string r = "\"real_time\":2,\"cpu_time\":2,\"time_unit\":\"ns\",\"iterations\":";
    const auto batch = bs::parse_google_benchmark_json(
        with_rows({"\"name\":\"BM_X\"," + r + "10,\"FLOPS\":4", "\"name\":\"BM_X\"," + r + "10,\"FLOPS\":6",
                   "\"name\":\"BM_X_mean\"," + r + "2,\"FLOPS\":5",
                   "\"name\":\"BM_X_stddev\"," + r + "2,\"FLOPS\":1.4142"}),
        "o.json");
    const bs::ResultSet& s = batch.result_sets.at(0);
    QVERIFY(!find_measurement(s, "BM_X_mean", "FLOPS"));
    const auto* flops = find_measurement(s, "BM_X", "FLOPS");
    QVERIFY(flops && flops->values.size() == 2);
    QCOMPARE(aggregate(*flops, "mean"), 5.0);
    QCOMPARE(aggregate(*flops, "repetitions"), -1.0);  // not stated before 1.5: n is the repetition rows read
    QCOMPARE(aggregate(*flops, "stddev"), 1.4142);
    const auto summary = bs::summarize_measurement(*flops);
    QVERIFY(summary && summary->n == 2 && summary->mean == 5.0 && summary->sd == 1.4142);
  }

  // Real output of a 2016 library (SOURCES): no run_type, no run_name, no host_name, integer times, repetitions
  // as repeated names followed by "_mean" and "_stddev" rows whose iterations are the first repetition's (3, and
  // 0 for stddev), not n. By hand: (41035891 + 40545623 + 38841168) / 3 = 40140894 ns, the file's _mean; its
  // _stddev 940587 ns is the population SD of the three (sqrt(((894997)^2 + (404729)^2 + (1299726)^2) / 3)), as
  // the library computed it then; the sample SD would be 1151979 ns. BenchScope keeps the file's figure.
  void real_repetitions_2016_without_run_type() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kRealFolder);
    const auto batch = parse_real("blond-tc1-repetitions-2016.json");
    const bs::ResultSet& s = batch.result_sets.at(0);
    QCOMPARE(s.platform, std::string("unknown host"));
    QCOMPARE(s.device, std::string("CPU (8 x 3600 MHz)"));
    QCOMPARE(s.provenance.date, std::string("08/16/16 02:47:06"));
    QCOMPARE(s.provenance.tool, std::string("google-benchmark"));
    QCOMPARE(s.measurements.size(), std::size_t{16});  // 8 benchmarks x (real_time, cpu_time), no "_mean" ones
    const auto* real = find_measurement(s, "BM_TC1Acceleration/1000/1.95313k/10", "real_time");
    QVERIFY(real);
    QCOMPARE(real->values.size(), std::size_t{3});
    QVERIFY(near(aggregate(*real, "mean"), 40140894e-9));
    QVERIFY(near(aggregate(*real, "stddev"), 940587e-9));
    const auto summary = bs::summarize_measurement(*real);
    QVERIFY(summary && summary->n == 3 && near(summary->sd, 940587e-9));
    QVERIFY(batch.warnings.empty());
  }
};

QTEST_GUILESS_MAIN(TestGoogleBenchmarkJson)
#include "test_google_benchmark_json.moc"
