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

#include "../../support/sysfs_fixture.h"
#include "analysis/power/phase_energy.h"
#include "kernels/kernel_runner.h"
#include "main_window.h"
#include "power/power_sensor_box.h"
#include "power/power_view.h"

// A RAPL package whose counter a thread advances by 2,000 uJ plus 100 uJ for every 0.25 s since the start, once
// a millisecond: a staircase of at most 2 W, 2.1 W, 2.2 W, ... (less when the sleeps run long) that makes the sweep
// points' mean powers differ, with the counter wrapping at 3,000,000 uJ so the trace goes through wraparounds.
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
};

QTEST_MAIN(TestKernelRunnerPower)
#include "test_kernel_runner_power.moc"
