// SPDX-License-Identifier: GPL-3.0-or-later
// The report's sustained section (#53): with a requirement, the verdict per platform with its margin or reason and
// the run that judged it, and "Not chosen" naming the unmet check; nothing without a requirement.
#include <QTest>

#include "report/platform_report.h"
#include "sustain/sustain_requirement.h"

using namespace bs;
using namespace bs::sustain;

namespace {

// 25 intervals of a minute at 100 GFLOPS, the fourth at `low`.
SustainRun run_of(const std::string& platform, double low) {
  SustainRun r;
  r.platform = platform;
  r.label = platform + " flops for 1500 s";
  r.rate_unit = "GFLOPS";
  for (int i = 0; i < 25; ++i) {
    r.t_s.push_back(60.0 * (i + 1));
    r.rate.push_back(i == 3 ? low : 100);
  }
  return r;
}

}  // namespace

class TestSustainReport : public QObject {
  Q_OBJECT
 private slots:
  void section_and_not_chosen() {
    ReportInput in;
    in.workspace = "w.bsw";
    QVERIFY(!QString::fromStdString(report_html(in)).contains("Sustained performance"));
    in.verdicts.resize(3);
    in.verdicts[0].platform = "nuc";  // the most compute, fails
    in.verdicts[0].ranked_flops = 5e12;
    in.verdicts[1].platform = "robot";
    in.verdicts[1].ranked_flops = 1e12;
    in.verdicts[2].platform = "pi";  // no sustained run
    in.verdicts[2].ranked_flops = 2e12;
    const std::vector<SustainRun> runs = {run_of("nuc", 91.2), run_of("robot", 99)};
    in.sustained = parse_sustain_requirement("stability>=97%,minutes>=20");
    in.sustained_verdicts = evaluate_sustain(*in.sustained, runs, {"nuc", "robot", "pi"});
    apply_sustain(in.verdicts, in.sustained_verdicts);
    in.constraints = "sustained " + describe(*in.sustained);
    const QString h = QString::fromStdString(report_html(in));
    QVERIFY(h.contains("Sustained performance"));
    QVERIFY(h.contains("stability &gt;= 97 %, at least 20 min") || h.contains("stability >= 97 %, at least 20 min"));
    QVERIFY(h.contains("stability 91.2 % &lt; 97 %, 5.8 points short"));
    QVERIFY(h.contains("robot flops for 1500 s, 25.0 min"));
    QVERIFY2(h.contains("nuc: stability 91.20 % of best (5.80 % of best short)"), qPrintable(h));
    QVERIFY(h.contains("pi: sustained: no sustained run of this platform"));
    QVERIFY(in.verdicts[1].recommended);
  }
};

QTEST_APPLESS_MAIN(TestSustainReport)
#include "test_sustain_report.moc"
