// SPDX-License-Identifier: GPL-3.0-or-later
// One way home for a result set measured in-process (#52): empirical ceilings (the Kernel Runner's Measure
// ceilings, `benchscope-cli devices --measure-ceilings`) and `run bandwidth`'s STREAM triad go home through
// measured_set_home, one import per device. The Kernel Runner hashed one device's date + note, the CLI the dates and
// notes of all the devices it measured in one import, so the CPU's ceilings stored by both were two imports.
#include <QTemporaryDir>
#include <QTest>

#include "../../support/home_checks.h"
#include "kernels/ceilings/bandwidth.h"
#include "kernels/ceilings/ceilings.h"
#include "kernels/measured_set_home.h"

using namespace bs;

namespace {

const std::string kRunner = "Kernel Runner: Measure ceilings";
const std::string kCli = "benchscope-cli devices --measure-ceilings";

// The CPU's ceilings as measure_ceilings returns them (two repetitions of each micro-kernel).
kernels::CeilingSet cpu_ceilings() {
  const kernels::CeilingSet c{.host = "robot-nuc",
                              .cpu_model = "Intel Core i7-8650U",
                              .backend = "CPU SIMD (AVX2+FMA)",
                              .isa = "avx2",
                              .threads = 8,
                              .clock_hz = 3.9e9,
                              .computed_peak_flops = 4.99e11,
                              .date = test::kHomeDate,
                              .rotation_mix = {"FLOP/s", {2.1e11, 2.2e11}, {2.6e10, 2.7e10}, "rotation mix: 6 chains"},
                              .fma = {"FLOP/s", {3.9e11, 4.0e11}, {4.9e10, 5.0e10}, "fma: 10 accumulators"},
                              .bandwidth = {"B/s", {2.4e10, 2.5e10}, {3.0e9, 3.1e9}, "triad: 3 x 64 MiB"}};
  return c;
}

// An OpenCL GPU's, measured by the same `devices --measure-ceilings` within the same second: timed on the device
// (no per-CPU-second figures, no thread count), without a triad.
kernels::CeilingSet device_ceilings() {
  const kernels::CeilingSet c{.host = "robot-nuc",
                              .cpu_model = "Intel UHD Graphics 620",
                              .backend = "OpenCL",
                              .isa = "opencl",
                              .kind = DeviceKind::Gpu,
                              .computed_peak_flops = 4.2e11,
                              .date = test::kHomeDate,
                              .rotation_mix = {"FLOP/s", {3.1e11, 3.2e11}, {}, "rotation mix: device"},
                              .fma = {"FLOP/s", {3.8e11, 3.9e11}, {}, "fma: device"},
                              .bandwidth = {}};
  return c;
}

}  // namespace

class TestMeasuredSetHome : public QObject {
  Q_OBJECT
 private slots:
  void the_kernel_runner_and_devices_measure_ceilings_store_one_import() {
    test::same_measurement_is_one_import(measured_set_home(kernels::ceiling_result_set(cpu_ceilings()), kRunner),
                                         measured_set_home(kernels::ceiling_result_set(cpu_ceilings()), kCli));
  }

  // The CLI measures the CPU and every device at once and stores one import per device (in one transaction), so
  // each device's ceilings are the import the Kernel Runner would store for that device, and it is refused there.
  void ceilings_the_cli_stored_are_refused_from_the_kernel_runner() {
    QTemporaryDir dir;
    Workspace ws(dir.filePath("w.bsw").toStdString());
    const std::vector<HomeBatch> cli = {measured_set_home(kernels::ceiling_result_set(cpu_ceilings()), kCli),
                                        measured_set_home(kernels::ceiling_result_set(device_ceilings()), kCli)};
    QCOMPARE(bring_home(ws, cli).size(), std::size_t{2});
    for (const kernels::CeilingSet& c : {cpu_ceilings(), device_ceilings()})
      QVERIFY_THROWS_EXCEPTION(WorkspaceError,
                               bring_home(ws, measured_set_home(kernels::ceiling_result_set(c), kRunner)));
    QCOMPARE(ws.imports().size(), std::size_t{2});
    QCOMPARE(ws.result_sets().size(), std::size_t{2});
  }

  void the_batch_holds_the_set_and_its_values_make_the_hash() {
    const HomeBatch home = measured_set_home(kernels::ceiling_result_set(cpu_ceilings()), kRunner);
    QCOMPARE(home.batch.format, std::string(kCeilingSource));
    QCOMPARE(home.batch.source_path, kRunner + " (robot-nuc, 2026-12-06T10:00:00Z)");
    QCOMPARE(home.batch.result_sets.size(), std::size_t{1});
    QCOMPARE(home.batch.result_sets[0].device, std::string("Intel Core i7-8650U"));
    QCOMPARE(home.batch.result_sets[0].measurements.size(), std::size_t{3});
    QVERIFY(home.batch.power_traces.empty());
    // Another measurement with the same date and settings (date + note, the old recipe, were equal) is another
    // import.
    kernels::CeilingSet other = cpu_ceilings();
    other.fma.values[1] = 4.1e11;
    QVERIFY(measured_set_home(kernels::ceiling_result_set(other), kRunner).content_hash != home.content_hash);
  }

  void a_bandwidth_set_goes_home_in_its_own_format() {
    const ResultSet set{"robot-nuc",
                        "Intel Core i7-8650U",
                        DeviceKind::Cpu,
                        "CPU SIMD (AVX2)",
                        kernels::kBandwidthSource,
                        {{"stream-triad/64MiB", kernels::kBandwidthMetric, "B/s", {2.4e10, 2.5e10}, {}}},
                        test::measured_on_robot()};
    const HomeBatch home = measured_set_home(set, "benchscope-cli run bandwidth");
    QCOMPARE(home.batch.format, std::string(kernels::kBandwidthSource));
    QCOMPARE(home.batch.source_path, std::string("benchscope-cli run bandwidth (robot-nuc, 2026-12-06T10:00:00Z)"));
    test::same_measurement_is_one_import(home, measured_set_home(set, "benchscope-cli run bandwidth"));
  }
};

QTEST_APPLESS_MAIN(TestMeasuredSetHome)
#include "test_measured_set_home.moc"
