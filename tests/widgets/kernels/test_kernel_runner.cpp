// SPDX-License-Identifier: GPL-3.0-or-later
// The Kernel Runner as a user drives it: run a small sweep, watch it fill in, find it stored; cancel a long one.
#include <QCoreApplication>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include "kernels/backends/backend_opencl.h"
#include "kernels/kernel_runner.h"
#include "main_window.h"
#include "peaks/flops_plot.h"
#include "workspace/workspace_tree.h"

class TestKernelRunner : public QObject {
  Q_OBJECT
 private slots:
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

  void fields_are_validated_as_typed() {
    bs::ui::KernelRunner runner;
    auto* workers = runner.findChildren<QLineEdit*>().at(0);
    QPushButton* run = nullptr;
    for (auto* b : runner.findChildren<QPushButton*>())
      if (b->text() == "Run") run = b;
    QVERIFY(run);
    QVERIFY(runner.input_error().isEmpty());
    QVERIFY(run->isEnabled());
    // Typed character by character, as a user does: the field turns red at once, naming itself and the reason.
    workers->clear();
    QTest::keyClicks(workers, "1,2,x");
    QVERIFY2(runner.input_error().startsWith("Workers:"), qPrintable(runner.input_error()));
    QVERIFY(workers->property("invalid").toBool());
    QVERIFY(!run->isEnabled());
    QTest::keyClick(workers, Qt::Key_Backspace);
    QTest::keyClicks(workers, "4");
    QVERIFY2(runner.input_error().isEmpty(), qPrintable(runner.input_error()));
    QVERIFY(!workers->property("invalid").toBool());
    QVERIFY(run->isEnabled());
    runner.set_dims("0");
    QVERIFY2(runner.input_error().startsWith("D:"), qPrintable(runner.input_error()));
    QVERIFY(!run->isEnabled());
    runner.set_dims("1,2");
    QVERIFY(run->isEnabled());
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

  // "Several robots…" with robots this desk cannot reach (their names do not resolve): each failure is said once at
  // the end, naming its robot, the queue goes on past the first to the second, and the runner is idle again.
  void a_robot_queue_goes_on_past_a_robot_that_fails() {
    bs::ui::KernelRunner runner;
    QSignalSpy failed(&runner, &bs::ui::KernelRunner::failed);
    QSignalSpy started(&runner, &bs::ui::KernelRunner::started);
    runner.start_on_robots({{"nosuch-a.invalid", "A"}, {"nosuch-b.invalid", "B"}});
    QVERIFY(runner.running());
    QVERIFY(failed.wait(60000));
    QCOMPARE(failed.count(), 1);
    const QString message = failed.first().first().toString();
    QVERIFY2(message.startsWith("nosuch-a.invalid: ") && message.contains("\n\nnosuch-b.invalid: "),
             qPrintable(message));
    QVERIFY(!runner.running());
    QCOMPARE(started.count(), 1);
    QVERIFY2(runner.remote_log()->text().startsWith("nosuch-b.invalid: "), qPrintable(runner.remote_log()->text()));
    QVERIFY(runner.progress_bar()->format().startsWith("nosuch-b.invalid (2 of 2)"));
  }

  // An OpenCL device's ceilings (PoCL's CPU device here; a GPU's on a machine with one): measured from the Kernel
  // Runner, shown with "timed on the device", cached for the next start; the scalar reference has none.
  void device_ceilings_are_measured_shown_and_cached() {
    if (const std::string why = bs::kernels::opencl_unavailable_reason(); !why.empty())
      QSKIP(qPrintable(QString::fromStdString(why)));
    QTemporaryDir cache;
    qputenv("BENCHSCOPE_CACHE_DIR", cache.path().toUtf8());
    bs::ui::KernelRunner runner;
    runner.select_backend("opencl:0");
    QVERIFY(runner.measure_ceilings_button()->isVisibleTo(&runner));
    QVERIFY2(runner.ceilings_label()->text().contains("No empirical ceiling measured for this device"),
             qPrintable(runner.ceilings_label()->text()));
    QSignalSpy measured(&runner, &bs::ui::KernelRunner::ceilings_measured);
    QSignalSpy failed(&runner, &bs::ui::KernelRunner::failed);
    runner.measure_ceilings();
    QVERIFY(runner.measuring_ceilings());
    QVERIFY(measured.wait(180000));
    QCOMPARE(failed.count(), 0);
    const bs::ResultSet set = measured.first().at(0).value<bs::ResultSet>();
    QCOMPARE(set.measurements.front().name, std::string("rotation-mix/opencl"));
    const bs::kernels::CeilingSet* c = runner.device_ceilings("opencl:0");
    QVERIFY(c && c->rotation_mix.measured() && c->bandwidth.measured());
    QVERIFY2(runner.ceilings_label()->text().contains("timed on the device"),
             qPrintable(runner.ceilings_label()->text()));
    QVERIFY(runner.ceilings_label()->toolTip().contains("OpenCL event profiling"));
    if (const QByteArray shots = qgetenv("BENCHSCOPE_SCREENSHOT_DIR"); !shots.isEmpty()) {
      runner.resize(560, 620);
      QVERIFY(runner.grab().save(QString::fromUtf8(shots) + "/kernel-runner-device-ceilings.png"));
    }
    bs::ui::KernelRunner again;  // a new start reads them from the cache, measuring nothing
    again.select_backend("opencl:0");
    QVERIFY(again.device_ceilings("opencl:0"));
    QVERIFY(again.ceilings_label()->text().contains("rotation mix"));
    runner.select_backend("cpu-scalar");
    QVERIFY(!runner.measure_ceilings_button()->isVisibleTo(&runner));
    QVERIFY(runner.ceilings_label()->text().contains("not for"));
    qunsetenv("BENCHSCOPE_CACHE_DIR");
  }
};

QTEST_MAIN(TestKernelRunner)
#include "test_kernel_runner.moc"
