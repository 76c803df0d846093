// SPDX-License-Identifier: GPL-3.0-or-later
// The Kernel Runner measuring on a robot over SSH (issue #44), driven in the real main window: the robot (this
// machine behind a real sshd on a local port, tests/support/ssh_robot.h) is chosen as the target and checked, the
// sweep's points are plotted live while it runs, and its results land in the workspace like a local run's, under
// the platform name typed, with the robot's provenance; a second run on the same robot is cancelled and brings
// its completed points. The Headroom and Pipeline tabs measure the control loop and the vision pipeline on the robot
// the same way. Screenshots at 1280x800
// and 1600x1000 go to $BENCHSCOPE_SCREENSHOT_DIR. CTest skip (77) without sshd.
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardItemModel>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <iostream>
#include <set>

#include "../../support/cli_harness.h"
#include "../../support/scenario_window.h"
#include "../../support/ssh_robot.h"
#include "headroom/headroom_run_panel.h"
#include "headroom/headroom_view.h"
#include "kernels/kernel_runner.h"
#include "main_window.h"
#include "peaks/flops_plot.h"
#include "remote/remote_run.h"
#include "remote/robot_queue_dialog.h"
#include "remote/robot_target.h"
#include "remote/robots.h"
#include "store/workspace.h"
#include "sustain/sustain_run_panel.h"
#include "sustain/sustain_view.h"
#include "vision/pipeline_measure_panel.h"
#include "vision/pipeline_view.h"
#include "workspace/workspace_tree.h"

namespace {

bs::test::SshRobot* g_robot = nullptr;

QPushButton* button(QWidget* parent, const QString& text) {
  for (QPushButton* b : parent->findChildren<QPushButton*>())
    if (b->text() == text) return b;
  return nullptr;
}

void screenshots(bs::ui::MainWindow& w, const QString& name) {
  const QByteArray dir = qgetenv("BENCHSCOPE_SCREENSHOT_DIR");
  if (dir.isEmpty()) return;
  for (const QSize size : {QSize(1280, 800), QSize(1600, 1000)}) {
    w.resize(size);
    QTest::qWait(30);
    // The robot's rows fit the window at its smallest size.
    QVERIFY2(w.size() == size, qPrintable(QStringLiteral("%1 is %2x%3, its minimum %4x%5")
                                              .arg(name)
                                              .arg(w.width())
                                              .arg(w.height())
                                              .arg(w.minimumSizeHint().width())
                                              .arg(w.minimumSizeHint().height())));
    w.grab().save(
        QStringLiteral("%1/%2-%3x%4.png").arg(QString::fromUtf8(dir), name).arg(size.width()).arg(size.height()));
  }
}

// The window on a new workspace, at the smallest screen size a lab uses, shown.
void open_at_1280x800(bs::ui::MainWindow& w, const QString& workspace) {
  QVERIFY(w.open_workspace(workspace));
  w.resize(1280, 800);
  w.show();
  QVERIFY(QTest::qWaitForWindowExposed(&w));
}

// Chooses the robot in `target` as a person does (the box), and waits for its check to finish.
void choose_robot(bs::ui::RobotTarget* target) {
  const int at = target->box()->findData(QStringLiteral("robot"));
  QVERIFY(at > 0);
  target->box()->setCurrentIndex(at);
  for (int i = 0; i < 1500 && (target->checking() || !target->check()); ++i) QTest::qWait(20);
  QVERIFY(target->check().has_value());
  QVERIFY2(target->check()->ok, target->check()->problem.c_str());
}

std::string setting(const bs::Provenance& p, const std::string& key) {
  for (const auto& [k, v] : p.settings)
    if (k == key) return v;
  return {};
}

}  // namespace

class TestRemoteGui : public QObject {
  Q_OBJECT
 private slots:
  void sweep_on_a_robot_is_plotted_live_and_imported() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    open_at_1280x800(w, dir.filePath("robot.bsw"));
    if (QTest::currentTestFailed()) return;
    bs::ui::KernelRunner* runner = w.kernel_runner();
    bs::ui::RobotTarget* target = runner->target();
    // The robot is in the list (added with its SSH config and CLI path); choosing it checks it.
    choose_robot(target);
    if (QTest::currentTestFailed()) return;
    QVERIFY(target->status_label()->text().contains("BenchScope " BENCHSCOPE_VERSION));
    QCOMPARE(target->platform_field()->text(), QString::fromStdString(target->check()->info.hostname));
    // Backends are the robot's: choose its scalar CPU backend; the platform is renamed before the run.
    QComboBox* backend = nullptr;
    for (QComboBox* box : runner->findChildren<QComboBox*>())
      if (box != target->box() && box->findText("CPU scalar", Qt::MatchStartsWith) >= 0) backend = box;
    QVERIFY(backend);
    backend->setCurrentIndex(backend->findText("CPU scalar", Qt::MatchStartsWith));
    runner->set_workers_spec("8:4000:8");
    runner->set_dims("1");
    runner->set_iterations(4000);
    runner->set_repeats(1);
    target->platform_field()->clear();
    QTest::keyClicks(target->platform_field(), "Robot GUI");
    qRegisterMetaType<bs::ui::RemoteRun*>();
    QSignalSpy live(runner, &bs::ui::KernelRunner::live_run);
    QSignalSpy done(runner, &bs::ui::KernelRunner::remote_finished);
    QPushButton* run = button(runner, "Run");
    QVERIFY(run && run->isEnabled());
    QTest::mouseClick(run, Qt::LeftButton);
    QVERIFY(runner->running());
    // Live: the plot draws the robot's sweep while it runs (counting points, not time).
    for (int i = 0; i < 3000 && live.count() < 20 && done.isEmpty(); ++i) QTest::qWait(10);
    QVERIFY(live.count() >= 20);
    QVERIFY(done.isEmpty());
    QVERIFY(w.flops_plot()->series_count() >= 1);
    QVERIFY(runner->progress_bar()->format().startsWith("robot:"));
    screenshots(w, "kernel-runner-robot-live");
    for (int i = 0; i < 6000 && done.isEmpty(); ++i) QTest::qWait(20);
    QCOMPARE(done.count(), 1);
    QVERIFY(!runner->running());
    // In the workspace like a local run, under the platform typed, with the robot's provenance.
    const auto runs = w.workspace()->runs();
    QCOMPARE(runs.size(), std::size_t{1});
    QCOMPARE(runs[0].run.platform, std::string("Robot GUI"));
    QCOMPARE(runs[0].run.samples.size(), std::size_t{500});
    QCOMPARE(setting(runs[0].run.provenance, "remote host"), std::string("robot"));
    QVERIFY(setting(runs[0].run.provenance, "remote command").find("--workers 8:4000:8") != std::string::npos);
    QCOMPARE(w.flops_plot()->series_count(), 1);
    screenshots(w, "kernel-runner-robot-done");
    // The robot remembers the platform name and the run.
    const bs::remote::RobotList robots;
    const bs::remote::Robot* stored = robots.find("robot");
    QVERIFY(stored && stored->platform == "Robot GUI");
    QVERIFY(!stored->runs.empty() && stored->runs.back().outcome.find("imported 1 run") != std::string::npos);

    // A second sweep, cancelled from the GUI after a few points: the completed ones come home.
    runner->set_workers_spec("1:20000:1");
    live.clear();
    QTest::mouseClick(run, Qt::LeftButton);
    for (int i = 0; i < 3000 && live.count() < 5 && done.count() == 1; ++i) QTest::qWait(10);
    QVERIFY(live.count() >= 5);
    QPushButton* cancel = button(runner, "Cancel");
    QVERIFY(cancel && cancel->isEnabled());
    QTest::mouseClick(cancel, Qt::LeftButton);
    for (int i = 0; i < 6000 && done.count() == 1; ++i) QTest::qWait(20);
    QCOMPARE(done.count(), 2);
    const auto after = w.workspace()->runs();
    QCOMPARE(after.size(), std::size_t{2});
    std::size_t partial = 0;
    for (const auto& r : after)
      if (r.run.samples.size() != 500) partial = r.run.samples.size();
    QVERIFY(partial >= 5 && partial < 20000);
    QVERIFY(runner->progress_bar()->format().contains("cancelled"));
  }

  // The Headroom tab measuring the control loop on the robot (issues #44, #45): the robot chosen under "Run on" and
  // checked, Run pressed, the robot's phases shown as they start, and the measurement imported under the platform
  // typed with the robot's provenance; the robots list records a "headroom" run.
  void headroom_on_a_robot_is_imported() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    open_at_1280x800(w, dir.filePath("headroom.bsw"));
    if (QTest::currentTestFailed()) return;
    bs::test::click_tab(w, bs::test::tab_of(w, w.headroom_view()));
    bs::ui::HeadroomRunPanel* panel = w.headroom_view()->run_panel();
    bs::ui::RobotTarget* target = panel->controls().target;
    target->reload();
    choose_robot(target);
    if (QTest::currentTestFailed()) return;
    // A short measurement: 500 Hz, 0.3 s per phase, idle then the FLOPS kernel with one worker, no real-time.
    panel->rate()->setValue(500);
    panel->seconds()->setValue(0.5);
    panel->realtime()->setChecked(false);
    panel->loads()->setText("flops:1");
    panel->command()->clear();
    target->platform_field()->clear();
    QTest::keyClicks(target->platform_field(), "Robot loop");
    qRegisterMetaType<bs::ui::RemoteRun*>();
    QSignalSpy done(panel, &bs::ui::HeadroomRunPanel::remote_finished);
    QSignalSpy failed(panel, &bs::ui::HeadroomRunPanel::failed);
    QVERIFY(panel->controls().run->isEnabled());
    QTest::mouseClick(panel->controls().run, Qt::LeftButton);
    QVERIFY(panel->controls().running());
    QVERIFY(panel->controls().cancel->isEnabled());
    bool phase_shown = false;
    for (int i = 0; i < 6000 && done.isEmpty() && failed.isEmpty(); ++i) {
      if (!phase_shown && panel->controls().status->text().contains("headroom phase")) {
        phase_shown = true;
        screenshots(w, "headroom-robot-running");
      }
      QTest::qWait(20);
    }
    QVERIFY2(failed.isEmpty(), failed.isEmpty() ? "" : qPrintable(failed.first().first().toString()));
    QCOMPARE(done.count(), 1);
    QVERIFY(phase_shown);
    QVERIFY(!panel->controls().running());
    const auto stored = w.workspace()->headroom_measurements();
    QCOMPARE(stored.size(), std::size_t{1});
    const auto& m = stored[0].measurement;
    QCOMPARE(m.platform, std::string("Robot loop"));
    QCOMPARE(m.phases.size(), std::size_t{2});  // idle, then beside the kernel
    QCOMPARE(setting(m.provenance, "remote host"), std::string("robot"));
    // The robot ran the canonical words of the panel's settings (core/commands): the command, then its options.
    const std::string command = setting(m.provenance, "remote command");
    QVERIFY2(command.find("headroom ") != std::string::npos && command.find(" --rate 500") != std::string::npos,
             command.c_str());
    QVERIFY(panel->controls().status->text().startsWith("Measured on robot"));
    // The workspace tree lists it, and removing it there is undone by Ctrl+Z with nothing lost.
    bs::ui::WorkspaceTree* tree = w.tree();
    QCOMPARE(tree->item_count(bs::ui::TreeItemRef::Kind::Headroom), 1);
    const auto* model = qobject_cast<const QStandardItemModel*>(tree->model());
    QModelIndex row;
    for (int r = 0; r < model->rowCount() && !row.isValid(); ++r)
      for (int c = 0; c < model->item(r)->rowCount(); ++c)
        if (tree->ref_at(model->item(r)->child(c)->index()).kind == bs::ui::TreeItemRef::Kind::Headroom)
          row = model->item(r)->child(c)->index();
    QVERIFY(row.isValid());
    const QString tip = row.data(Qt::ToolTipRole).toString();
    QVERIFY2(tip.contains("Robot loop") && tip.contains("application loop") && tip.contains("non-real-time"),
             qPrintable(tip));
    tree->setFocus();
    tree->setCurrentIndex(row);
    bs::test::press(w, Qt::Key_Delete);
    QVERIFY(w.workspace()->headroom_measurements().empty());
    bs::test::press(w, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(w.workspace()->headroom_measurements().size(), std::size_t{1});
    QCOMPARE(w.workspace()->headroom_measurements()[0].measurement.phases.size(), std::size_t{2});
    QCOMPARE(tree->item_count(bs::ui::TreeItemRef::Kind::Headroom), 1);
    // The robot's long command line is shown whole, wrapped, and does not hold the window wider than the screen.
    QVERIFY(w.minimumSizeHint().width() <= 1280);
    screenshots(w, "headroom-robot-done");
    const bs::remote::RobotList robots;
    const bs::remote::Robot* r = robots.find("robot");
    // The robots list names the command by its whole line, as the CLI does (core/remote/robots.h).
    QVERIFY(r && !r->runs.empty() && r->runs.back().command.starts_with("headroom --"));
    QVERIFY(r->runs.back().outcome.find("imported 1 headroom measurement") != std::string::npos);
  }

  // The Pipeline tab measuring on the robot (issue #44): the robot chosen under "Run on", Measure pressed, the bar
  // following the robot's "captured k of N frames", and the run shown in the table and stored under the platform
  // typed, with the robot's provenance and the command it ran (the synthetic capture: no frame leaves the desk).
  void pipeline_on_a_robot_is_imported() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    open_at_1280x800(w, dir.filePath("pipeline.bsw"));
    if (QTest::currentTestFailed()) return;
    bs::test::click_tab(w, bs::test::tab_of(w, w.pipeline_view()));
    bs::ui::PipelineMeasurePanel* panel = w.pipeline_view()->measure_panel();
    bs::ui::RobotTarget* target = panel->controls().target;
    target->reload();
    choose_robot(target);
    if (QTest::currentTestFailed()) return;
    QVERIFY(panel->controls().run->text() == "Measure on robot");
    panel->frames()->setValue(6);
    panel->workers()->setValue(1);
    panel->detector()->setCurrentIndex(panel->detector()->findData(QStringLiteral("hog")));
    target->platform_field()->clear();
    QTest::keyClicks(target->platform_field(), "Robot eyes");
    qRegisterMetaType<bs::ui::RemoteRun*>();
    QSignalSpy done(panel, &bs::ui::PipelineMeasurePanel::remote_finished);
    QSignalSpy failed(panel, &bs::ui::PipelineMeasurePanel::failed);
    QTest::mouseClick(panel->controls().run, Qt::LeftButton);
    QVERIFY(panel->controls().running());
    auto* bar = panel->findChild<QProgressBar*>();
    QVERIFY(bar);
    int most = 0;
    bool shot = false;
    for (int i = 0; i < 6000 && done.isEmpty() && failed.isEmpty(); ++i) {
      if (bar->maximum() > 0) most = std::max(most, bar->value());
      if (!shot && most > 0) {
        shot = true;
        screenshots(w, "pipeline-robot-running");
      }
      QTest::qWait(10);
    }
    QVERIFY2(failed.isEmpty(), failed.isEmpty() ? "" : qPrintable(failed.first().first().toString()));
    QCOMPARE(done.count(), 1);
    QVERIFY2(most > 0, "the progress bar never followed the robot");
    QVERIFY(!panel->controls().running());
    const auto stored = w.workspace()->pipeline_runs();
    QCOMPARE(stored.size(), std::size_t{1});
    const bs::PipelineRun& run = stored[0].run;
    QCOMPARE(run.platform, std::string("Robot eyes"));
    QCOMPARE(run.stage(bs::pipeline_stage::kPreprocess)->n, std::size_t{6});
    QCOMPARE(setting(run.provenance, "remote host"), std::string("robot"));
    QVERIFY2(setting(run.provenance, "remote command").find("pipeline --synthetic --frames 6") != std::string::npos,
             setting(run.provenance, "remote command").c_str());
    QVERIFY(panel->controls().status->text().startsWith("Measured on robot"));
    // The table shows it under its platform.
    bool listed = false;
    QTableWidget* table = w.pipeline_view()->table();
    for (int r = 0; r < table->rowCount(); ++r)
      if (auto* item = table->item(r, bs::ui::PipelineView::Platform); item && item->text() == "Robot eyes")
        listed = true;
    QVERIFY(listed);
    QVERIFY(w.minimumSizeHint().width() <= 1280);
    screenshots(w, "pipeline-robot-done");
    const bs::remote::RobotList robots;
    const bs::remote::Robot* r = robots.find("robot");
    QVERIFY(r && !r->runs.empty() && r->runs.back().command.starts_with("pipeline --"));
    QVERIFY2(r->runs.back().outcome.find("imported 1 pipeline run") != std::string::npos,
             r->runs.back().outcome.c_str());
  }

  // "Several robots…": the sweep runs on each checked robot in turn, each under the platform typed in the dialog,
  // and each robot's run lands as it arrives.
  // The Sustained tab on a robot (issue #53): Run pressed with the robot chosen, its intervals drawn at the desk as
  // the robot streams them, and the sustained record imported under the platform typed with the robot's provenance.
  void sustained_on_a_robot_is_drawn_live_and_imported() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    open_at_1280x800(w, dir.filePath("sustain.bsw"));
    if (QTest::currentTestFailed()) return;
    bs::test::click_tab(w, bs::test::tab_of(w, w.sustain_view()));
    bs::ui::SustainRunPanel* panel = w.sustain_view()->run_panel();
    bs::ui::RobotTarget* target = panel->controls().target;
    target->reload();
    choose_robot(target);
    if (QTest::currentTestFailed()) return;
    panel->load()->setText("flops:1");
    panel->seconds()->setValue(3);
    panel->interval()->setValue(0.5);
    target->platform_field()->clear();
    QTest::keyClicks(target->platform_field(), "Robot torso");
    qRegisterMetaType<bs::ui::RemoteRun*>();
    qRegisterMetaType<bs::SustainRun>();
    QSignalSpy done(panel, &bs::ui::SustainRunPanel::robot_finished);
    QSignalSpy failed(panel, &bs::ui::SustainRunPanel::failed);
    QSignalSpy live(panel, &bs::ui::SustainRunPanel::live_interval);
    QTest::mouseClick(panel->controls().run, Qt::LeftButton);
    QVERIFY(panel->controls().running());
    for (int i = 0; i < 6000 && done.isEmpty() && failed.isEmpty(); ++i) QTest::qWait(20);
    QVERIFY2(failed.isEmpty(), failed.isEmpty() ? "" : qPrintable(failed.first().first().toString()));
    QCOMPARE(done.count(), 1);
    for (int i = 0; i < 100 && panel->controls().running(); ++i) QTest::qWait(20);
    const auto stored = w.workspace()->sustain_runs();
    QCOMPARE(stored.size(), std::size_t{1});
    const bs::SustainRun& r = stored[0].run;
    QCOMPARE(r.platform, std::string("Robot torso"));
    QCOMPARE(r.rate.size(), std::size_t{6});
    QCOMPARE(setting(r.provenance, "remote host"), std::string("robot"));
    const std::string command = setting(r.provenance, "remote command");
    QVERIFY2(command.find("sustain ") != std::string::npos && command.find(" --load flops:1") != std::string::npos,
             command.c_str());
    QVERIFY2(live.count() >= 3, ("the robot's intervals were not drawn as they came: " + command).c_str());
    QCOMPARE(w.sustain_view()->chooser()->count(), 1);
    screenshots(w, "sustained-robot-done");
  }

  void several_robots_one_after_another() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    open_at_1280x800(w, dir.filePath("queue.bsw"));
    if (QTest::currentTestFailed()) return;
    bs::ui::KernelRunner* runner = w.kernel_runner();
    runner->target()->reload();
    runner->set_workers_spec("1,2,4,8");
    runner->set_dims("1");
    runner->set_iterations(1000);
    runner->set_repeats(2);
    qRegisterMetaType<bs::ui::RemoteRun*>();
    QSignalSpy done(runner, &bs::ui::KernelRunner::remote_finished);
    bool answered = false;
    // The dialog is answered through the running event loop, as a person would: both robots checked, each
    // platform renamed, the backend left at cpu, OK.
    std::function<void()> answer = [&] {
      auto* d = qobject_cast<bs::ui::RobotQueueDialog*>(QApplication::activeModalWidget());
      if (!d) {  // not shown yet: look again on the next turn of the event loop
        QTimer::singleShot(10, this, answer);
        return;
      }
      QTableWidget* t = d->table();
      for (int r = 0; r < t->rowCount(); ++r) {
        const QString name = t->item(r, 0)->text();
        const bool wanted = name == "robot" || name == "robot-b";
        t->item(r, 0)->setCheckState(wanted ? Qt::Checked : Qt::Unchecked);
        if (wanted) t->item(r, 1)->setText(name == "robot" ? "Queue A" : "Queue B");
      }
      d->backend_box()->setCurrentIndex(d->backend_box()->findData("cpu-scalar"));
      if (const QByteArray shots = qgetenv("BENCHSCOPE_SCREENSHOT_DIR"); !shots.isEmpty())
        d->grab().save(QString::fromUtf8(shots) + "/robot-queue-dialog.png");
      answered = true;
      d->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->click();
    };
    QTimer::singleShot(0, this, answer);
    QPushButton* several = runner->several_robots_button();
    QVERIFY(several->isEnabled());
    QTest::mouseClick(several, Qt::LeftButton);
    QVERIFY(answered);
    // A failure would show a message box: its text is the test's failure message.
    QString box_text;
    QTimer boxes;
    connect(&boxes, &QTimer::timeout, this, [&] {
      if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
        box_text = box->text();
        box->close();
      }
    });
    boxes.start(50);
    for (int i = 0; i < 6000 && done.count() < 2 && box_text.isEmpty(); ++i) QTest::qWait(20);
    QVERIFY2(box_text.isEmpty(), qPrintable(box_text));
    QCOMPARE(done.count(), 2);
    for (int i = 0; i < 200 && runner->running(); ++i) QTest::qWait(20);
    QVERIFY(!runner->running());
    std::set<std::string> platforms;
    for (const auto& r : w.workspace()->runs()) {
      platforms.insert(r.run.platform);
      QCOMPARE(r.run.samples.size(), std::size_t{4});
      QCOMPARE(r.run.backend.rfind("CPU scalar", 0), std::size_t{0});
    }
    QCOMPARE(platforms, (std::set<std::string>{"Queue A", "Queue B"}));
    screenshots(w, "kernel-runner-robot-queue");
  }
};

namespace {
int remote_gui_main(int argc, char** argv) {
  QApplication app(argc, argv);
  bs::test::SshRobot robot;
  if (const QString why = robot.start(); !why.isEmpty()) {
    std::cout << "SKIP: no SSH server to test against: " << why.toStdString() << '\n';
    return bs::test::kSkipCode;
  }
  g_robot = &robot;
  // The desk's robots list in the test's folder, holding the robot with its SSH config and the built CLI.
  qputenv("XDG_CONFIG_HOME", robot.path("desk-config").toUtf8());
  bs::remote::Robot r;
  r.name = "robot";
  r.added = true;
  r.config_file = robot.config().toStdString();
  r.remote_cli = bs::test::kCli.toStdString();
  bs::remote::RobotList().put(r);
  r.name = "robot-b";  // the same machine under its second Host name: a second robot for the queue
  bs::remote::RobotList().put(r);
  TestRemoteGui tc;
  return QTest::qExec(&tc, argc, argv);
}
}  // namespace
BENCHSCOPE_TEST_CUSTOM_MAIN(remote_gui_main)

#include "test_remote_gui.moc"
