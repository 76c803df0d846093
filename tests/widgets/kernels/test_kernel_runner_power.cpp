// SPDX-License-Identifier: GPL-3.0-or-later
// The Kernel Runner recording power from a fixture sysfs tree: energy per sweep point shown, the trace with a phase
// per point stored in the run's import, drawn with its phases on the Power tab. scripts/screenshots runs it with
// BENCHSCOPE_SCREENSHOT_DIR set to collect docs/screenshots/kernel-runner-power.png and power-view-sweep-phases.png.
#include <QCoreApplication>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <atomic>
#include <cmath>
#include <thread>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProgressBar>

#include "../../support/cli_harness.h"
#include "../../support/sysfs_fixture.h"
#include "analysis/power/phase_energy.h"
#include "analysis/power/sweep_energy.h"
#include "kernels/kernel_runner.h"
#include "main_window.h"
#include "power/power_sensor_box.h"
#include "power/power_stats_panel.h"
#include "power/power_view.h"

// A RAPL package whose counter a thread advances by 2,000 uJ plus 100 uJ for every 0.25 s since the start, once
// a millisecond: a staircase of at most 2 W, 2.1 W, 2.2 W, ... (less when the sleeps run long) that makes the sweep
// points' mean powers differ, with the counter wrapping at 3,000,000 uJ so the trace goes through wraparounds.
class RaplStaircase {
 public:
  explicit RaplStaircase(const std::filesystem::path& root) : root_(root) {
    bs::test::rapl_package(root_, 0, 0, kMax);
    thread_ = std::thread([this] {
      // clock-ok: the fixture stands for a RAPL counter that advances with real time; no test bound uses the clock
      const auto t0 = std::chrono::steady_clock::now();
      long long counter = 0;
      while (!stop_) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        // clock-ok: as above, the simulated counter's rate; the assertions bound it by the trace's own times
        const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        counter = (counter + 2000 + 100 * static_cast<long long>(t / 0.25)) % kMax;
        bs::test::put(root_, "sys/class/powercap/intel-rapl:0/energy_uj", std::to_string(counter));
      }
    });
  }
  ~RaplStaircase() {
    stop_ = true;
    thread_.join();
  }

 private:
  static constexpr long long kMax = 3'000'000;
  std::filesystem::path root_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

class TestKernelRunnerPower : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    qputenv("BENCHSCOPE_NVML_LIBRARY", "none");  // the fixture's sensors only, whatever GPU this machine has
  }

  void sweep_recorded_with_power_from_a_fixture() {
    QTemporaryDir dir, sys;
    RaplStaircase rapl(sys.path().toStdString());
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(dir.filePath("w.bsw")));
    bs::ui::KernelRunner* runner = w.kernel_runner();
    runner->power_box()->set_sysfs_root(sys.path());
    QCOMPARE(runner->power_box()->count(), 3);  // off, auto, rapl:package-0
    QVERIFY(runner->power_box()->choose("auto"));
    runner->set_workers_spec("2048,4096,8192,16384");
    runner->set_dims("4");
    runner->set_iterations(200000);
    runner->set_repeats(3);
    QSignalSpy done(runner, &bs::ui::KernelRunner::finished);
    runner->start();
    QVERIFY(done.wait(120000));
    QCOMPARE(runner->energy_table()->rowCount(), 4);  // one row per point
    const auto traces = w.workspace()->power_traces();
    QCOMPARE(traces.size(), std::size_t{1});
    const bs::PowerTrace& t = traces[0].trace;
    QCOMPARE(t.provenance.measurement, bs::MeasurementKind::OnBoardSensor);
    QVERIFY(t.provenance.sensor.find("rapl:package-0") != std::string::npos);
    QCOMPARE(t.platform, w.workspace()->runs().at(0).run.platform);  // paired with the run
    QCOMPARE(t.phases.size(), std::size_t{5});                       // the warm-up and four points
    QCOMPARE(t.phases[0].name, std::string("warm-up D=4"));
    QCOMPARE(t.phases[4].name, std::string("point W=16384 D=4"));
    // The writer adds at most 2,000 uJ + 100 uJ per 0.25 s elapsed every millisecond (it sleeps at least 1 ms, more
    // on a loaded machine): no phase can show more than that rate at the end of the recording, and, wraps
    // included, none shows a negative or missing power.
    const double top = 2.0 + 0.1 * std::ceil(t.time_s.back() / 0.25) + 0.05;
    for (const bs::PhaseEnergy& e : bs::phase_energies(t))
      QVERIFY2(e.mean_power_w > 0 && e.mean_power_w < top, e.name.c_str());
    for (int r = 0; r < 4; ++r) QVERIFY(runner->energy_table()->item(r, 4)->text().toDouble() > 0);
    w.resize(1400, 900);
    w.show();
    for (QTabWidget* tabs : w.findChildren<QTabWidget*>())
      if (tabs->indexOf(w.power_view()) >= 0) tabs->setCurrentWidget(w.power_view());
    w.power_view()->set_quantity(bs::ui::PowerView::Quantity::Power);
    QTest::qWait(50);
    if (const QByteArray shots = qgetenv("BENCHSCOPE_SCREENSHOT_DIR"); !shots.isEmpty()) {
      runner->grab().save(QString::fromUtf8(shots) + "/kernel-runner-power.png", "PNG", 0);
      w.power_view()->grab().save(QString::fromUtf8(shots) + "/power-view-sweep-phases.png", "PNG", 0);
    }
  }

  void short_points_run_long_enough_and_agree_everywhere() {
    // Issue #32.4: points of a few milliseconds against a sensor sampled every 100 ms. Each point repeats its timed
    // work until it spans kMinSamplesPerPoint samples; the Kernel Runner, the Power tab's Phases table and
    // `benchscope-cli power --phases` then give the same energy and mean power for every point.
    QTemporaryDir dir, sys;
    RaplStaircase rapl(sys.path().toStdString());
    bs::ui::MainWindow w;
    const QString ws = dir.filePath("w.bsw");
    QVERIFY(w.open_workspace(ws));
    bs::ui::KernelRunner* runner = w.kernel_runner();
    runner->power_box()->set_sysfs_root(sys.path());
    QVERIFY(runner->power_box()->choose("auto"));
    runner->set_workers_spec("64,128");
    runner->set_dims("4");
    runner->set_iterations(2000);  // a timed run of a few ms at most: alone, a point would span 0 or 1 samples
    runner->set_repeats(2);
    QSignalSpy done(runner, &bs::ui::KernelRunner::finished);
    runner->start();
    QVERIFY(done.wait(120000));
    const auto runs = w.workspace()->runs();
    QCOMPARE(runs.size(), std::size_t{1});
    const auto traces = w.workspace()->power_traces();
    QCOMPARE(traces.size(), std::size_t{1});
    const auto points = bs::sweep_point_energies(traces[0].trace, {runs[0].run});
    QCOMPARE(points.size(), std::size_t{2});
    for (const bs::PointEnergy& p : points) {
      QVERIFY2(p.samples >= bs::kMinSamplesPerPoint, qPrintable(QString::number(p.samples)));
      QVERIFY(!p.too_short());
      QVERIFY(p.runs > 2);  // the timed work repeated beyond the two asked for; every timing is one run
    }
    // The Kernel Runner's table: unmarked, n >= 10.
    QTableWidget* kr = runner->energy_table();
    QCOMPARE(kr->rowCount(), 2);
    for (int r = 0; r < 2; ++r) {
      QVERIFY2(!kr->item(r, 7)->text().contains("n <"), qPrintable(kr->item(r, 7)->text()));
      QVERIFY(kr->item(r, 7)->text().toInt() >= 10);
    }
    // The Power tab's Phases table, same rows.
    w.power_view()->set_quantity(bs::ui::PowerView::Quantity::Power);
    w.power_view()->set_detected_phases(false);
    const QStringList lines = w.power_view()->phase_panel()->tsv().split('\n', Qt::SkipEmptyParts);
    const QStringList head = lines.value(0).split('\t');
    const int energy_col = static_cast<int>(head.indexOf("energy (J)")),
              mean_col = static_cast<int>(head.indexOf("mean power (W)")), n_col = static_cast<int>(head.indexOf("n"));
    QVERIFY(energy_col > 0 && mean_col > 0 && n_col > 0);
    // The CLI on the same workspace.
    const bs::test::CliResult cli = bs::test::cli({"power", ws, "--phases", "--json"});
    QCOMPARE(cli.code, 0);
    const QJsonArray cli_phases =
        QJsonDocument::fromJson(cli.out).object()["traces"].toArray().at(0).toObject()["phases"].toArray();
    for (int r = 0; r < 2; ++r) {
      const QString name =
          QString::fromStdString(bs::sweep_point_phase(points[static_cast<std::size_t>(r)].workers, 4));
      const QString kr_energy = kr->item(r, 4)->text(), kr_mean = kr->item(r, 3)->text();
      bool in_table = false;
      for (const QString& line : lines) {
        const QStringList cells = line.split('\t');
        if (cells.value(0) != name) continue;
        in_table = true;
        QCOMPARE(cells.value(energy_col), kr_energy);
        QCOMPARE(cells.value(mean_col), kr_mean);
        QVERIFY2(!cells.value(n_col).contains("n <"), qPrintable(cells.value(n_col)));
      }
      QVERIFY2(in_table, qPrintable(name));
      bool in_cli = false;
      for (const QJsonValue& v : cli_phases) {
        const QJsonObject o = v.toObject();
        if (o["name"].toString() != name) continue;
        in_cli = true;
        QCOMPARE(QString::number(o["energy_j"].toDouble(), 'f', 4), kr_energy);
        QCOMPARE(QString::number(o["mean_power_w"].toDouble(), 'f', 4), kr_mean);
        QVERIFY(o["n"].toInt() >= 10);
      }
      QVERIFY2(in_cli, qPrintable(name));
    }
  }

  void cancelled_sweep_keeps_its_progress() {
    // Issue #32.8: Cancel leaves the bar where the sweep stopped, saying so, instead of jumping to 100 %.
    bs::ui::KernelRunner runner;
    runner.set_workers_spec("1:4096:1");
    runner.set_dims("4");
    runner.set_iterations(200000);
    runner.set_repeats(1);
    QSignalSpy done(&runner, &bs::ui::KernelRunner::finished);
    QSignalSpy live(&runner, &bs::ui::KernelRunner::live_run);
    runner.start();
    QVERIFY(live.wait(60000));  // a point done
    runner.cancel();
    QVERIFY(done.wait(60000));
    QVERIFY(done.at(0).at(1).toBool());  // cancelled
    QVERIFY(runner.progress_bar()->value() < 1000);
    QVERIFY(runner.progress_bar()->text().startsWith("cancelled at"));
    // Issue #32.8: the sweep's parameters come back in the next session's Kernel Runner.
    const bs::ui::KernelRunner next;
    QCOMPARE(next.workers_spec(), QString("1:4096:1"));
  }
};

QTEST_MAIN(TestKernelRunnerPower)
#include "test_kernel_runner_power.moc"
