// SPDX-License-Identifier: GPL-3.0-or-later
// The Roofline tab: one roof per device (sloped when a bandwidth is known), one marker per run at its peak.
#include <QTest>
#include <qcustomplot.h>

#include "roofline_view.h"

class TestRooflineView : public QObject {
  Q_OBJECT
 private slots:
  void roofs_and_markers() {
    bs::FlopsRun cpu;
    cpu.platform = "vm";
    cpu.device = "CPU";
    cpu.backend = "CPU SIMD";
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
};

QTEST_MAIN(TestRooflineView)
#include "test_roofline_view.moc"
