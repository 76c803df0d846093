// SPDX-License-Identifier: GPL-3.0-or-later
// The Kernel Runner as a user drives it: run a small sweep, watch it fill in, find it stored; cancel a long one.
#include <QApplication>
#include <QCoreApplication>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <QTabWidget>
#include <QTableWidget>
#include <atomic>
#include <cmath>
#include <thread>

#include "../support/sysfs_fixture.h"
#include "analysis/phase_energy.h"
#include "flops_plot.h"
#include "kernel_runner.h"
#include "main_window.h"
#include "power_sensor_box.h"
#include "power_view.h"
#include "workspace_tree.h"

class TestKernelRunner : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QCoreApplication::setOrganizationName("BenchScopeTest");
    QCoreApplication::setApplicationName("test_kernel_runner");
  }

  void sweep_fills_the_plot_and_lands_in_the_workspace() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(dir.filePath("w.bsw")));
    bs::ui::KernelRunner* runner = w.kernel_runner();
    runner->set_workers_spec("1,2,4,8");
    runner->set_dims("1,4");
    runner->set_iterations(500);
    runner->set_repeats(2);
    QSignalSpy live(runner, &bs::ui::KernelRunner::live_run);
    QSignalSpy done(runner, &bs::ui::KernelRunner::finished);
    runner->start();
    QVERIFY(runner->running());
    QVERIFY(done.wait(60000));
    QCOMPARE(live.count(), 8);  // one per completed point
    QCOMPARE(done.first().at(1).toBool(), false);
    QCOMPARE(w.workspace()->runs().size(), std::size_t{2});
    QCOMPARE(w.tree()->run_count(), 2);
    QCOMPARE(w.flops_plot()->series_count(), 2);
    const auto runs = w.workspace()->runs();
    QCOMPARE(runs[0].run.provenance.origin, bs::DataOrigin::Measured);
    QCOMPARE(runs[0].run.samples.size(), std::size_t{4});
    QCOMPARE(runs[0].run.samples[0].seconds.size(), std::size_t{2});
  }

  void cancel_keeps_the_completed_points() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(dir.filePath("w.bsw")));
    bs::ui::KernelRunner* runner = w.kernel_runner();
    runner->set_workers_spec("1:2000:1");  // far more than the test waits for
    runner->set_dims("4");
    runner->set_iterations(2000);
    runner->set_repeats(1);
    QSignalSpy done(runner, &bs::ui::KernelRunner::finished);
    connect(runner, &bs::ui::KernelRunner::live_run, runner, [runner](const bs::FlopsRun& run) {
      if (run.samples.size() == 3) runner->cancel();
    });
    runner->start();
    QVERIFY(done.wait(60000));
    QCOMPARE(done.first().at(1).toBool(), true);
    const auto runs = w.workspace()->runs();
    QCOMPARE(runs.size(), std::size_t{1});
    // The cancel reaches the sweep thread a little after the third point (the signal is queued), so a few more
    // points may complete, but never the whole sweep, and every kept point is a complete, valid timing.
    QVERIFY(runs[0].run.samples.size() >= 3);
    QVERIFY(runs[0].run.samples.size() < 2000);
    for (const auto& s : runs[0].run.samples) QVERIFY(s.seconds.size() == 1 && s.seconds[0] > 0);
  }
};

// A RAPL package whose counter a thread advances by 2,000 uJ every 1 ms plus 100 uJ per 1 ms for every 0.25 s
// since the start: a staircase 2 W, 2.1 W, 2.2 W, ... that makes each sweep point's mean power differ, with the
// counter wrapping at 3,000,000 uJ (about every 1.4 s) so the trace goes through wraparounds.
class RaplStaircase {
 public:
  explicit RaplStaircase(const std::filesystem::path& root) : root_(root) {
    bs::test::rapl_package(root_, 0, 0, kMax);
    thread_ = std::thread([this] {
      const auto t0 = std::chrono::steady_clock::now();
      long long counter = 0;
      while (!stop_) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
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
    QCoreApplication::setOrganizationName("BenchScopeTest");
    QCoreApplication::setApplicationName("test_kernel_runner");
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
    QCOMPARE(t.phases.size(), std::size_t{5});  // the warm-up and four points
    QCOMPARE(t.phases[0].name, std::string("warm-up D=4"));
    QCOMPARE(t.phases[4].name, std::string("point W=16384 D=4"));
    // The staircase starts at 2 W and climbs 0.1 W per 0.25 s: every point's mean power lies between 2 W and
    // what it reached by the end of the recording.
    const double top = 2.0 + 0.1 * std::ceil(t.time_s.back() / 0.25) + 0.3;
    for (const bs::PhaseEnergy& e : bs::phase_energies(t)) QVERIFY2(e.mean_power_w > 1.7 && e.mean_power_w < top, e.name.c_str());
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
};

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  int status = 0;
  {
    TestKernelRunner a;
    status |= QTest::qExec(&a, argc, argv);
  }
  {
    TestKernelRunnerPower b;
    status |= QTest::qExec(&b, argc, argv);
  }
  return status;
}
#include "test_kernel_runner.moc"
