// SPDX-License-Identifier: GPL-3.0-or-later
// The report's HTML without Qt: escaping, the decision first (recommendation, constraints met, chart, table), the
// platforms table transposed with units in their own column and empty measures left out, numbered figures with
// their captions in the same paragraph, the details and the sources appendix, and sections as a list.
#include <QTest>

#include "report/platform_report.h"
#include "report/report_sections.h"
#include "report/table_fit.h"

namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

bs::ReportInput two_robots() {
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
  b.mean_power_w = 30;
  in.rows = {a, b};
  bs::ConstraintCheck met{"power budget (mean power)", "W", 15, 12.5, true, 2.5};
  bs::ConstraintCheck failed{"power budget (mean power)", "W", 15, 30, false, -15};
  in.verdicts = {{"Robot A", true, {met}, true, "", ""}, {"Robot B", false, {failed}, false, "", ""}};
  in.constraints = "a power budget of 15 W";
  in.comparison_chart = bs::ReportFigure{"Best peak per platform.", "data:image/png;base64,CCCC", 500, 150, "", ""};
  in.figures = {{"All GPUs: FLOPS against workers.", "data:image/png;base64,AAAA", 345, 240, "fig1a", "GPU X"},
                {"All CPUs: FLOPS against tasks.", "data:image/png;base64,BBBB", 345, 240, "fig2a", "CPU Y"}};
  return in;
}

}  // namespace

class TestPlatformReport : public QObject {
  Q_OBJECT
 private slots:
  void escapes() { QCOMPARE(bs::html_escape("a<b & \"c\">"), std::string("a&lt;b &amp; &quot;c&quot;&gt;")); }

  // Page one: the recommendation with the constraint it met and the margin, before the chart and the table; the
  // others and why they were not chosen.
  // Words as a table column needs them whole: a path breaks after each '/', a unit keeps its short denominator
  // (page 1 once printed "GFLOPS/" over "W" in a column sized for "GFLOPS/").
  void words_of_units_and_paths() {
    QCOMPARE(bs::longest_word("GFLOPS/W"), std::size_t{8});
    QCOMPARE(bs::longest_word("op/s per W"), std::size_t{4});
    QCOMPARE(bs::longest_word("results/closed/Intel"), std::size_t{8});
    QCOMPARE(bs::longest_word("perf-rapl-validation.csv"), std::size_t{14});
    QCOMPARE(bs::longest_word("Area-51"), std::size_t{7});
  }

  void decision_first() {
    const std::string html = bs::report_html(two_robots());
    QVERIFY(html.find("lab &lt;1&gt;.bsw") != std::string::npos);
    const auto rec = html.find("Recommended under a power budget of 15 W: Robot A");
    const auto met = html.find(" Met: power budget (mean power): 12.50 W against at most 15.00 W (2.50 W to spare).");
    const auto other = html.find("Not chosen: Robot B: power budget 30.00 W (15.00 W over).");
    const auto chart = html.find("<b>Figure 1.</b> Best peak per platform.");
    const auto table = html.find("<b>Table 1.</b> Platforms at a glance");
    const auto details = html.find("Platform details");
    for (auto p : {rec, met, other, chart, table, details}) QVERIFY(p != std::string::npos);
    QVERIFY(rec < met && met < chart && chart < table && table < details);
  }

  // Issue #50.3: nothing recommended because the control loop is unknown for one platform and fails for the other.
  // Page one said "No platform can be recommended" and "Robot A: meets the constraints" (the unknown check has no
  // value and was left out of the reasons); now it names every check that decided it.
  void no_pick_never_says_a_platform_meets_everything() {
    bs::ReportInput in = two_robots();
    in.constraints = "a power budget of 15 W, a 1 kHz control loop";
    bs::ConstraintCheck unknown{
        "control loop: load not applied: pipeline@30fps ran at 9.29 of 30 fps (31 %)", "", 0, std::nullopt, false, 0};
    bs::ConstraintCheck p999{"p99.9 (pipeline@30fps)", "us", 200, 1500, false, -1300};
    in.verdicts[0].checks.push_back(unknown);
    in.verdicts[0].meets_all = in.verdicts[0].recommended = false;
    in.verdicts[1].checks.push_back(p999);
    const std::string html = bs::report_html(in);
    QVERIFY(html.find("No platform can be recommended") != std::string::npos);
    QVERIFY2(html.find("meets the constraints") == std::string::npos, html.c_str());
    QVERIFY2(
        html.find("Robot A: control loop: load not applied: pipeline@30fps ran at 9.29 of 30 fps") != std::string::npos,
        html.c_str());
    // A latency is a ceiling: over, not short.
    QVERIFY2(html.find("p99.9 1500.00 us (1300.00 us over)") != std::string::npos, html.c_str());
  }

  // Units in a column of their own, numbers bare; a measure no platform has is not a row; the peak says its device.
  void table_transposed_without_empty_rows() {
    const auto tables = bs::platform_summary_tables(two_robots().rows, two_robots().verdicts);
    QCOMPARE(tables.size(), std::size_t{1});
    const bs::ReportTable& t = tables[0];
    QCOMPARE(t.header.at(0), (std::vector<std::string>{"Measure", "Unit", "Robot A", "Robot B"}));
    const auto row = [&](const std::string& name) -> const std::vector<std::string>* {
      for (const auto& r : t.rows)
        if (r[0] == name) return &r;
      return nullptr;
    };
    QVERIFY(row("Mean power"));
    QCOMPARE(*row("Mean power"), (std::vector<std::string>{"Mean power", "W", "12.50", "30.00"}));
    QCOMPARE(row("GPU peak")->at(2), std::string("1.50 (GPU X, OpenCL)"));
    QCOMPARE(row("Of theoretical peak")->at(1), std::string("%"));
    QCOMPARE(row("Of theoretical peak")->at(2), std::string("50"));
    QCOMPARE(row("Battery runtime")->at(2), std::string("120.00"));
    QVERIFY(!row("CPU peak"));       // nobody has one
    QVERIFY(!row("Preprocessing"));  // no pipeline runs
    QVERIFY(!row("Max power"));
  }

  // Twelve platforms do not fit across a page with whole words: the table splits (at most eight platforms in one,
  // set smaller where needed), same rows in each part.
  void many_platforms_split() {
    std::vector<bs::PlatformRow> rows;
    for (int i = 0; i < 12; ++i) {
      bs::PlatformRow r;
      r.platform = "Platform number " + std::to_string(i);
      r.mean_power_w = i + 1;
      rows.push_back(r);
    }
    const auto tables = bs::platform_summary_tables(rows, {});
    QVERIFY(tables.size() >= 2);
    std::size_t platforms = 0;
    for (const auto& t : tables) {
      QCOMPARE(t.rows.size(), tables[0].rows.size());
      QVERIFY(t.header[0].size() <= 10);
      platforms += t.header[0].size() - 2;
    }
    QCOMPARE(platforms, std::size_t{12});
  }

  // Figures numbered in report order (the chart first), image and caption in one paragraph, template id said.
  void figures_numbered_with_captions() {
    const std::string html = bs::report_html(two_robots());
    QVERIFY(html.find("<img src=\"data:image/png;base64,AAAA\"") != std::string::npos);
    const auto fig2 = html.find("<img src=\"data:image/png;base64,AAAA\"");
    const auto cap2 = html.find("<b>Figure 2.</b> All GPUs: FLOPS against workers. (fig1a)");
    const auto fig3 = html.find("<img src=\"data:image/png;base64,BBBB\"");
    const auto cap3 = html.find("<b>Figure 3.</b> All CPUs: FLOPS against tasks. (fig2a)");
    QVERIFY(cap2 != std::string::npos && cap3 != std::string::npos);
    QVERIFY(fig2 < cap2 && cap2 < fig3 && fig3 < cap3);
    // Same paragraph: no </p> between an image and its caption.
    QVERIFY(html.substr(fig2, cap2 - fig2).find("</p>") == std::string::npos);
    QCOMPARE(count(html, "<b>Figure "), std::size_t{3});
  }

  void sources_appendix() {
    const std::string html = bs::report_html(two_robots());
    const auto appendix = html.find("Appendix A. Sources and provenance");
    QVERIFY(appendix != std::string::npos);
    QVERIFY(html.find("mean of a-current.csv x 12 V", appendix) != std::string::npos);
    QVERIFY(html.find("measured", appendix) != std::string::npos);
    QVERIFY(html.find("Figure 2 (fig1a): GPU X", appendix) != std::string::npos);
    QVERIFY(html.find("50.0 % of the theoretical peak") != std::string::npos);
    QVERIFY(html.find("1500.00 GFLOPS on GPU X (OpenCL, D = 4, 4096 workers)") != std::string::npos);
  }

  // A flagged number carries its footnote marker in the table, the note under it, and the reason in the details;
  // the details say how the power was measured.
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
    QVERIFY(html.find("[1] 5.25 TFLOPS is 5.9x the GPU X's FP32 peak &lt;here&gt;. In full: Platform details.") !=
            std::string::npos);
    QVERIFY(html.find("&#9888; above_spec_peak</b>: 5.25 TFLOPS") != std::string::npos);
    QVERIFY(html.find("Power measured by: on-board sensor: INA3221 VDD_IN.") != std::string::npos);
  }

  // A section is one function in a list: a list with one more writes it where it stands.
  void sections_are_a_list() {
    auto sections = bs::report_sections();
    // decision, details, inference, headroom (issue #45), sustained performance (#53), candidates, figures, sources
    QCOMPARE(sections.size(), std::size_t{8});
    sections.insert(sections.begin() + 1, [](const bs::ReportInput&, bs::ReportBuilder& b) {
      b.heading(2, "Candidates");
      b.paragraph("published results");
    });
    const std::string html = bs::report_html(two_robots(), sections);
    const auto candidates = html.find("<h2>Candidates</h2>");
    QVERIFY(candidates != std::string::npos);
    QVERIFY(candidates > html.find("Platforms at a glance") && candidates < html.find("Platform details"));
  }

  // The library's candidates (report --library) are a section of their own: after the details, before the figures,
  // and absent when none were asked for.
  void candidates_section_after_details() {
    bs::ReportInput in = two_robots();
    QVERIFY(bs::report_html(in).find("<h2>Candidates</h2>") == std::string::npos);
    bs::Candidate c;
    c.platform = "Orin";
    c.origin = bs::DataOrigin::Published;
    c.throughput_per_s = 1586;
    c.source = "https://github.com/mlcommons/inference_results_v3.0/blob/1948f9b/closed/NVIDIA/x.txt";
    in.candidates = bs::CandidatesSectionInput{{{"resnet50", "SingleStream", "int8", "", {c}}}, {}, "orin", "", ""};
    const std::string html = bs::report_html(in);
    const auto at = html.find("<h2>Candidates</h2>");
    QVERIFY(at != std::string::npos);
    QVERIFY(at > html.find("Platform details"));
    QVERIFY(at < html.rfind("Appendix A. Sources and provenance"));
    // A numbered table with the units in a header row, the source linked in the notes under it.
    QVERIFY(html.find("Candidates for resnet50, SingleStream, int8", at) != std::string::npos);
    QVERIFY(html.find("<tr class=\"units\"><th align=\"right\"></th>", at) != std::string::npos);
    QVERIFY(html.find("<a href=\"https://github.com/mlcommons/", at) != std::string::npos);
  }
};

QTEST_MAIN(TestPlatformReport)
#include "test_platform_report.moc"
