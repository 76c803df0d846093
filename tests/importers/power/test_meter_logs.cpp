// SPDX-License-Identifier: GPL-3.0-or-later
// Logs of measuring tools: nvidia-smi --query-gpu CSV, perf stat RAPL energy and SPEC PTDaemon (MLPerf spl.txt).
// The real files (third-party: the shared folder's tests/data/power/real, SOURCES there; those functions skip
// without it) are checked against hand arithmetic; small inline logs pin the rules (units, missing samples, several
// GPUs, intervals, locales, marks, broken input).
#include <QFile>
#include <QTest>

#include <cmath>

#include "analysis/power/power.h"
#include "analysis/power/power_stats.h"
#include "power/nvidia_smi.h"
#include "power/perf_stat.h"
#include "power/power_import.h"
#include "power/ptd_log.h"
#include "workspace/registry.h"

#include "../../support/find_item.h"
#include "../../support/import_errors.h"
#include "../../support/public_data.h"

namespace {

const std::string kReal = bs::test::public_data("tests/data/power/real/");

// What each log format refuses a text with (the file name only labels the error).
const auto smi_error_of = bs::test::import_errors_of(bs::kNvidiaSmiFileFormat, "x.csv");
const auto perf_error_of = bs::test::import_errors_of(bs::kPerfStatFileFormat, "x.csv");
const auto ptd_error_of = bs::test::import_errors_of(bs::kPtdLogFileFormat, "x.txt");

bool near(double a, double b, double tol = 1e-9) { return std::abs(a - b) <= tol; }

const bs::PowerChannel& channel(const bs::PowerTrace& t, const std::string& name) {
  return bs::test::item_of(t.channels, &bs::PowerChannel::name, name, "channel " + name);
}

}  // namespace

class TestMeterLogs : public QObject {
  Q_OBJECT
 private slots:
  // --- nvidia-smi -------------------------------------------------------------------------------------------
  void nvidia_smi_two_columns_real() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA("tests/data/power/real");
    const auto b = bs::import_file(kReal + "nvidia-smi-flame-2col.csv", bs::CancelToken{});
    QCOMPARE(b.format, std::string("nvidia-smi"));  // beats the generic power CSV on "timestamp, power.draw [W]"
    QCOMPARE(b.power_traces.size(), std::size_t{1});
    const bs::PowerTrace& t = b.power_traces[0];
    QCOMPARE(t.start_time, std::string("2024-10-30T18:42:33.189"));
    QCOMPARE(t.total_channel, std::string("power.draw"));
    QCOMPARE(t.provenance.measurement, bs::MeasurementKind::OnBoardSensor);
    QCOMPARE(t.provenance.sensor, std::string("NVML (nvidia-smi)"));
    QCOMPARE(t.time_s.size(), std::size_t{11});
    // 18:42:33.189 .. 18:42:33.692: 0.503 s.
    QVERIFY(near(t.time_s.back(), 0.503, 1e-6));
    // Mean by hand: 22.89 + 2 x 22.73 + 4 x 23.00 + 2 x 22.67 + 2 x 22.60 = 250.89 W; / 11 = 22.8082 W.
    const auto stats = bs::trace_stats(t);
    QVERIFY(near(stats.power_w->mean, 250.89 / 11, 1e-9));
    // Energy: trapezoids of 0.050-0.051 s between the samples; first step (22.89 + 22.73) / 2 x 0.050 = 1.1405 J;
    // all ten sum to 11.4757 J (about the mean 22.81 W x 0.503 s = 11.47 J).
    QVERIFY(near(stats.energy_j, 11.47565, 1e-4));
  }
  void nvidia_smi_named_gpu_real() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA("tests/data/power/real");
    const auto b = bs::import_file(kReal + "nvidia-smi-fletcher-gtx1650.csv", bs::CancelToken{});
    QCOMPARE(b.format, std::string("nvidia-smi"));
    const bs::PowerTrace& t = b.power_traces.at(0);
    QCOMPARE(b.power_traces.size(), std::size_t{1});  // one uuid: one GPU
    QCOMPARE(t.provenance.gpu_model, std::string("NVIDIA GeForce GTX 1650"));
    QCOMPARE(t.channels.size(), std::size_t{1});
    // 9 x 19.46 W + 3 x 19.89 W = 175.14 + 59.67 = 234.81 W over 12 rows: 19.5675 W.
    QVERIFY(near(bs::trace_stats(t).power_w->mean, 19.5675, 1e-9));
    QVERIFY(near(t.time_s.back(), 0.129, 1e-6));  // 03:33:31.779 .. 03:33:31.908
    QCOMPARE(b.warnings.size(), std::size_t{1});  // pstate, memory.*, utilization.*, power.management
    QVERIFY(b.warnings[0].find("pstate") != std::string::npos);
    // temperature.gpu is read since #53: the GPU's temperature beside its power (every row says 50).
    QVERIFY(b.warnings[0].find("temperature.gpu") == std::string::npos);
    QCOMPARE(b.sustain_runs.size(), std::size_t{1});
    QCOMPARE(b.sustain_runs[0].temperatures.at(0).celsius, std::vector<double>(12, 50.0));
  }
  void nvidia_smi_interleaved_gpus_and_missing_samples() {
    const auto b = bs::kNvidiaSmiFileFormat.parse_text(
        "timestamp, name, pci.bus_id, power.draw [W], power.limit [W], utilization.gpu [%]\n"
        "2023/10/05 14:31:02.123, NVIDIA A100-SXM4-40GB, 00000000:07:00.0, 285.43 W, 400.00 W, 97 %\n"
        "2023/10/05 14:31:02.125, NVIDIA A100-SXM4-40GB, 00000000:0F:00.0, [N/A], 400.00 W, 0 %\n"
        "2023/10/05 14:31:03.124, NVIDIA A100-SXM4-40GB, 00000000:07:00.0, 290.57 W, 400.00 W, 98 %\n"
        "2023/10/05 14:31:03.126, NVIDIA A100-SXM4-40GB, 00000000:0F:00.0, [Not Supported], 400.00 W, 0 %\n",
        "smi.csv");
    QCOMPARE(b.power_traces.size(), std::size_t{2});
    const bs::PowerTrace& a = b.power_traces[0];
    // Named by the GPU's name (issue #32.8), with the bus id because both GPUs share it.
    QCOMPARE(a.label, std::string("smi.csv NVIDIA A100-SXM4-40GB (00000000:07:00.0)"));
    QCOMPARE(a.channels[0].values, (std::vector<double>{285.43, 290.57}));
    QVERIFY(near(a.time_s[1], 1.001, 1e-6));
    QCOMPARE(a.provenance.settings.at(0), (std::pair<std::string, std::string>("power.limit", "400.00 W")));
    const bs::PowerTrace& c = b.power_traces[1];
    QCOMPARE(c.start_time, std::string("2023-10-05T14:31:02.125"));
    QVERIFY(std::isnan(c.channels[0].values[0]) && std::isnan(c.channels[0].values[1]));  // never 0 W
    QVERIFY(std::any_of(b.warnings.begin(), b.warnings.end(),
                        [](const std::string& w) { return w.find("2 power readings") != std::string::npos; }));
    // Issue #32.5: n counts the readings present: 2 for the first GPU, none for the second (2 rows each).
    QCOMPARE(bs::power_stats(a).n, std::size_t{2});
    QCOMPARE(bs::power_stats(c).n, std::size_t{0});
  }
  void nvidia_smi_n_counts_readings_not_rows() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA("tests/data/power/real");
    // The real GTX 1650 log with two of its twelve power cells turned into "[N/A]": n = 10 of 12 rows, and the
    // mean over the ten (the log's own readings: 8 x 19.46 W + 2 x 19.89 W = 195.46 W).
    QFile f(QString::fromStdString(kReal + "nvidia-smi-fletcher-gtx1650.csv"));
    QVERIFY(f.open(QIODevice::ReadOnly));
    QList<QByteArray> lines = f.readAll().split('\n');
    // Rows 3 and 11 of the file (inside the log: the range of a log runs from its first reading to its last).
    QVERIFY(lines.size() > 11);
    QVERIFY(lines[2].endsWith("19.46 W") && lines[10].endsWith("19.89 W"));
    lines[2].replace("19.46 W", "[N/A]");
    lines[10].replace("19.89 W", "[N/A]");
    const auto b = bs::kNvidiaSmiFileFormat.parse_text(lines.join('\n').toStdString(), "smi-na.csv");
    const bs::PowerTrace& t = b.power_traces.at(0);
    QCOMPARE(t.label, std::string("smi-na.csv"));  // one GPU: the file's name
    const bs::PowerStats s = bs::power_stats(t);
    QCOMPARE(s.rows, std::size_t{12});
    QCOMPARE(s.n, std::size_t{10});
    QCOMPARE(s.power_w->summary.n, std::size_t{10});
    QVERIFY(near(s.power_w->summary.mean, (8 * 19.46 + 2 * 19.89) / 10, 1e-9));
  }
  void nvidia_smi_nounits_instant_and_average() {
    const auto b = bs::kNvidiaSmiFileFormat.parse_text(
        "timestamp, index, power.draw.average [W], power.draw.instant [W]\n"
        "2024/01/01 00:00:00.000, 0, 70.00, 71.50\n"
        "2024/01/01 00:00:00.500, 0, 72.00, 80.25\n",
        "n.csv");
    const bs::PowerTrace& t = b.power_traces.at(0);
    QCOMPARE(t.channels.size(), std::size_t{2});
    QCOMPARE(t.total_channel, std::string("power.draw.instant"));
    QCOMPARE(t.channels[0].name, std::string("power.draw.instant"));
    QCOMPARE(channel(t, "power.draw.instant").values[1], 80.25);
  }
  void nvidia_smi_noheader_inferred_only_when_safe() {
    const auto b = bs::kNvidiaSmiFileFormat.parse_text(
        "2024/10/13 03:33:31.779, NVIDIA GeForce GTX 1650, GPU-eced1bd8-b3e7-abfc-0555-6f654cee60a5, P0, 19.46 W\n"
        "2024/10/13 03:33:31.792, NVIDIA GeForce GTX 1650, GPU-eced1bd8-b3e7-abfc-0555-6f654cee60a5, P0, 19.89 W\n",
        "nh.csv");
    QCOMPARE(b.power_traces.at(0).channels[0].values, (std::vector<double>{19.46, 19.89}));
    QCOMPARE(b.power_traces.at(0).provenance.gpu_model, std::string("NVIDIA GeForce GTX 1650"));
    // Two columns in W (power.draw and power.limit?) or none (nounits): the error says to keep the header.
    for (const char* text : {"2024/10/13 03:33:31.779, 19.46 W, 75.00 W\n", "2024/10/13 03:33:31.779, 0, 19.46\n"}) {
      const auto e = smi_error_of(text);
      QCOMPARE(e.category(), bs::ImportErrorCategory::MissingField);
      QVERIFY2(e.reason().find("keep the header") != std::string::npos, e.what());
    }
  }
  void nvidia_smi_broken_logs() {
    // No timestamp: the -l interval is not in the file.
    auto e = smi_error_of("power.draw [W]\n20.0 W\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::MissingField);
    QVERIFY(e.reason().find("timestamp") != std::string::npos);
    e = smi_error_of(
        "timestamp, power.draw [W]\n2024/01/01 00:00:01.000, 20 W\n"
        "2024/01/01 00:00:00.000, 20 W\n2024/01/01 00:00:02.000, 20 W\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(e.location().line, std::size_t{3});
    e = smi_error_of(
        "timestamp, power.draw [W]\n2024/01/01 00:00:01.000, lots W\n"
        "2024/01/01 00:00:02.000, 20 W\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(e.location().field, std::string("power.draw"));
    e = smi_error_of("timestamp, power.draw [kW]\n2024/01/01 00:00:01.000, 1\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::Unsupported);
    // A cut-off last line and a repeated header are skipped with warnings.
    const auto b = bs::kNvidiaSmiFileFormat.parse_text(
        "timestamp, power.draw [W]\n2024/01/01 00:00:00.000, 20 W\n"
        "timestamp, power.draw [W]\n2024/01/01 00:00:01.000, 22 W\n2024/01/01 00:0",
        "x.csv");
    QCOMPARE(b.power_traces.at(0).time_s.size(), std::size_t{2});
    QCOMPARE(b.warnings.size(), std::size_t{2});
  }

  // --- perf stat RAPL ---------------------------------------------------------------------------------------
  void perf_summary_real_with_program_output() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA("tests/data/power/real");
    // Compiler warnings of the measured build come first; cycles, instructions and MiB events are not energy.
    const auto b = bs::import_file(kReal + "perf-rapl-validation-gcc-papi.txt", bs::CancelToken{});
    QCOMPARE(b.format, std::string("perf-stat-rapl"));
    const bs::PowerTrace& t = b.power_traces.at(0);
    QCOMPARE(t.channels.size(), std::size_t{3});
    QCOMPARE(t.total_channel, std::string("pkg"));
    QCOMPARE(t.provenance.sensor, std::string("RAPL (perf stat)"));
    QCOMPARE(t.time_s, (std::vector<double>{0.0, 10.709146172}));
    // 271.49 J / 10.709146172 s = 25.3512 W; cores 193.94 J -> 18.1098 W; ram 11.83 J -> 1.10466 W.
    QVERIFY(near(channel(t, "pkg").values[0], 271.49 / 10.709146172));
    QVERIFY(near(channel(t, "pkg").values[0], 25.3512, 1e-4));
    QVERIFY(near(channel(t, "ram").values[1], 1.10466, 1e-5));
    // The two-sample trace integrates back to perf's energy.
    QVERIFY(near(bs::trace_stats(t).energy_j, 271.49, 1e-9));
  }
  void perf_summary_real_issue_thread() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA("tests/data/power/real");
    const auto b = bs::import_file(kReal + "perf-sandmark-378-human.txt", bs::CancelToken{});
    QCOMPARE(b.format, std::string("perf-stat-rapl"));
    // 43.26 J over 1.001041336 s = 43.215 W.
    QVERIFY(near(b.power_traces.at(0).channels.at(0).values[0], 43.215, 1e-3));
  }
  void perf_interval_csv_real() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA("tests/data/power/real");
    const auto b = bs::import_file(kReal + "perf-rapl-validation-sleep-interval.csv", bs::CancelToken{});
    QCOMPARE(b.format, std::string("perf-stat-rapl"));
    const bs::PowerTrace& t = b.power_traces.at(0);
    // 5 intervals of -I 100 -> 10 samples: [0, 0.100360379], [0.100360379, 0.200796737], ...
    QCOMPARE(t.total_channel, std::string("pkg"));
    QCOMPARE(t.channels[0].name, std::string("pkg"));  // the total first, for readers of the first channel
    QCOMPARE(t.time_s.size(), std::size_t{10});
    // Issue #32.5: five readings of the package (pkg, cores, ram interleaved in the file), held over ten samples.
    QCOMPARE(bs::power_stats(t).n, std::size_t{5});
    QCOMPARE(bs::power_stats(t).rows, std::size_t{10});
    QCOMPARE(t.time_s[1], 0.100360379);
    QCOMPARE(t.time_s[2], 0.100360379);
    QCOMPARE(t.time_s[9], 0.501561575);
    const auto& pkg = channel(t, "pkg").values;
    // First interval: 0.911932 J / 0.100360379 s = 9.0866 W; second: 0.247253 J / (0.200796737 - 0.100360379 =
    // 0.100436358 s) = 2.4618 W; fifth: 1.144287 J / 0.100278978 s = 11.4110 W.
    QVERIFY(near(pkg[0], 9.086574, 1e-6) && pkg[0] == pkg[1]);
    QVERIFY(near(pkg[2], 2.461788, 1e-6));
    QVERIFY(near(pkg[9], 11.411036, 1e-6));
    // Energy = 0.911932 + 0.247253 + 0.490601 + 0.468811 + 1.144287 = 3.262884 J, exactly perf's sum.
    QVERIFY(near(bs::integrate_trapezoid(t.time_s, pkg), 3.262884, 1e-9));
    QVERIFY(near(bs::integrate_trapezoid(t.time_s, channel(t, "ram").values), 0.327454, 1e-9));
    // Statistics use pkg: energy 3.262884 J; sample mean (9.086574 + 2.461788 + 4.891924 + 4.678850 + 11.411036) / 5
    // = 6.506034 W (each interval's two samples weigh the same).
    const auto stats = bs::trace_stats(t);
    QVERIFY(near(stats.energy_j, 3.262884, 1e-9));
    QVERIFY(near(stats.power_w->mean, 6.506034, 1e-6));
  }
  void perf_interval_human_per_socket_and_not_counted() {
    const auto b = bs::kPerfStatFileFormat.parse_text(
        "# started on Sun Aug 24 12:00:00 2026\n\n"
        "#           time socket cpus             counts unit events\n"
        "     1.001048308 S0        1              19.63 Joules power/energy-pkg/\n"
        "     1.001048308 S1        1      <not counted> Joules power/energy-pkg/\n"
        "     2.002369058 S0        1              19.41 Joules power/energy-pkg/\n"
        "     2.002369058 S1        1              20.00 Joules power/energy-pkg/\n",
        "p.txt");
    const bs::PowerTrace& t = b.power_traces.at(0);
    QCOMPARE(t.start_time, std::string("2026-08-24T12:00:00"));
    QCOMPARE(t.total_channel, std::string("S0 pkg"));
    QVERIFY(near(channel(t, "S0 pkg").values[0], 19.63 / 1.001048308));
    QVERIFY(std::isnan(channel(t, "S1 pkg").values[0]));
    QVERIFY(near(channel(t, "S1 pkg").values[2], 20.00 / (2.002369058 - 1.001048308)));
    QCOMPARE(b.warnings.size(), std::size_t{2});  // two packages; one count not counted
  }
  void perf_summary_locale_psys_and_runs() {
    // Decimal comma with '.' grouping (a German locale), psys present: psys is the total.
    const auto b = bs::kPerfStatFileFormat.parse_text(
        " Performance counter stats for 'system wide' (5 runs):\n\n"
        "          1.373,00 Joules power/energy-pkg/                    ( +-  0,83% )\n"
        "          2.006,65 Joules power/energy-psys/\n\n"
        "      16,553457859 +- 0,000736 seconds time elapsed  ( +-  0,01% )\n",
        "de.txt");
    const bs::PowerTrace& t = b.power_traces.at(0);
    QCOMPARE(t.total_channel, std::string("psys"));
    QVERIFY(near(channel(t, "pkg").values[0], 1373.0 / 16.553457859));
    QVERIFY(near(channel(t, "psys").values[0], 2006.65 / 16.553457859));
    QCOMPARE(t.provenance.settings.at(0).second, std::string("5"));
    // A French locale groups thousands with a space: "5 005,68" is one number (the shape of a paste seen in a public
    // course repository; numbers as there).
    const auto fr = bs::kPerfStatFileFormat.parse_text(
        "         5 005,68 Joules power/energy-cores/\n"
        "          5 591,86 Joules power/energy-pkg/\n"
        "             34,22 Joules power/energy-gpu/\n"
        "287,542923380 seconds time elapsed\n",
        "fr.txt");
    QVERIFY(near(channel(fr.power_traces.at(0), "pkg").values[0], 5591.86 / 287.542923380));
    QVERIFY(near(channel(fr.power_traces.at(0), "gpu").values[0], 34.22 / 287.542923380));
    // Thousands grouping in the C locale, and two runs pasted one after the other: one trace each.
    const auto two = bs::kPerfStatFileFormat.parse_text(
        " Performance counter stats for 'system wide':\n  2,306.32 Joules power/energy-pkg/\n"
        "  277.955355190 seconds time elapsed\n"
        " Performance counter stats for 'system wide':\n  <not supported> Joules power/energy-pkg/\n"
        "  1.0 seconds time elapsed\n",
        "c.txt");
    QCOMPARE(two.power_traces.size(), std::size_t{2});
    QVERIFY(near(two.power_traces[0].channels[0].values[0], 2306.32 / 277.955355190));
    QVERIFY(std::isnan(two.power_traces[1].channels[0].values[0]));
    QCOMPARE(two.power_traces[1].label, std::string("c.txt #2"));
  }
  void perf_broken_outputs() {
    // -x without -I: energy but no elapsed time.
    auto e = perf_error_of("893.33,Joules,power/energy-pkg/,20005559241,100.00,,\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::MissingField);
    QVERIFY(e.reason().find("-I") != std::string::npos);
    // ... unless duration_time was counted: 893.33 J over 20.0 s.
    const auto d = bs::kPerfStatFileFormat.parse_text(
        "893.33,Joules,power/energy-pkg/,20005559241,100.00,,\n"
        "20000000000,ns,duration_time,20000000000,100.00,,\n",
        "d.csv");
    QVERIFY(near(d.power_traces.at(0).channels.at(0).values[0], 893.33 / 20.0));
    e = perf_error_of(
        " Performance counter stats for 'sleep 1':\n 1,990,524 cycles\n"
        " 1.0 seconds time elapsed\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::MissingField);
    e = perf_error_of("1.0,abc,Joules,power/energy-pkg/,1,100\n2.0,1,Joules,power/energy-pkg/,1,100\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(e.location().line, std::size_t{1});
    e = perf_error_of(
        "2.0,1,Joules,power/energy-pkg/,1,100\n1.0,1,Joules,power/energy-pkg/,1,100\n"
        "3.0,1,Joules,power/energy-pkg/,1,100\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(e.location().line, std::size_t{2});
  }

  // --- PTDaemon ---------------------------------------------------------------------------------------------
  void ptd_power_dev_example_real() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA("tests/data/power/real");
    const auto b = bs::import_file(kReal + "ptd-power-dev-example-spl.txt", bs::CancelToken{});
    QCOMPARE(b.format, std::string("ptdaemon"));  // beats the generic CSV, which would also see Time and Watts
    const bs::PowerTrace& t = b.power_traces.at(0);
    QCOMPARE(t.start_time, std::string("2020-12-23T10:21:51.496"));
    QCOMPARE(t.provenance.measurement, bs::MeasurementKind::ExternalMeter);
    QCOMPARE(t.total_channel, std::string("power"));
    QCOMPARE(t.channels.size(), std::size_t{3});
    QCOMPARE(channel(t, "voltage").values[0], 228.37);
    QCOMPARE(channel(t, "current").values[0], 0.20428);
    // 20 samples, Watts summing to 803.80 W: mean 40.19 W; 10:21:51.496 .. 10:22:10.507 = 19.011 s.
    const auto stats = bs::trace_stats(t);
    QVERIFY(near(stats.power_w->mean, 40.19, 1e-9));
    QVERIFY(near(t.time_s.back(), 19.011, 1e-6));
    // Trapezoids: first (23.43 + 33.52) / 2 x 1.009 s = 28.731 J; all 19: 771.70 J.
    QVERIFY(near(stats.energy_j, 771.7004, 1e-3));
    QCOMPARE(t.phases.size(), std::size_t{1});
    QCOMPARE(t.phases[0].name, std::string("testing-workload"));
    QVERIFY(near(t.phases[0].end_s, 19.011, 1e-6));
  }
  void ptd_jetson_xavier_real() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA("tests/data/power/real");
    const auto b = bs::import_file(kReal + "ptd-krai-xavier-run1-spl.txt", bs::CancelToken{});
    const bs::PowerTrace& t = b.power_traces.at(0);
    // 24 samples summing to 332.06 W: mean 13.8358 W; idle about 9.5-12 W, the load from 17:18:14 (26.57 W).
    QVERIFY(near(bs::trace_stats(t).power_w->mean, 332.06 / 24, 1e-9));
    QCOMPARE(t.phases.at(0).name, std::string("2021-02-26_17-06-42_testing"));
    QVERIFY(near(t.phases[0].end_s, 22.999, 1e-6));
    // #46: alone, a PTDaemon log has no LoadGen power window, and it is AC wall power: said, once.
    QCOMPARE(b.warnings.size(), std::size_t{1});
    QVERIFY(b.warnings[0].find("without LoadGen's power window") != std::string::npos);
    QVERIFY(b.warnings[0].find("AC wall power") != std::string::npos);
    QVERIFY(t.provenance.sensor.find("AC wall power") != std::string::npos);
  }
  void ptd_marks_channels_and_missing_readings() {
    const auto b = bs::kPtdLogFileFormat.parse_text(
        "Time,03-01-2021 "
        "09:00:00.000,Watts,-1.000000,Volts,230.0,Amps,0.1,PF,0.5,Mark,ranging,Ch1,Watts,10.0,Volts,230.0,Amps,0.05,PF,"
        "0.9\n"
        "Time,03-01-2021 "
        "09:00:01.000,Watts,20.0,Volts,230.0,Amps,0.1,PF,0.5,Mark,ranging,Ch1,Watts,11.0,Volts,230.0,Amps,0.05,PF,0.9\n"
        "02-26-2021 17:07:11.443: ERROR: Can't evaluate uncertainty of this sample!\n"
        "Time,03-01-2021 "
        "09:00:05.000,Watts,30.0,Volts,230.0,Amps,0.2,PF,0.5,Mark,testing,Ch1,Watts,12.0,Volts,230.0,Amps,0.05,PF,0.9\n"
        "Time,03-01-2021 "
        "09:00:06.500,Watts,31.0,Volts,230.0,Amps,0.2,PF,0.5,Mark,testing,Ch1,Watts,13.0,Volts,230.0,Amps,0.05,PF,0."
        "9\n",
        "spl.txt");
    const bs::PowerTrace& t = b.power_traces.at(0);
    QCOMPARE(t.channels.size(), std::size_t{6});
    QVERIFY(std::isnan(channel(t, "power").values[0]));
    QCOMPARE(channel(t, "Ch1 power").values[3], 13.0);
    QCOMPARE(t.phases.size(), std::size_t{2});
    QCOMPARE(t.phases[0].name, std::string("ranging"));
    QCOMPARE(t.phases[0].end_s, 1.0);
    QCOMPARE(t.phases[1].start_s, 5.0);
    QCOMPARE(t.phases[1].end_s, 6.5);
    QCOMPARE(b.warnings.size(), std::size_t{3});  // the PTDaemon message line; the -1 reading; no power window
  }
  void ptd_day_first_dates_and_errors() {
    // mlcommons/power-dev's README shows "28-12-2020": a first field above 12 can only be a day.
    const auto b = bs::kPtdLogFileFormat.parse_text(
        "Time,28-12-2020 15:21:14.682,Watts,22.95,Volts,228.57,Amps,0.20643,PF,0.4864,Mark,x\n"
        "Time,28-12-2020 15:21:15.686,Watts,23.08,Volts,228.44,Amps,0.20732,PF,0.4874,Mark,x\n",
        "dm.txt");
    QCOMPARE(b.power_traces.at(0).start_time, std::string("2020-12-28T15:21:14.682"));
    auto e = ptd_error_of(
        "Time,12-23-2020 10:21:52.000,Watts,1,Volts,1,Amps,1,PF,1,Mark,a\n"
        "Time,12-23-2020 10:21:51.000,Watts,1,Volts,1,Amps,1,PF,1,Mark,a\n"
        "Time,12-23-2020 10:21:53.000,Watts,1,Volts,1,Amps,1,PF,1,Mark,a\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(e.location().line, std::size_t{2});
    e = ptd_error_of(
        "Time,12-23-2020 10:21:52.000,Watts,x,Volts,1,Amps,1,PF,1,Mark,a\n"
        "Time,12-23-2020 10:21:53.000,Watts,1,Volts,1,Amps,1,PF,1,Mark,a\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(e.location().field, std::string("Watts"));
  }
  void power_command_reads_meter_logs() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA("tests/data/power/real");
    // benchscope-cli power goes through import_power_log: the meter formats are picked there too.
    QCOMPARE(bs::import_power_log(kReal + "ptd-power-dev-example-spl.txt").format, std::string("ptdaemon"));
    QCOMPARE(bs::import_power_log(kReal + "nvidia-smi-flame-2col.csv").format, std::string("nvidia-smi"));
    QCOMPARE(bs::import_power_log(kReal + "perf-rapl-validation-sleep-interval.csv").format,
             std::string("perf-stat-rapl"));
    // ... and the generic CSV keeps its own files.
    QCOMPARE(bs::import_power_log(BENCHSCOPE_TEST_DATA_DIR "/power/joulescope-export.csv").format,
             std::string("power-csv"));
  }
};

QTEST_APPLESS_MAIN(TestMeterLogs)
#include "test_meter_logs.moc"
