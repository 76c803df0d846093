// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli sustain` as a user runs it (#53), event-driven: the test reads the process's JSON lines as they
// stream and acts when an interval at or after a set time arrives, never on a timer of its own.
//  - a fixture tree whose CPU clock drops from 3.0 to 1.8 GHz and whose zone climbs to 97 °C (trip 95 °C) once the
//    run reaches 10 s: throttling detected with its onset between 8 and 14 s;
//  - the "done when": stress-ng --cpu 2 started once the run reaches 20 s of 40: stability under 90 %, the
//    slowest interval after 20 s and, where the load alone held within 3 % (the stable threshold), the first slow
//    interval between 16 and 26 s (skipped without stress-ng, or when the machine was not quiet alone);
//  - a tree without clocks or zones says "unknown", never "no throttling"; the run is stored in a workspace.
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include <nlohmann/json.hpp>

#include "store/workspace.h"

#include "../../support/cli_harness.h"

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

void put(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

void write_cool_tree(const fs::path& root) {
  const fs::path cpu = root / "sys/devices/system/cpu/cpu0/cpufreq";
  put(cpu / "scaling_cur_freq", "3000000\n");
  put(cpu / "cpuinfo_max_freq", "3000000\n");
  const fs::path zone = root / "sys/class/thermal/thermal_zone0";
  put(zone / "type", "x86_pkg_temp\n");
  put(zone / "temp", "70000\n");
  put(zone / "trip_point_0_type", "passive\n");
  put(zone / "trip_point_0_temp", "95000\n");
}

struct Streamed {
  int code = -1;
  std::vector<json> lines;  // every JSON line of stdout, in order
  QByteArray err;
};

// Runs benchscope-cli ARGS, calling `on_interval` with each "interval" line as it arrives; returns once it exits.
Streamed stream(const QStringList& args, const std::function<void(const json&)>& on_interval) {
  Streamed s;
  QProcess p;
  QByteArray pending;
  QObject::connect(&p, &QProcess::readyReadStandardOutput, [&] {
    pending += p.readAllStandardOutput();
    for (qsizetype nl; (nl = pending.indexOf('\n')) >= 0;) {
      const QByteArray line = pending.left(nl);
      pending.remove(0, nl + 1);
      json j = json::parse(line.toStdString(), nullptr, false);
      if (j.is_discarded()) continue;
      if (j.value("type", "") == "interval") on_interval(j);
      s.lines.push_back(std::move(j));
    }
  });
  p.start(bs::test::kCli, args);
  if (!p.waitForFinished(600000)) {  // a hang, not a measurement: ctest's timeout bounds the test as well
    p.kill();
    p.waitForFinished();
    return s;
  }
  pending += p.readAllStandardOutput();
  if (!pending.trimmed().isEmpty()) {
    json j = json::parse(pending.toStdString(), nullptr, false);
    if (!j.is_discarded()) s.lines.push_back(std::move(j));
  }
  s.err = p.readAllStandardError();
  s.code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
  return s;
}

const json& result_of(const Streamed& s) {
  static const json none;
  return !s.lines.empty() && s.lines.back().value("type", "") == "result" ? s.lines.back() : none;
}

}  // namespace

class TestCliSustain : public QObject {
  Q_OBJECT
 private slots:
  void throttling_is_found_at_its_onset() {
    QTemporaryDir dir;
    const fs::path root = dir.path().toStdString();
    write_cool_tree(root);
    bool heated = false;
    std::size_t intervals_seen = 0;
    const Streamed s =
        stream({"sustain", "--load", "flops", "--seconds", "20", "--interval", "1", "--sysfs-root",
                QString::fromStdString(root.string()), "--json", "--workspace", dir.filePath("sustain.bsw")},
               [&](const json& line) {
                 ++intervals_seen;
                 if (heated || line.at("t_s").get<double>() < 10) return;
                 heated = true;  // the clock drops and the zone climbs past its trip point
                 put(root / "sys/devices/system/cpu/cpu0/cpufreq/scaling_cur_freq", "1800000\n");
                 put(root / "sys/class/thermal/thermal_zone0/temp", "97000\n");
               });
    QVERIFY2(s.code == 0, s.err.constData());
    QVERIFY(heated);
    QCOMPARE(intervals_seen, std::size_t{20});  // each interval streamed as it completed
    const json& r = result_of(s);
    QVERIFY2(r.is_object(), s.err.constData());
    QCOMPARE(r["intervals"].size(), std::size_t{20});
    QCOMPARE(r["rate_unit"].get<std::string>(), std::string("GFLOPS"));
    QVERIFY(r["peak_rate"].get<double>() > 0);
    QVERIFY(r["sustained_rate"].get<double>() > 0);
    const json& t = r["throttle"];
    QVERIFY(t["detected"].get<bool>());
    const double onset = t["onset_s"].get<double>();
    QVERIFY2(onset >= 8 && onset <= 14, std::to_string(onset).c_str());
    QCOMPARE(t["clock_at_onset"]["value"].get<double>(), 1.8e9);
    QCOMPARE(t["temperature_at_onset"]["value"].get<double>(), 97.0);
    QCOMPARE(t["what"].size(), std::size_t{2});
    QCOMPARE(r["intervals"][0]["clocks_hz"]["cpu0"].get<double>(), 3.0e9);
    // Stored: read back through the Workspace API, as the GUI will.
    bs::Workspace ws(dir.filePath("sustain.bsw").toStdString(), bs::Workspace::OpenMode::ReadOnly);
    const auto runs = ws.sustain_runs();
    QCOMPARE(runs.size(), std::size_t{1});
    QCOMPARE(runs[0].run.t_s.size(), std::size_t{20});
    QCOMPARE(runs[0].run.clocks[0].hz.back(), 1.8e9);
    QCOMPARE(*runs[0].run.temperatures[0].trip_c, 95.0);
  }

  void nothing_exposed_is_unknown() {
    QTemporaryDir dir;
    const bs::test::CliResult r =
        bs::test::cli({"sustain", "--load", "flops", "--seconds", "2", "--interval", "1", "--sysfs-root", dir.path()});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY2(r.out.contains("throttling:      unknown: no cpufreq"), r.out.constData());
    QVERIFY(r.out.contains("not exposed"));
    QVERIFY(!r.out.contains("throttling:      none"));
    QVERIFY(r.out.contains("GFLOPS"));
    QVERIFY(r.err.contains("sustain 1.0 s: "));  // the live line of the first interval
  }

  void a_bad_value_is_a_warning_not_a_crash() {
    QTemporaryDir dir;
    const fs::path root = dir.path().toStdString();
    write_cool_tree(root);
    put(root / "sys/class/thermal/thermal_zone0/temp", "99999999999999999999999999\n");
    const bs::test::CliResult r = bs::test::cli(
        {"sustain", "--load", "flops", "--seconds", "2", "--interval", "1", "--sysfs-root", dir.path(), "--json"});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY(r.err.contains("warning: thermal_zone0 x86_pkg_temp: /sys/class/thermal/thermal_zone0/temp: '9999"));
    const json last = json::parse(r.out.trimmed().split('\n').last().toStdString());
    QVERIFY(last["intervals"][0]["temperatures_c"]["thermal_zone0 x86_pkg_temp"].is_null());
  }

  void refusals_name_the_option() {
    const bs::test::CliResult r = bs::test::cli({"sustain", "--load", "flops:0", "--seconds", "2"});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains("--load"), r.err.constData());
  }

  void a_competing_load_lowers_stability_where_it_starts() {
    const QString stress = QStandardPaths::findExecutable("stress-ng");
    if (stress.isEmpty()) QSKIP("stress-ng is not installed");
    QProcess competitor;
    const Streamed s =
        stream({"sustain", "--load", "flops", "--seconds", "40", "--interval", "2", "--json"}, [&](const json& line) {
          if (competitor.state() != QProcess::NotRunning || line.at("t_s").get<double>() < 20) return;
          competitor.start(stress, {"--cpu", "2", "--timeout", "60", "--quiet"});
          competitor.waitForStarted();
        });
    const bool competed = competitor.state() != QProcess::NotRunning;
    competitor.terminate();
    competitor.waitForFinished();
    QVERIFY2(s.code == 0, s.err.constData());
    QVERIFY2(competed, "stress-ng did not start (or ended before the run did)");
    const json& r = result_of(s);
    QVERIFY2(r.is_object(), s.err.constData());
    // Every interval's (end, rate) as streamed.
    std::vector<std::pair<double, double>> rates;
    for (const json& line : s.lines)
      if (line.value("type", "") == "interval" && line.contains("rate") && line.at("rate").is_number())
        rates.emplace_back(line.at("t_s").get<double>(), line.at("rate").get<double>());
    // The claim needs a quiet machine before the competitor: a CI machine whose neighbour took half of it for the
    // first 20 s and then left (63 GFLOPS, then 146) measures the neighbour. Past the first interval (the load
    // settling), every interval before 20 s must lie within 15 % of their median, or there is nothing to test.
    std::vector<double> before;
    for (const auto& [t, rate] : rates)
      if (t > 2 && t < 20) before.push_back(rate);
    QVERIFY2(before.size() >= 5, s.err.constData());
    std::vector<double> sorted = before;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted[sorted.size() / 2];
    const QString unit = QString::fromStdString(r.value("rate_unit", ""));
    for (const double v : before)
      if (std::abs(v - median) > 0.15 * median)
        QSKIP(qPrintable(QString("the machine was not quiet before stress-ng started (%1 beside a median of %2 %3); "
                                 "the competing load cannot be told from it")
                             .arg(v)
                             .arg(median)
                             .arg(unit)));
    // And stress-ng must have taken something: a rate that rose as it started means the machine's other load left.
    double after_sum = 0;
    int after_n = 0;
    for (const auto& [t, rate] : rates)
      if (t >= 24) {
        after_sum += rate;
        ++after_n;
      }
    if (after_n > 0 && after_sum / after_n > median)
      QSKIP(qPrintable(QString("the rate rose as stress-ng started (%1 after, %2 before): the machine's other load "
                               "left then")
                           .arg(after_sum / after_n)
                           .arg(median)));
    // Nor may any interval after it run faster than the machine did alone: 56 GFLOPS for 20 s, then 83 as stress-ng
    // started (seen here, a virtual machine's neighbour leaving at that moment) measures the neighbour again.
    for (const auto& [t, rate] : rates)
      if (t >= 20 && rate > 1.15 * median)
        QSKIP(qPrintable(QString("an interval after stress-ng started ran faster than the machine alone (%1 at %2 s, "
                                 "%3 before): the machine's other load left then")
                             .arg(rate)
                             .arg(t)
                             .arg(median)));
    const double stability = r["stability_percent"].get<double>();
    QVERIFY2(stability < 90, std::to_string(stability).c_str());
    // Where the competitor started shows: the slowest interval is one of those after it (it started once the 20 s
    // interval arrived).
    const auto slowest =
        std::min_element(rates.begin(), rates.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
    QVERIFY2(slowest->first > 20, (std::to_string(slowest->first) + "\n" + s.err.toStdString()).c_str());
    // The first slow interval is the first below 97 % of the best (3DMark's stable threshold): it lands where the
    // competitor started only where the machine alone kept every interval within those 3 % (not under ASan's
    // noise here: 61.7 to 66.7 GFLOPS).
    if (sorted.front() < 0.97 * sorted.back()) {
      qInfo("first slow interval not checked: alone, the load ran from %.4g to %.4g %s (more than 3 %% apart)",
            sorted.front(), sorted.back(), qPrintable(unit));
      return;
    }
    const json& slow = r["first_slow"];
    QVERIFY2(slow.is_object(), s.err.constData());
    const double at = slow["end_s"].get<double>();
    QVERIFY2(at >= 16 && at <= 26, (std::to_string(at) + "\n" + s.err.toStdString()).c_str());
  }
};

QTEST_GUILESS_MAIN(TestCliSustain)
#include "test_cli_sustain.moc"
