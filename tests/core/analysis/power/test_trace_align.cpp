// SPDX-License-Identifier: GPL-3.0-or-later
// Overlay alignment: offsets that put the same phase of every trace at one moment, and the phase names shared.
#include <QTest>

#include "analysis/power/trace_align.h"

class TestTraceAlign : public QObject {
  Q_OBJECT
 private slots:
  void align_at_phase() {
    const std::vector<std::vector<bs::TracePhase>> phases = {
        {{"idle", 0, 4}, {"benchmark", 4.5, 30}},
        {{"warm-up", 0, 10}, {"benchmark", 12.25, 40}, {"benchmark", 50, 60}},  // the first of a name counts
        {{"idle", 0, 3}}};
    const auto at0 = bs::align_at_phase(phases, "benchmark");
    QCOMPARE(at0.size(), std::size_t{3});
    QCOMPARE(*at0[0], -4.5);
    QCOMPARE(*at0[1], -12.25);
    QVERIFY(!at0[2]);  // no such phase: left as it was
    const auto at10 = bs::align_at_phase(phases, "benchmark", 10);
    QCOMPARE(*at10[0] + 4.5, 10.0);  // the phase now starts at 10 s on the shared axis
    QCOMPARE(*at10[1] + 12.25, 10.0);
    QCOMPARE(bs::shared_phase_names(phases), (std::vector<std::string>{"idle", "benchmark"}));
    QCOMPARE(bs::shared_phase_names(phases, 1), (std::vector<std::string>{"idle", "benchmark", "warm-up"}));
  }
};

QTEST_APPLESS_MAIN(TestTraceAlign)
#include "test_trace_align.moc"
