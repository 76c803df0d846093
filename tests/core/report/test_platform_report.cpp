// SPDX-License-Identifier: GPL-3.0-or-later
// The report's HTML without Qt: escaping, one page per platform with its numbers and sources, the recommendation,
// the figures.
#include <QTest>

#include "report/platform_report.h"

class TestPlatformReport : public QObject {
  Q_OBJECT
 private slots:
  void escapes() { QCOMPARE(bs::html_escape("a<b & \"c\">"), std::string("a&lt;b &amp; &quot;c&quot;&gt;")); }

  void pages_numbers_sources_figures() {
    bs::ReportInput in;
    in.workspace = "lab <1>.bsw";
    in.generated = "2026-11-23T07:00:00";
    in.tool = "BenchScope test";
    bs::PlatformRow a;
    a.platform = "Robot A";
    a.mean_power_w = 12.5;
    a.battery_runtime_h = 2;
    bs::PeakRow gpu;
    gpu.platform = "Robot A";
    gpu.device = "GPU X";
    gpu.backend = "OpenCL";
    gpu.dims = 4;
    gpu.peak.flops = 1.5e12;
    gpu.peak.workers = 4096;
    gpu.theoretical_flops = 3e12;
    gpu.fraction_of_theoretical = 0.5;
    a.gpu = gpu;
    a.sources[bs::column::kPower] = {"a-current.csv", bs::DataOrigin::Measured, "mean of a-current.csv x 12 V"};
    bs::PlatformRow b;
    b.platform = "Robot B";
    in.rows = {a, b};
    bs::PlatformVerdict va{"Robot A", true, {}, true, "", ""}, vb{"Robot B", false, {}, false, "", ""};
    in.verdicts = {va, vb};
    in.constraints = "a power budget of 15 W";
    in.figures = {{"fig1a: All GPUs", "data:image/png;base64,AAAA"}};
    const std::string html = bs::report_html(in);
    QVERIFY(html.find("lab &lt;1&gt;.bsw") != std::string::npos);
    QCOMPARE(std::count(html.begin(), html.end(), '\n') > 10, true);
    std::size_t pages = 0;
    for (auto p = html.find("class=\"platform\""); p != std::string::npos; p = html.find("class=\"platform\"", p + 1))
      ++pages;
    QCOMPARE(pages, std::size_t{3});  // two platforms + the figures
    QVERIFY(html.find("<h2>Robot A</h2>") != std::string::npos);
    QVERIFY(html.find("12.50") != std::string::npos);   // mean power
    QVERIFY(html.find("120.00") != std::string::npos);  // 2 h of battery in minutes
    QVERIFY(html.find("50.0 % of the theoretical peak") != std::string::npos);
    QVERIFY(html.find("1500.00 GFLOPS on GPU X (OpenCL, D = 4, 4096 workers)") != std::string::npos);
    QVERIFY(html.find("mean of a-current.csv x 12 V") != std::string::npos);
    QVERIFY(html.find("measured") != std::string::npos);
    QVERIFY(html.find("Recommended under a power budget of 15 W: Robot A") != std::string::npos);
    QVERIFY(html.find("<img src=\"data:image/png;base64,AAAA\"") != std::string::npos);
  }

  // A flagged number carries its footnote marker in the comparison table, the note under it, and the reason on its
  // platform's page; the page says how the power was measured.
  void flags_and_measurement() {
    bs::ReportInput in;
    bs::PlatformRow a;
    a.platform = "Robot A";
    bs::PeakRow gpu;
    gpu.device = "GPU X";
    gpu.backend = "OpenCL";
    gpu.peak.flops = 5.25e12;
    gpu.flags = {{"above_spec_peak", "5.25 TFLOPS is 5.9x the GPU X's FP32 peak <here>"}};
    a.gpu = gpu;
    a.flags[bs::column::kGpuPeak] = gpu.flags;
    a.power_measurement = "on-board sensor: INA3221 VDD_IN";
    in.rows = {a};
    const std::string html = bs::report_html(in);
    QVERIFY(html.find("5.25 (GPU X, OpenCL) [1]") != std::string::npos);
    QVERIFY(html.find("[1] above_spec_peak: 5.25 TFLOPS is 5.9x the GPU X's FP32 peak &lt;here&gt;") !=
            std::string::npos);
    QVERIFY(html.find("&#9888; above_spec_peak</b>: 5.25 TFLOPS") != std::string::npos);
    QVERIFY(html.find("Power measured by: on-board sensor: INA3221 VDD_IN.") != std::string::npos);
  }
};

QTEST_MAIN(TestPlatformReport)
#include "test_platform_report.moc"
