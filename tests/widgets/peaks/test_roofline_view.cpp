// SPDX-License-Identifier: GPL-3.0-or-later
// The Roofline tab: one roof per device (sloped when a bandwidth is known), one marker per run at its peak.
#include <qcustomplot.h>
#include <QTest>

#include "../../support/run_on.h"
#include "peaks/roofline_view.h"

class TestRooflineView : public QObject {
  Q_OBJECT
 private slots:
  void roofs_and_markers() {
    auto cpu = bs::test::run_on<bs::FlopsRun>("vm", "CPU", "CPU SIMD");
    cpu.dims = 4;
    cpu.iterations = 40000;
    cpu.samples = {{64, {0.01}}, {128, {0.015}}};
    cpu.theoretical_peak_flops = 400e9;
    bs::FlopsRun gpu = cpu;
    gpu.device = "GPU";
    gpu.backend = "OpenCL";
    bs::ResultSet bw{"vm", "CPU", bs::DeviceKind::Cpu, "CPU SIMD", "benchscope-bandwidth", {}, {}};
    bw.measurements.push_back({"stream-triad/128MiB", "bandwidth", "B/s", {40e9, 50e9}, {}});
    bs::ui::RooflineView view;
    view.resize(1000, 600);
    view.set_data({cpu, gpu}, {bw}, {{{"vm", "CPU"}, 0}, {{"vm", "GPU"}, 1}});
    QCOMPARE(view.ceilings().size(), std::size_t{2});
    QCOMPARE(view.points().size(), std::size_t{2});
    QCOMPARE(view.plot()->graphCount(), 4);           // two roofs, two markers
    QCOMPARE(view.plot()->graph(0)->dataCount(), 3);  // CPU: memory slope, ridge, flat
    QCOMPARE(view.plot()->graph(1)->dataCount(), 2);  // GPU: flat only, no bandwidth
    QCOMPARE(*view.ceilings()[0].ridge_intensity(), 400e9 / 50e9);
    // The CPU run's peak: 6*4*40000*128 flops in 0.015 s, compute-bound at I = 960000 / 68.
    QCOMPARE(view.points()[0].flops, 6.0 * 4 * 40000 * 128 / 0.015);
    QVERIFY(!view.points()[0].memory_bound);
    QCOMPARE(view.plot()->xAxis->scaleType(), QCPAxis::stLogarithmic);
  }

  void preprocessing_stages_placed() {
    auto gpu = bs::test::run_on<bs::FlopsRun>("robot", "GPU", bs::DeviceKind::Gpu, "OpenCL");
    gpu.dims = 4;
    gpu.iterations = 40000;
    gpu.samples = {{1024, {0.01}}};
    gpu.theoretical_peak_flops = 1e12;
    bs::ResultSet bw{"robot", "GPU", bs::DeviceKind::Gpu, "OpenCL", "benchscope-bandwidth", {}, {}};
    bw.measurements.push_back({"stream-triad/128MiB", "bandwidth", "B/s", {20e9}, {}});
    auto run = bs::test::run_on<bs::PipelineRun>("robot", "GPU (OpenCL) preprocessing, CPU detection", "opencl");
    run.demosaic = "bilinear";
    run.frame_width = 1280;
    run.frame_height = 1024;
    run.stages.push_back({bs::pipeline_stage::kPreprocess, 500, 0.00621, 0.00099, {}, {}, {}, {}});
    run.provenance.source_file = "pipeline-robot.json";
    bs::ui::RooflineView view;
    view.resize(1000, 600);
    view.set_data({gpu}, {bw}, {{{"robot", "GPU"}, 0}}, {run});
    QCOMPARE(view.stages().placed.size(), std::size_t{1});
    const bs::StagePlacement& s = view.stages().placed.front();
    QCOMPARE(s.point.intensity, 35.0 / 16.0);
    QVERIFY(std::fabs(s.point.flops - 35.0 * 1280 * 1024 / 0.00621) < 1);
    QVERIFY(s.point.memory_bound);  // 2.19 op/B left of the ridge at 50
    // Roof, rotation marker, the legend's star, the stage's star.
    QCOMPARE(view.plot()->graphCount(), 4);
    QCOMPARE(view.plot()->graph(2)->name(),
             QString("Preprocessing stage of a pipeline run, integer op/s (hover: numbers, source); bar: ± SD"));
    QCOMPARE(view.plot()->graph(3)->scatterStyle().shape(), QCPScatterStyle::ssStar);
    const QString tip = view.stage_tooltip(s);
    QVERIFY(tip.contains("6.21 ± 0.99 ms (n = 500)"));
    QVERIFY(tip.contains("pipeline-robot.json"));
    QVERIFY(tip.contains("memory-bound"));
    QVERIFY(tip.contains("35.0 integer ops and 16.0 bytes"));
  }
};

QTEST_MAIN(TestRooflineView)
#include "test_roofline_view.moc"
