// SPDX-License-Identifier: GPL-3.0-or-later
// The inference table the views, `platforms` and the report share: per-image time from a batched forward pass,
// inferences per second and per Wh, the share of the device ceiling, unknowns as dashes, the architecture-timing
// label, and which way each column is better.
#include <QTest>

#include <cmath>

#include "../../../support/run_on.h"
#include "analysis/platform/inference_table.h"
#include "report/platform_report.h"

namespace {

bs::DnnRun run() {
  auto r = bs::test::run_on<bs::DnnRun>("robot", "CPU (4 OpenCV threads)", "cpu");
  r.model = "yolo-n";
  r.family = "YOLOv8";
  r.architecture_only = true;
  r.input_width = r.input_height = 640;
  r.batch = 4;
  r.flops = 4 * 8'800'000'000LL;
  r.forward = {"inference", 10, 0.8, 0.04, {}, {}, {}, {}};  // 0.2 s per image
  r.device_peak_flops = 440e9;
  r.energy_per_inference_j = 2.5;
  return r;
}

}  // namespace

class TestInferenceTable : public QObject {
  Q_OBJECT
 private slots:
  void cells_follow_the_run() {
    bs::DnnRun plain = run();
    plain.model = "ssd.onnx";
    plain.family = "SSD";
    plain.architecture_only = false;
    plain.batch = 1;
    plain.flops = 2'500'000'000;
    plain.forward = {"inference", 5, 0.05, 0.001, {}, {}, {}, {}};
    plain.device_peak_flops.reset();
    plain.energy_per_inference_j.reset();
    const std::vector<bs::DnnRun> runs{run(), plain};
    const bs::ExportTable t = bs::inference_table(runs);
    QCOMPARE(t.rows.size(), std::size_t{2});
    const auto& a = t.rows[0];
    QCOMPARE(a[1], std::string("yolo-n (YOLOv8), architecture timing: no detections"));
    QCOMPARE(a[2], std::string("640x640, 4"));
    QVERIFY2(a[4].starts_with("200.00 ± 10.00") && a[4].find("n = 10") != std::string::npos, a[4].c_str());
    QCOMPARE(a[5], std::string("5.00"));    // 4 images / 0.8 s
    QCOMPARE(a[6], std::string("44.00"));   // 35.2 GFLOP / 0.8 s
    QCOMPARE(a[7], std::string("10.0 %"));  // of 440 GFLOPS
    QCOMPARE(a[8], std::string("2.5000"));
    QCOMPARE(a[9], std::string("1440"));   // 3600 J per Wh / 2.5 J
    QCOMPARE(a[10], std::string("8.80"));  // per image
    const auto& b = t.rows[1];
    QCOMPARE(b[1], std::string("ssd.onnx (SSD)"));
    QCOMPARE(b[7], std::string("\xE2\x80\x93"));
    QCOMPARE(b[8], std::string("\xE2\x80\x93"));
    QCOMPARE(b[9], std::string("\xE2\x80\x93"));
    QVERIFY(std::isnan(bs::inference_value(plain, bs::InferenceColumn::InferencesPerWh)));
    QCOMPARE(bs::inference_better(bs::InferenceColumn::TimePerImage), -1);
    QCOMPARE(bs::inference_better(bs::InferenceColumn::InferencesPerWh), +1);
    QCOMPARE(bs::inference_better(bs::InferenceColumn::Platform), 0);
  }

  void report_has_the_table_only_with_runs() {
    bs::ReportInput in;
    in.workspace = "w";
    QVERIFY(bs::report_html(in).find("Detection network inference") == std::string::npos);
    in.inference_runs = {run()};
    const std::string html = bs::report_html(in);
    QVERIFY(html.find("Detection network inference") != std::string::npos);
    QVERIFY(html.find("architecture timing: no detections") != std::string::npos);
  }
};

QTEST_GUILESS_MAIN(TestInferenceTable)
#include "test_inference_table.moc"
