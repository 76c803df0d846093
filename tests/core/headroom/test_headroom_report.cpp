// SPDX-License-Identifier: GPL-3.0-or-later
// The report's control-loop section: each measurement's kernel facts and table, the non-real-time warning, and with
// a requirement the verdict per platform (unknown for a platform without a measurement); nothing without either.
#include <QTest>

#include "headroom/latency_recorder.h"
#include "headroom/loop_requirement.h"
#include "report/platform_report.h"
#include "report/report_sections.h"

using namespace bs::headroom;

class TestHeadroomReport : public QObject {
  Q_OBJECT
 private slots:
  void section_in_the_report() {
    bs::ReportInput in;
    in.workspace = "w.bsw";
    std::string html = bs::report_html(in);
    QVERIFY(!QString::fromStdString(html).contains("Control-loop headroom"));

    HeadroomMeasurement m;
    m.platform = "robot";
    m.kind = LatencyKind::ApplicationLoop;
    m.tool = "benchscope probe";
    m.kernel.release = "6.1.0-rt";
    m.kernel.preemption = "PREEMPT_RT";
    Phase p;
    p.name = "pipeline@30fps";
    LatencyRecorder r(1'000'000, 1000, 1'000'000);
    for (int i = 0; i < 100; ++i) r.add(42'000);
    ThreadLatency t = r.result();
    t.policy = "SCHED_OTHER";
    t.period_ns = 1'000'000;
    p.threads.push_back(t);
    m.phases.push_back(p);
    in.headroom = {m};
    in.loop = parse_loop_requirement("1kHz,p99<=100us,load=pipeline@30fps");
    in.loop_verdicts = evaluate_loop(*in.loop, in.headroom, {"robot", "nuc"});
    html = bs::report_html(in);
    const QString h = QString::fromStdString(html);
    QVERIFY(h.contains("Control-loop headroom"));
    QVERIFY(h.contains("1 kHz, p99 &lt;= 100 us, beside pipeline@30fps") || h.contains("1 kHz, p99 <= 100 us"));
    QVERIFY(h.contains("kernel 6.1.0-rt, PREEMPT_RT"));
    QVERIFY(h.contains("NON-REAL-TIME"));
    QVERIFY(h.contains("42 us"));                    // p50 of the table
    QVERIFY(h.contains("no headroom measurement"));  // the nuc
  }
};

QTEST_APPLESS_MAIN(TestHeadroomReport)
#include "test_headroom_report.moc"
