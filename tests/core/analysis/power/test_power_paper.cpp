// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's current-consumption section, recomputed from sample_data through the importer and core:
// mean current (SD), power at 16 V, GFLOPS/W with the GPU peaks, battery life on 14.8 V x 3.85 Ah.
#include <QTest>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include "../../../support/paper_sample.h"

#include "analysis/platform/efficiency.h"
#include "analysis/platform/platform_efficiency.h"
#include "analysis/power/battery.h"
#include "analysis/power/power_stats.h"
#include "workspace/registry.h"

namespace {

double round2(double v) { return std::round(v * 100) / 100; }

}  // namespace

class TestPowerPaper : public QObject {
  Q_OBJECT
 private slots:
  void reproduces_the_paper_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<double>("mean_a");
    QTest::addColumn<double>("sd_a");
    QTest::addColumn<double>("mean_w");
    QTest::addColumn<double>("peak_flops");
    QTest::addColumn<double>("gflops_per_w");
    QTest::addColumn<double>("minutes");
    QTest::newRow("NUC") << "nuc-current.csv" << 2.53 << 0.35 << 40.52 << 5.25e12 << 104.64 << 84.36;
    QTest::newRow("Jetson") << "jetson-current.csv" << 0.59 << 0.09 << 9.48 << 0.49e12 << 41.26 << 360.48;
  }
  void reproduces_the_paper() {
    QFETCH(QString, file);
    QFETCH(double, mean_a);
    QFETCH(double, sd_a);
    QFETCH(double, mean_w);
    QFETCH(double, peak_flops);
    QFETCH(double, gflops_per_w);
    QFETCH(double, minutes);
    const bs::ImportBatch batch =
        bs::import_file(BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018/power/" + file.toStdString(), bs::CancelToken{});
    QCOMPARE(batch.format, std::string("power-csv"));
    const bs::PowerTrace& trace = batch.power_traces.at(0);
    QCOMPARE(trace.provenance.origin, bs::DataOrigin::Reconstructed);
    QCOMPARE(*trace.supply_voltage_v, 16.0);  // from the log's "# supply_voltage_V: 16"
    const bs::PowerStats s = bs::power_stats(trace);
    QCOMPARE(s.power_source, bs::PowerSource::CurrentTimesSupply);
    QCOMPARE(round2(s.current_a->summary.mean), mean_a);
    QCOMPARE(round2(s.current_a->summary.sd), sd_a);
    QCOMPARE(round2(s.power_w->summary.mean), mean_w);
    QCOMPARE(round2(bs::paper_gflops_per_watt(peak_flops, *s.supply_v, s.current_a->summary.max)), gflops_per_w);
    const bs::DischargeResult battery =
        bs::simulate_discharge(*bs::find_battery_preset("paper-4s-3850"), bs::constant_load(s.power_w->summary.mean));
    QCOMPARE(round2(battery.runtime_s / 60), minutes);
    // The honest variants are smaller numbers of the same kind, labelled as such.
    bs::EfficiencyInputs in;
    in.peak_flops = peak_flops;
    in.supply_v = s.supply_v;
    in.max_current_a = s.current_a->summary.max;
    in.mean_power_w = s.power_w->summary.mean;
    const auto figures = bs::efficiency_figures(in);
    QCOMPARE(round2(figures[0].value), gflops_per_w);
    QVERIFY(figures[1].value > figures[0].value);  // mean power is below supply x max current
    QVERIFY(figures[1].label.find("mean power") != std::string::npos);
  }

  // Each platform's best run, whatever its device, paired with its log: the rows the CLI and the GUI show.
  void platform_efficiency_picks_the_best_run() {
    auto [runs, traces, pipelines] = bs::test::load_paper_sample();
    std::sort(traces.begin(), traces.end(), [](const auto& a, const auto& b) { return a.platform > b.platform; });
    const bs::EfficiencyComparison table = bs::compare_efficiency(runs, traces);
    const auto& rows = table.rows;
    QCOMPARE(rows.size(), std::size_t{2});  // only the NUC and the Jetson have current logs
    QCOMPARE(rows[0].peak.platform, std::string("NUC"));
    QCOMPARE(rows[0].peak.backend, std::string("OpenCL"));
    QCOMPARE(round2(rows[0].peak.peak.flops / 1e12), 5.25);
    QCOMPARE(round2(rows[0].power_w.mean), 40.52);
    QCOMPARE(round2(*rows[0].paper_gflops_per_w), 104.64);
    QCOMPARE(rows[1].peak.platform, std::string("Jetson TX2"));
    QCOMPARE(rows[1].peak.backend, std::string("CUDA"));
    QCOMPARE(round2(rows[1].power_w.mean), 9.48);
    QCOMPARE(round2(*rows[1].paper_gflops_per_w), 41.26);
    QCOMPARE(*rows[1].supply_v, 16.0);
    QCOMPARE(rows[1].current_a->n, std::size_t{1200});
    QCOMPARE(rows[1].joules_per_gflop, rows[1].power_w.mean / (rows[1].peak.peak.flops / 1e9));
    QVERIFY(rows[1].mean_power_gflops_per_w > *rows[1].paper_gflops_per_w);
    QVERIFY(rows[1].paper_missing.empty());
    // The desktop and the laptop have runs and no log: named, with the reason, not dropped.
    QCOMPARE(table.left_out.size(), std::size_t{2});
    for (const bs::EfficiencyLeftOut& l : table.left_out)
      QCOMPARE(l.reason, std::string("no power log of this platform"));
    // A supply override changes the paper's figure in proportion (current stays what was measured).
    const auto at12 = bs::platform_efficiency(runs, traces, 12.0);
    QCOMPARE(*at12[0].paper_gflops_per_w, *rows[0].paper_gflops_per_w * 16 / 12);
  }

  // Issue #50.5: a tegrastats log (the module's input rail in mW, no supply current) gives its platform the
  // mean-power figures and says why the paper's is missing; a log of a platform without runs is named with why.
  void a_log_of_power_only_gives_the_mean_power_figures() {
    auto [runs, traces, pipelines] = bs::test::load_paper_sample();
    std::vector<bs::PowerTrace> logs;
    for (const char* file : {"tegrastats-tx2-jetpack4.log", "tegrastats-orin-jetpack6.log"})
      for (bs::PowerTrace& t :
           bs::import_file(std::string(BENCHSCOPE_TEST_DATA_DIR "/power/") + file, bs::CancelToken{}).power_traces)
        logs.push_back(std::move(t));
    QCOMPARE(logs.size(), std::size_t{2});
    logs[0].platform = "Jetson TX2";  // as the import's platform question answers it
    logs[1].platform = "Jetson AGX Orin";
    std::vector<bs::PowerTrace> nuc_and_tegrastats{traces[0].platform == "NUC" ? traces[0] : traces[1]};
    nuc_and_tegrastats.insert(nuc_and_tegrastats.end(), logs.begin(), logs.end());
    const bs::EfficiencyComparison table = bs::compare_efficiency(runs, nuc_and_tegrastats);
    QCOMPARE(table.rows.size(), std::size_t{2});
    const bs::PlatformEfficiency& tx2 = table.rows[1];
    QCOMPARE(tx2.peak.platform, std::string("Jetson TX2"));
    QVERIFY(!tx2.paper_gflops_per_w && !tx2.current_a && !tx2.supply_v);
    QVERIFY2(tx2.paper_missing.find("measures power, not a supply current") != std::string::npos,
             tx2.paper_missing.c_str());
    QVERIFY(tx2.power_w.mean > 1 && tx2.power_w.mean < 20);  // VDD_IN, watts
    QCOMPARE(tx2.mean_power_gflops_per_w, tx2.peak.peak.flops / 1e9 / tx2.power_w.mean);
    QCOMPARE(tx2.figures.size(), std::size_t{2});  // at mean power and J/GFLOP
    std::map<std::string, std::string> left_out;
    for (const bs::EfficiencyLeftOut& l : table.left_out) left_out[l.platform] = l.reason;
    QCOMPARE(left_out.size(), std::size_t{3});
    QVERIFY2(left_out["Jetson AGX Orin"].find("no FLOPS run") != std::string::npos,
             left_out["Jetson AGX Orin"].c_str());
    QCOMPARE(left_out["Desktop (Alienware Area-51)"], std::string("no power log of this platform"));
  }
};

QTEST_APPLESS_MAIN(TestPowerPaper)
#include "test_power_paper.moc"
