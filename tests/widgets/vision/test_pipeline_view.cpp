// SPDX-License-Identifier: GPL-3.0-or-later
// The Pipeline tab on the paper's sample data: the paper's four stage times with SD and n, numeric sorting,
// provenance in the tooltips, reconstructed rows marked; and a measured run beside them. Saves a screenshot.
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTest>

#include "../../support/run_on.h"
#include "analysis/platform/pipeline_table.h"
#include "vision/pipeline/pipeline.h"
#include "vision/pipeline_measure_panel.h"
#include "vision/pipeline_view.h"
#include "vision/reproject/cuda_preprocess.h"
#include "workspace/registry.h"

using bs::ui::PipelineMeasurePanel;
using bs::ui::PipelineView;

namespace {

std::vector<bs::PipelineRun> paper_runs() {
  std::vector<bs::PipelineRun> runs;
  for (const char* f : {"pipeline-nuc.json", "pipeline-jetson.json"})
    for (auto& r : bs::import_file(std::string(BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018/") + f, bs::CancelToken{})
                       .pipeline_runs)
      runs.push_back(std::move(r));
  return runs;
}

QString text(const QTableWidget* t, int row, int col) { return t->item(row, col)->text(); }

}  // namespace

class TestPipelineView : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);  // QSettings in a test location, not the user's
    QSettings().clear();                       // each run starts as a fresh machine: nothing remembered
  }

  void paper_table() {
    PipelineView v;
    v.resize(1200, 320);
    v.set_data(paper_runs());
    const QTableWidget* t = v.table();
    QCOMPARE(t->rowCount(), 4);
    // Stage order, then platform: preprocessing Jetson, NUC; detection Jetson, NUC.
    QCOMPARE(text(t, 0, PipelineView::Platform), QString("Jetson TX2"));
    QCOMPARE(text(t, 0, PipelineView::Time), QString("6.48 ± 2.43 ms (n = 500)"));
    QCOMPARE(text(t, 1, PipelineView::Time), QString("6.21 ± 0.99 ms (n = 500)"));
    QCOMPARE(text(t, 2, PipelineView::Time), QString("570 ± 1100 ms (n = 500)"));
    QCOMPARE(text(t, 3, PipelineView::Time), QString("170 ± 190 ms (n = 500)"));
    QCOMPARE(text(t, 3, PipelineView::StageRate), QString("5.88 fps"));  // 1 / 0.17 s
    QCOMPARE(text(t, 3, PipelineView::P95), QString("–"));               // not published
    QCOMPARE(text(t, 3, PipelineView::Data), QString("reconstructed"));
    QVERIFY(t->item(3, PipelineView::Time)->toolTip().contains("reconstructed from the paper's reported figures"));
    QVERIFY(t->item(3, PipelineView::Time)->toolTip().contains("pipeline-nuc.json"));
    // Sorted by time numerically (text order would put "170" before "6.21").
    v.table()->sortByColumn(PipelineView::Time, Qt::AscendingOrder);
    QCOMPARE(text(t, 0, PipelineView::Time), QString("6.21 ± 0.99 ms (n = 500)"));
    QCOMPARE(text(t, 3, PipelineView::Time), QString("570 ± 1100 ms (n = 500)"));
    v.table()->sortByColumn(PipelineView::StageRate, Qt::DescendingOrder);
    QCOMPARE(text(t, 0, PipelineView::Platform), QString("NUC"));
    QCOMPARE(text(t, 0, PipelineView::Stage), QString("Preprocessing (demosaic + reprojection)"));
  }

  void measured_run_beside_the_paper() {
    auto runs = paper_runs();
    auto m = bs::test::run_on<bs::PipelineRun>("this host", "CPU (2 threads)", "cpu");
    m.throughput_fps = 4.25;
    m.stages = {{"preprocess", 50, 0.0042, 0.0005, 0.0035, 0.007, 0.0041, 0.0051},
                {"detect", 50, 0.21, 0.03, 0.15, 0.3, 0.2, 0.26},
                {"end-to-end", 50, 0.22, 0.03, 0.16, 0.31, 0.21, 0.27}};
    m.provenance.origin = bs::DataOrigin::Measured;
    m.provenance.host = "vm-1";
    m.provenance.settings.emplace_back("lens calibration", "line-fit, RMS 0.27 px; 27 lines");
    runs.push_back(m);
    PipelineView v;
    v.resize(1400, 360);
    v.set_data(runs);
    QTableWidget* t = v.table();
    QCOMPARE(t->rowCount(), 7);
    t->sortByColumn(PipelineView::P95, Qt::AscendingOrder);
    QCOMPARE(text(t, 0, PipelineView::P95), QString("5.10"));
    QCOMPARE(text(t, 0, PipelineView::Time), QString("4.20 ± 0.50 ms (n = 50)"));  // known p95s first, unknown last
    QCOMPARE(text(t, 6, PipelineView::P95), QString("–"));
    QCOMPARE(text(t, 0, PipelineView::Throughput), QString("4.25 fps"));
    QCOMPARE(text(t, 0, PipelineView::Data), QString("measured"));
    QVERIFY(t->item(0, PipelineView::Stage)->toolTip().contains("host vm-1"));
    // How the run's lens was obtained (issue #20); reconstructed runs recorded none.
    QCOMPARE(text(t, 0, PipelineView::LensColumn), QString("line-fit, RMS 0.27 px; 27 lines"));
    QCOMPARE(text(t, 6, PipelineView::LensColumn), QString("–"));
    // Stages sort in pipeline order: preprocessing rows first, end to end last.
    t->sortByColumn(PipelineView::Stage, Qt::AscendingOrder);
    QCOMPARE(text(t, 0, PipelineView::Stage), QString("Preprocessing (demosaic + reprojection)"));
    QCOMPARE(text(t, 6, PipelineView::Stage), QString("End to end"));
    QCOMPARE(text(t, 6, PipelineView::Time), QString("220 ± 30 ms (n = 50)"));
    QCOMPARE(text(t, 6, PipelineView::StageRate), QString("–"));  // a latency, not a rate
    // The LaTeX export holds the same cells.
    const std::string tex = bs::to_latex(bs::pipeline_table(runs));
    QVERIFY(tex.find("6.21 $\\pm$ 0.99 ms (n = 500)") != std::string::npos);
    QVERIFY(tex.find("reconstructed") != std::string::npos);
    v.show();
    QVERIFY(QTest::qWaitForWindowExposed(&v));
    const QString shot = BENCHSCOPE_BINARY_DIR "/pipeline-view.png";
    QVERIFY(v.grab().save(shot));
  }

  void measure_panel_options_are_remembered() {
    {
      PipelineView v;
      PipelineMeasurePanel* p = v.measure_panel();
      QCOMPARE(p->workers()->value(), static_cast<int>(bs::vision::default_detection_workers()));
      QCOMPARE(p->scale()->value(), 0.5);
      QCOMPARE(p->workers()->minimum(), 1);
      QCOMPARE(p->scale()->maximum(), 1.0);
      QVERIFY(p->scale()->minimum() > 0);
      QVERIFY(p->workers()->toolTip().contains("Detection worker threads"));
      QVERIFY(p->scale()->toolTip().contains("mapped back"));
      p->frames()->setValue(7);
      p->workers()->setValue(3);
      p->scale()->setValue(0.35);
    }
    PipelineMeasurePanel again;
    QCOMPARE(again.frames()->value(), 7);
    QCOMPARE(again.workers()->value(), 3);
    QCOMPARE(again.scale()->value(), 0.35);
  }

  void measure_panel_runs_the_pipeline() {
    PipelineView v;
    PipelineMeasurePanel* p = v.measure_panel();
    p->frames()->setValue(3);
    p->workers()->setValue(2);
    p->scale()->setValue(0.25);
    QSignalSpy measured(&v, &PipelineView::run_measured);
    QSignalSpy failed(p, &PipelineMeasurePanel::failed);
    p->controls().run->click();
    QVERIFY(p->controls().running() || measured.count() == 1);
    QVERIFY(!p->controls().run->isEnabled() || measured.count() == 1);
    QVERIFY2(measured.wait(120000) || measured.count() == 1,
             failed.isEmpty() ? "no run" : qPrintable(failed[0][0].toString()));
    const auto run = measured[0][0].value<bs::PipelineRun>();
    QVERIFY(run.stage("detect"));
    QCOMPARE(run.stage("detect")->n, std::size_t{3});
    QCOMPARE(run.stage("end-to-end")->n, std::size_t{3});
    QCOMPARE(run.provenance.origin, bs::DataOrigin::Measured);
    QVERIFY2(run.device.find("2 detection workers") != std::string::npos, run.device.c_str());
    QVERIFY2(run.provenance.note.find("2 detection workers, detect scale 0.25") != std::string::npos,
             run.provenance.note.c_str());
    QCOMPARE(run.frame_width, 1280);
    QVERIFY(p->controls().run->isEnabled());
  }

  void measure_panel_backends() {
    // The CUDA entry is there, enabled exactly when the library says the path can run, and says why when not;
    // OpenCL (PoCL here) measures a real run whose record names the backend and the device.
    PipelineMeasurePanel p;
    const auto* model = qobject_cast<QStandardItemModel*>(p.backend()->model());
    QVERIFY(model);
    const int cuda = p.backend()->findData(QStringLiteral("cuda"));
    QVERIFY(cuda >= 0);
    const std::string why = bs::vision::cuda_preprocessing_unavailable();
    QCOMPARE(model->item(cuda)->isEnabled(), why.empty());
    if (!why.empty()) QVERIFY(model->item(cuda)->toolTip().contains(QString::fromStdString(why)));
    p.backend()->setCurrentIndex(p.backend()->findData(QStringLiteral("opencl")));
    p.frames()->setValue(2);
    p.workers()->setValue(1);
    p.scale()->setValue(0.25);
    QSignalSpy measured(&p, &PipelineMeasurePanel::run_measured);
    QSignalSpy failed(&p, &PipelineMeasurePanel::failed);
    p.start();
    QTRY_VERIFY_WITH_TIMEOUT(!p.controls().running(), 120000);
    QCoreApplication::processEvents();
    QVERIFY2(measured.count() == 1, failed.isEmpty() ? "no run" : qPrintable(failed[0][0].toString()));
    const auto run = measured[0][0].value<bs::PipelineRun>();
    QCOMPARE(run.backend, std::string("opencl"));
    QCOMPARE(run.demosaic, std::string("bilinear"));
    QVERIFY2(run.device.find("(OpenCL) preprocessing") != std::string::npos, run.device.c_str());
    QVERIFY(run.provenance.note.find("preprocessing on opencl") != std::string::npos);
    PipelineMeasurePanel again;  // remembered
    QCOMPARE(again.backend()->currentData().toString(), QStringLiteral("opencl"));
    again.backend()->setCurrentIndex(0);
  }

  void measure_panel_cancel_stores_nothing() {
    PipelineMeasurePanel p;
    p.frames()->setValue(100000);
    p.workers()->setValue(1);
    p.scale()->setValue(0.25);
    QSignalSpy measured(&p, &PipelineMeasurePanel::run_measured);
    p.start();
    QVERIFY(p.controls().cancel->isEnabled());
    p.controls().cancel->click();  // Cancel as a person presses it
    QTRY_VERIFY_WITH_TIMEOUT(!p.controls().running(), 120000);
    QCoreApplication::processEvents();
    QCOMPARE(measured.count(), 0);
    QVERIFY(p.controls().run->isEnabled());
  }

  void empty_workspace_says_how_to_get_data() {
    PipelineView v;
    v.set_data({});
    QCOMPARE(v.table()->rowCount(), 0);
    QVERIFY(v.findChild<QLabel*>()->text().contains("benchscope-cli pipeline"));
  }
};

QTEST_MAIN(TestPipelineView)
#include "test_pipeline_view.moc"
