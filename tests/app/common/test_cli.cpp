// SPDX-License-Identifier: GPL-3.0-or-later
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <map>

#include "../../support/cli_harness.h"

namespace {

using Result = bs::test::CliResult;
using bs::test::bytes_of;
using bs::test::cli;
using bs::test::kPaper;

// Finds the peak row for (device, backend, dims); fails the test when absent.
QJsonObject row(const QJsonArray& rows, const QString& device, const QString& backend, int dims) {
  for (const auto& v : rows) {
    const QJsonObject o = v.toObject();
    if (o["device"].toString() == device && o["backend"].toString() == backend && o["dims"].toInt() == dims) return o;
  }
  return {};
}

double rounded(double v, double unit) { return std::round(v / unit * 100.0) / 100.0; }

}  // namespace

class TestCli : public QObject {
  Q_OBJECT
 private slots:
  void version_help_and_unknown() {
    QCOMPARE(cli({"--version"}).code, 0);
    QVERIFY(cli({"--version"}).out.startsWith("benchscope-cli "));
    const Result help = cli({"help"});
    QCOMPARE(help.code, 0);
    QVERIFY(help.out.contains("import") && help.out.contains("peaks"));
    QCOMPARE(cli({"help", "peaks"}).code, 0);
    QCOMPARE(cli({"frobnicate"}).code, 2);
    QCOMPARE(cli({}).code, 2);
    QCOMPARE(cli({"peaks", "--no-such-option", kPaper}).code, 2);
  }

  void peaks_reproduce_tables_1_and_2_data() {
    QTest::addColumn<bool>("via_workspace");
    QTest::newRow("files") << false;
    QTest::newRow("workspace") << true;
  }
  void peaks_reproduce_tables_1_and_2() {
    QFETCH(bool, via_workspace);
    QTemporaryDir dir;
    QString source = kPaper;
    if (via_workspace) {
      source = dir.filePath("paper.bsw");
      QCOMPARE(cli({"import", source, kPaper, "--quiet"}).code, 0);
    }
    const Result r = cli({"peaks", source, "--json"});
    QCOMPARE(r.code, 0);
    const QJsonObject doc = QJsonDocument::fromJson(r.out).object();
    QCOMPARE(doc["format"].toString(), QString("benchscope-peaks"));
    QCOMPARE(doc["version"].toInt(), 1);
    const QJsonArray rows = doc["rows"].toArray();
    const double T = 1e12, G = 1e9;
    struct Expect {
      const char* device;
      const char* backend;
      int dims;
      double peak, unit;
      double reported;  // 0: none
    };
    // Table 1 (TFLOPS: OpenCL / CUDA / reported) and Table 2 (GFLOPS).
    const Expect table[] = {
        {"GTX1080Ti", "OpenCL", 4, 9.14, T, 10.61},
        {"GTX1080Ti", "CUDA", 4, 9.34, T, 10.61},
        {"NUC GPU (Iris Plus 650)", "OpenCL", 4, 5.25, T, 0.88},
        {"Intel HD Graphics 630", "OpenCL", 4, 2.40, T, 0.44},
        {"Jetson GPU (Pascal, 256 cores)", "CUDA", 4, 0.49, T, 0.75},
        {"i7-7800X", "CPU SIMD (AVX/SSE)", 4, 49.68, G, 0},
        {"i7-7920HQ", "CPU SIMD (AVX/SSE)", 4, 29.33, G, 0},
        {"NUC CPU (i7-7567U)", "CPU SIMD (AVX/SSE)", 4, 15.54, G, 0},
        {"Jetson CPU (ARM A57 + Denver2)", "CPU SIMD (NEON)", 4, 4.69, G, 0},
    };
    for (const Expect& e : table) {
      const QJsonObject o = row(rows, e.device, e.backend, e.dims);
      QVERIFY2(!o.isEmpty(), e.device);
      QCOMPARE(rounded(o["peak_flops"].toDouble(), e.unit), e.peak);
      QCOMPARE(o["origin"].toString(), QString("reconstructed"));
      if (e.reported > 0) {
        QCOMPARE(rounded(o["reported_flops"].toDouble(), e.unit), e.reported);
        QVERIFY(std::abs(o["ratio_to_reported"].toDouble() - o["peak_flops"].toDouble() / (e.reported * e.unit)) <
                1e-9);
      } else {
        QVERIFY(o["reported_flops"].isNull());
      }
    }
    // Figure 1b's extra curves: D = 1, 2 for the NUC and Jetson GPUs.
    QCOMPARE(rows.size(), 13);
    QVERIFY(!row(rows, "NUC GPU (Iris Plus 650)", "OpenCL", 1).isEmpty());
    QVERIFY(!row(rows, "Jetson GPU (Pascal, 256 cores)", "CUDA", 2).isEmpty());
    // The human table shows the same numbers with units.
    const Result human = cli({"peaks", source});
    QVERIFY(human.out.contains("9.34 TFLOPS") && human.out.contains("15.54 GFLOPS") && human.out.contains("5.97x"));

    // Plausibility: the NUC GPU's 5.25 TFLOPS is 5.944x the Iris Plus 650's 883.2 GFLOPS (48 EUs x 16 x 1.15 GHz),
    // above 1.3x: flagged with the likely causes. The GTX 1080 Ti's 9.14 TFLOPS is 0.806 of 11.34: not flagged.
    const QJsonObject nuc = row(rows, "NUC GPU (Iris Plus 650)", "OpenCL", 4);
    QCOMPARE(nuc["spec"].toObject()["id"].toString(), QString("intel-iris-plus-650"));
    QCOMPARE(nuc["spec"].toObject()["fp32_peak_flops"].toDouble(), 883.2e9);
    QVERIFY(std::abs(nuc["fraction_of_spec"].toDouble() - 5.944) < 0.001);
    const QJsonArray flags = nuc["flags"].toArray();
    QCOMPARE(flags.size(), 1);
    QCOMPARE(flags[0].toObject()["code"].toString(), QString("above_spec_peak"));
    const QString why = flags[0].toObject()["reason"].toString();
    QVERIFY2(why.contains("compiler") && why.contains("asynchronous") && why.contains("5.9x"), qPrintable(why));
    const QJsonObject gtx = row(rows, "GTX1080Ti", "OpenCL", 4);
    QCOMPARE(gtx["flags"].toArray().size(), 0);
    QVERIFY(std::abs(gtx["fraction_of_spec"].toDouble() - 0.806) < 0.001);
    QCOMPARE(doc["device_table"].toObject()["error"].toString(), QString());
    QVERIFY(doc["device_table"].toObject()["devices"].toInt() >= 45);
    // The text table marks the row and prints the reason under the table.
    QVERIFY(human.out.contains("] above_spec_peak: 5.25 TFLOPS is 5.9x the Intel Iris Plus Graphics 650"));
  }

  void bad_files_fail_cleanly_and_leave_the_workspace_unchanged_data() {
    QTest::addColumn<QByteArray>("content");
    QTest::newRow("empty") << QByteArray();
    QTest::newRow("truncated") << QByteArray(
        "{\"format\": \"benchscope-run\", \"version\": 1, \"runs\": [{\"platform\"");
    QTest::newRow("nan") << QByteArray(
        "{\"format\":\"benchscope-run\",\"version\":1,\"runs\":[{\"platform\":\"p\",\"device\":\"d\",\"backend\":\"b\","
        "\"params\":{\"iterations\":1,\"dims\":1},\"samples\":[{\"workers\":1,\"seconds\":[NaN]}]}]}");
    QTest::newRow("wrong types") << QByteArray(
        "{\"format\":\"benchscope-run\",\"version\":1,\"runs\":[{\"platform\":\"p\",\"device\":\"d\",\"backend\":\"b\","
        "\"params\":{\"iterations\":\"many\",\"dims\":1},\"samples\":[{\"workers\":1,\"seconds\":[1]}]}]}");
    QByteArray binary;
    for (int i = 0; i < 1000; ++i) binary.append(static_cast<char>(i * 7));
    QTest::newRow("binary") << binary;
  }
  void bad_files_fail_cleanly_and_leave_the_workspace_unchanged() {
    QFETCH(QByteArray, content);
    QTemporaryDir dir;
    const QString bad = dir.filePath("bad-input.json");
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(content);
    f.close();
    // A workspace that does not exist must still not exist afterwards.
    const QString fresh = dir.filePath("fresh.bsw");
    Result r = cli({"import", fresh, bad});
    QCOMPARE(r.code, 1);
    QVERIFY(!QFile::exists(fresh));
    const QList<QByteArray> lines = r.err.trimmed().split('\n');
    QCOMPARE(lines.size(), 1);  // one line per failed file, nothing else on stderr
    QVERIFY2(lines[0].contains("bad-input.json"), r.err.constData());
    QVERIFY(lines[0].startsWith("benchscope-cli: error: "));
    // An existing workspace keeps its bytes.
    const QString ws = dir.filePath("existing.bsw");
    QCOMPARE(cli({"import", ws, kPaper + "/cpu.json", "--quiet"}).code, 0);
    const QByteArray before = bytes_of(ws);
    r = cli({"import", ws, bad});
    QCOMPARE(r.code, 1);
    QCOMPARE(bytes_of(ws), before);
  }

  void run_flops_writes_a_measured_run() {
    QTemporaryDir dir;
    const QString json = dir.filePath("run.json"), ws = dir.filePath("w.bsw");
    const Result r = cli({"run", "flops", "--workers", "1,4,16", "--points", "1,4", "--iterations", "500", "--repeats",
                          "2", "--out", json, "--workspace", ws, "--quiet"});
    QCOMPARE(r.code, 0);
    QVERIFY(r.out.contains("D = 4: peak") && r.out.contains("% of"));
    const QJsonArray rows = QJsonDocument::fromJson(cli({"peaks", json, "--json"}).out).object()["rows"].toArray();
    QCOMPARE(rows.size(), 2);
    QCOMPARE(rows[0].toObject()["origin"].toString(), QString("measured"));
    QCOMPARE(rows[0].toObject()["n"].toInt(), 2);
    QVERIFY(rows[0].toObject()["fraction_of_theoretical"].toDouble() > 0);
    QCOMPARE(QJsonDocument::fromJson(cli({"peaks", ws, "--json"}).out).object()["rows"].toArray().size(), 2);
    QCOMPARE(cli({"run", "flops", "--workers", "10:1:1"}).code, 2);
    QCOMPARE(cli({"run", "flops", "--backend", "fpga"}).code, 2);
    QCOMPARE(cli({"devices", "--json"}).code, 0);
    if (QJsonDocument::fromJson(cli({"devices", "--json"}).out).object()["devices"].toArray().size() > 2) {
      const Result ocl = cli({"run", "flops", "--backend", "opencl", "--workers", "1,8", "--iterations", "300",
                              "--repeats", "1", "--quiet"});
      QCOMPARE(ocl.code, 0);
      QVERIFY(ocl.out.contains("OpenCL, D = 4: peak"));
    }
  }

  // devices --measure-ceilings measures every OpenCL device's ceilings beside the CPU's (PoCL's CPU device here, a
  // GPU where there is one), caches them under the device, stores them in a workspace, and plain `devices` then
  // shows them from the cache.
  void devices_measure_and_cache_device_ceilings() {
    const QJsonArray listed = QJsonDocument::fromJson(cli({"devices", "--json"}).out).object()["devices"].toArray();
    QString opencl;
    for (const auto& v : listed)
      if (v.toObject()["backend"].toString().startsWith("opencl")) opencl = v.toObject()["backend"].toString();
    if (opencl.isEmpty()) QSKIP("no OpenCL device here");
    QTemporaryDir dir;
    qputenv("BENCHSCOPE_CACHE_DIR", dir.path().toUtf8());
    const Result measured = cli({"devices", "--measure-ceilings", "--json", "--workspace", dir.filePath("w.bsw")});
    QCOMPARE(measured.code, 0);
    QJsonObject entry;
    for (const auto& v : QJsonDocument::fromJson(measured.out).object()["devices"].toArray())
      if (v.toObject()["backend"].toString() == opencl) entry = v.toObject();
    const QJsonObject c = entry["empirical_ceilings"].toObject();
    QCOMPARE(c["isa"].toString(), QString("opencl"));
    QCOMPARE(c["threads"].toInt(), 0);
    for (const char* k : {"rotation_mix", "fma", "bandwidth"}) {
      QVERIFY2(c[k].toObject()["mean"].toDouble() > 0, k);
      QVERIFY2(c[k].toObject()["per_cpu_second_mean"].isNull(), k);  // timed on the device
    }
    const Result cached = cli({"devices"});
    QCOMPARE(cached.code, 0);
    const QString text = QString::fromUtf8(cached.out);
    const qsizetype at = text.indexOf(opencl + ":");
    QVERIFY2(at >= 0 && text.indexOf("empirical ceilings (cached", at) > at, qPrintable(text));
    QVERIFY(text.indexOf("device memory bandwidth ceiling", at) > at);
    QVERIFY(QFile::exists(dir.filePath("ceilings.json")));
    qunsetenv("BENCHSCOPE_CACHE_DIR");
  }

  // devices --table marks a value no source confirmed with a trailing '?' and lists the fields.
  void device_table_marks_unverified_values() {
    const Result r = cli({"devices", "--table"});
    QCOMPARE(r.code, 0);
    const QString out = QString::fromUtf8(r.out);
    const auto entry = [&](const char* id) {
      const qsizetype at = out.indexOf(QString(id) + " (");
      const qsizetype next = out.indexOf(QRegularExpression("\\n\\S"), at + 1);
      return at < 0 ? QString() : out.mid(at, next - at);
    };
    const QString tx2 = entry("nvidia-jetson-tx2-gpu");
    QVERIFY2(tx2.contains("GB/s?") && tx2.contains("unverified: memory_bandwidth_bytes_per_s"), qPrintable(tx2));
    QVERIFY2(!tx2.contains("FLOPS?") && !tx2.contains("W?"), qPrintable(tx2));
    const QString nuc = entry("intel-iris-plus-650");
    QVERIFY2(!nuc.isEmpty() && !nuc.contains('?') && !nuc.contains("unverified"), qPrintable(nuc));
    const QString ti = entry("nvidia-rtx-3080-ti");
    QVERIFY2(ti.contains("FLOPS?") && ti.contains("W?"), qPrintable(ti));
    const QJsonArray devices =
        QJsonDocument::fromJson(cli({"devices", "--table", "--json"}).out).object()["devices"].toArray();
    for (const auto& v : devices)
      if (v.toObject()["id"].toString() == "nvidia-rtx-3080-ti")
        QVERIFY(v.toObject()["unverified"].toArray().contains(QJsonValue("tdp_w")));
  }

  void power_efficiency_and_battery_reproduce_the_paper() {
    QTemporaryDir dir;
    const QString ws = dir.filePath("paper.bsw");
    QCOMPARE(cli({"import", ws, kPaper, "--quiet"}).code, 0);
    const QJsonArray traces = QJsonDocument::fromJson(cli({"power", ws, "--json"}).out).object()["traces"].toArray();
    QCOMPARE(traces.size(), 2);
    for (const auto& v : traces) {
      const QJsonObject t = v.toObject();
      const double w = t["power_w"].toObject()["mean"].toDouble();
      QCOMPARE(rounded(w, 1.0), t["platform"].toString() == "NUC" ? 40.52 : 9.48);
      QCOMPARE(t["origin"].toString(), QString("reconstructed"));
    }
    const QJsonArray eff =
        QJsonDocument::fromJson(cli({"efficiency", ws, "--json"}).out).object()["platforms"].toArray();
    QCOMPARE(eff.size(), 2);
    for (const auto& v : eff) {
      const QJsonObject e = v.toObject();
      QCOMPARE(rounded(e["flops_per_watt_paper"].toDouble(), 1e9), e["platform"].toString() == "NUC" ? 104.64 : 41.26);
    }
    const Result nuc = cli({"battery", "--power-log", kPaper + "/power/nuc-current.csv", "--json"});
    QCOMPARE(nuc.code, 0);
    QCOMPARE(rounded(QJsonDocument::fromJson(nuc.out).object()["runtime_min"].toDouble(), 1.0), 84.36);
    const Result jetson = cli(
        {"battery", "--volts", "14.8", "--capacity-mah", "3850", "--power-log", kPaper + "/power/jetson-current.csv"});
    QVERIFY2(jetson.out.contains("360.48 min"), jetson.out.constData());
    QCOMPARE(cli({"battery", "--watts", "0"}).code, 2);
    QCOMPARE(cli({"battery"}).code, 2);
    QCOMPARE(cli({"power", kPaper + "/cpu.json"}).code, 1);  // no power logs there
  }

  // battery --workspace: per-platform runtimes (the GUI's Battery tab), presets saved in the workspace and used
  // by --preset afterwards, only there.
  void battery_per_platform_and_workspace_presets() {
    QTemporaryDir dir;
    const QString ws = dir.filePath("paper.bsw");
    QCOMPARE(cli({"import", ws, kPaper, "--quiet"}).code, 0);
    const auto minutes = [](const Result& r) {
      std::map<QString, double> out;
      for (const auto& v : QJsonDocument::fromJson(r.out).object()["platforms"].toArray())
        out[v.toObject()["platform"].toString()] = v.toObject()["runtime_min"].toDouble();
      return out;
    };
    const Result paper = cli({"battery", "--workspace", ws, "--json"});
    QCOMPARE(paper.code, 0);
    QCOMPARE(rounded(minutes(paper)["NUC"], 1.0), 84.36);
    QCOMPARE(rounded(minutes(paper)["Jetson TX2"], 1.0), 360.48);
    const Result saved = cli({"battery", "--workspace", ws, "--capacity-mah", "5000", "--dod", "0.8", "--extra-load",
                              "60", "--save-preset", "robot pack", "--json"});
    QCOMPARE(saved.code, 0);
    QVERIFY(saved.err.contains("saved battery preset 'robot pack'"));
    // The saved preset's pack, depth of discharge and extra load come back as the defaults.
    const Result robot = cli({"battery", "--workspace", ws, "--preset", "robot pack", "--json"});
    QCOMPARE(robot.code, 0);
    QCOMPARE(minutes(robot)["NUC"], minutes(saved)["NUC"]);
    QVERIFY(std::abs(minutes(robot)["NUC"] - 14.8 * 5.0 * 0.8 / (40.524 + 60) * 60) < 0.01);
    const Result given = cli({"battery", "--workspace", ws, "--preset", "robot pack", "--watts", "10", "--json"});
    QCOMPARE(given.code, 0);
    QVERIFY(std::abs(QJsonDocument::fromJson(given.out).object()["runtime_min"].toDouble() -
                     14.8 * 5.0 * 0.8 / 70 * 60) < 1e-6);
    QCOMPARE(cli({"battery", "--preset", "robot pack", "--watts", "10"}).code, 2);  // not a built-in
    QCOMPARE(cli({"battery", "--workspace", dir.filePath("missing.bsw")}).code, 2);
    QCOMPARE(cli({"battery", "--save-preset", "x", "--watts", "10"}).code, 2);
    QCOMPARE(cli({"battery", "--workspace", ws, "--mission", "walk:x:10"}).code, 2);
  }

  void bench_decimate_prints_figures() {
    const Result r = cli({"bench", "decimate", "--samples", "100000", "--columns", "100", "--runs", "1"});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains("-> 200 points"), r.out.constData());
    QVERIFY(r.out.contains("plain min/max scan"));
  }

  void synth_frame_writes_raw_sidecar_and_truth() {
    QTemporaryDir dir;
    const QString prefix = dir.filePath("frames/chart");
    const Result r = cli({"synth-frame", "--out", prefix, "--size", "128x96", "--bits", "12", "--pattern", "RGGB"});
    QCOMPARE(r.code, 0);
    QCOMPARE(QFileInfo(prefix + ".raw").size(), qint64{128 * 96 * 2});  // 16-bit words
    const QJsonObject side = QJsonDocument::fromJson(bytes_of(prefix + ".json")).object();
    QCOMPARE(side["width"].toInt(), 128);
    QCOMPARE(side["pattern"].toString(), QString("RGGB"));
    QCOMPARE(side["bit_depth"].toInt(), 12);
    QCOMPARE(side["synthetic"].toBool(), true);
    QVERIFY(QFileInfo::exists(prefix + "-truth.png"));
    QCOMPARE(cli({"synth-frame", "--out", prefix, "--bits", "9"}).code, 2);
    QCOMPARE(cli({"synth-frame", "--out", prefix, "--size", "huge"}).code, 2);
  }

  void folder_duplicates_and_keep_going() {
    QTemporaryDir dir;
    const QString ws = dir.filePath("w.bsw");
    Result r = cli({"import", ws, kPaper});
    QCOMPARE(r.code, 0);
    QCOMPARE(r.out.count("imported "), 10);  // 5 run files + 2 current logs + 2 pipeline timing files + the capture
    QVERIFY2(r.out.contains("paper-capture.raw: frame 1280x1024 BGGR 8-bit synthetic"), r.out.constData());
    QCOMPARE(r.out.count("1 pipeline run (benchscope-pipeline-v1)"), 2);
    QVERIFY(r.out.contains("skipped") && r.out.contains("README.md"));  // not a data file
    r = cli({"import", ws, kPaper + "/cpu.json"});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains("already imported on 20") && r.out.contains("(skipped)"), r.out.constData());
    QVERIFY(!r.out.contains("imported " + kPaper.toUtf8()));
    QFile bad(dir.filePath("bad.json"));
    QVERIFY(bad.open(QIODevice::WriteOnly));
    bad.write("{\"format\": \"benchscope-run\"");
    bad.close();
    QFile::copy(BENCHSCOPE_TEST_DATA_DIR "/importers/clpeak/gtx1080ti.txt", dir.filePath("clpeak.txt"));
    const QByteArray before = bytes_of(ws);
    r = cli({"import", ws, dir.filePath("bad.json"), dir.filePath("clpeak.txt")});
    QCOMPARE(r.code, 1);
    QVERIFY(!r.out.contains("imported " + dir.filePath("clpeak.txt").toUtf8()));  // all or nothing by default
    QCOMPARE(bytes_of(ws), before);
    QCOMPARE(r.err.trimmed().split('\n').size(), 1);
    r = cli({"import", ws, dir.filePath("bad.json"), dir.filePath("clpeak.txt"), "--keep-going"});
    QCOMPARE(r.code, 1);
    QVERIFY(r.out.contains("imported") && r.out.contains("clpeak.txt"));
    const QJsonObject doc = QJsonDocument::fromJson(cli({"peaks", ws, "--json"}).out).object();
    QCOMPARE(doc["throughput"].toArray().size(), 2);  // GTX 1080 Ti and PoCL from clpeak
    // Single precision by default: the GTX 1080 Ti's row is its float2 11461.23 GFLOPS, never a double or int row.
    const QJsonObject gtx = doc["throughput"].toArray()[0].toObject();
    QCOMPARE(gtx["precision"].toString(), QString("fp32"));
    QCOMPARE(gtx["metric"].toString(), QString("single-precision compute"));
    QCOMPARE(gtx["value"].toDouble(), 11461.23e9);
    QCOMPARE(doc["rows"].toArray().size(), 13);
  }
};

QTEST_GUILESS_MAIN(TestCli)
#include "test_cli.moc"
