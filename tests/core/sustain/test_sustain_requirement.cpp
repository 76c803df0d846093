// SPDX-License-Identifier: GPL-3.0-or-later
// The sustained requirement (#53): its syntax and errors, and the verdicts on synthetic records whose stability,
// length and throttling are known by construction: pass, fail with its margin, unknown with its reason (no record, a
// run too short to say, throttling not exposed, an imported log without a rate), which record judges a platform,
// and how the verdicts change the recommendation.
#include <QTest>

#include "../../support/core_platform_verdicts.h"
#include "../../support/refusal.h"
#include "../../support/sustained_flops.h"
#include "sustain/sustain_requirement.h"

using namespace bs;
using namespace bs::sustain;

namespace {

// A record of `platform` with one interval of `step_s` seconds per rate.
SustainRun record(const std::string& platform, const std::vector<double>& rates, double step_s = 60) {
  auto r = bs::test::sustained_flops_run(platform, platform + " flops", step_s);
  r.rate = rates;
  for (std::size_t i = 0; i < rates.size(); ++i) r.t_s.push_back(static_cast<double>(i + 1) * step_s);
  return r;
}

// `n` intervals at `rate`, the interval `at` at `low` instead.
std::vector<double> steady(std::size_t n, double rate, std::size_t at = 0, double low = -1) {
  std::vector<double> v(n, rate);
  if (low >= 0) v[at] = low;
  return v;
}

// cpu0 at its 3 GHz maximum, from interval `drop_at` on at `dropped_hz`.
void add_clock(SustainRun& r, std::size_t drop_at, double dropped_hz) {
  ClockSeries c{"cpu0", 3e9, {}};
  for (std::size_t i = 0; i < r.t_s.size(); ++i) c.hz.push_back(i < drop_at ? 3e9 : dropped_hz);
  r.clocks.push_back(c);
}

const SustainVerdict& verdict_of(const std::vector<SustainVerdict>& v, const std::string& platform) {
  for (const SustainVerdict& x : v)
    if (x.platform == platform) return x;
  qFatal("no verdict for %s", platform.c_str());
}

QString error_of(const std::string& text) {
  return bs::test::refusal<std::invalid_argument>([&] { parse_sustain_requirement(text); });
}

}  // namespace

class TestSustainRequirement : public QObject {
  Q_OBJECT
 private slots:
  void parses_the_syntax() {
    const SustainRequirement r = parse_sustain_requirement("stability>=97%, minutes>=20");
    QCOMPARE(*r.min_stability_percent, 97.0);
    QCOMPARE(*r.min_minutes, 20.0);
    QVERIFY(!r.no_throttle && !r.min_sustained_rate);
    QCOMPARE(QString::fromStdString(describe(r)), QString("stability >= 97 %, at least 20 min"));
    const SustainRequirement s = parse_sustain_requirement("Throttle=None,sustained>=42.5,minutes>=10min");
    QVERIFY(s.no_throttle);
    QCOMPARE(*s.min_sustained_rate, 42.5);
    QCOMPARE(*s.min_minutes, 10.0);
    QVERIFY(!s.min_stability_percent);
    QCOMPARE(QString::fromStdString(s.text), QString("Throttle=None,sustained>=42.5,minutes>=10min"));
  }

  void rejects_what_it_cannot_read() {
    QVERIFY(error_of("").contains("no term to check"));
    QVERIFY(error_of("speed>=3").contains("term 'speed>=3': unknown term 'speed'"));
    QVERIFY(error_of("stability>=abc").contains("'abc' is not a number > 0"));
    QVERIFY(error_of("stability>=120%").contains("at most 100 %"));
    QVERIFY(error_of("stability>=97%,stability>=90%").contains("'stability' is given twice"));
    QVERIFY(error_of("throttle=some").contains("only throttle=none"));
    QVERIFY(error_of("minutes=20").contains("term 'minutes=20': a term is KEY>=VALUE"));
    QVERIFY(error_of("sustained>=50fps").contains("the record's own unit"));
    QCOMPARE(error_of("stability>=97%"), QString("(accepted)"));
  }

  void verdicts_pass_fail_unknown() {
    // nuc: 25 min, worst 99 of 100: passes by 2 points. jetson: 25 min, worst 91.2 of 100: fails by 5.8 points.
    // pi: 5 min at a steady 100: too short to say. orin: no record.
    const std::vector<SustainRun> runs = {record("pi", steady(5, 100)), record("jetson", steady(25, 100, 12, 91.2)),
                                          record("nuc", steady(25, 100, 3, 99))};
    const SustainRequirement r = parse_sustain_requirement("stability>=97%,minutes>=20");
    const std::vector<SustainVerdict> v = evaluate_sustain(r, runs, {"orin", "nuc"});
    QCOMPARE(v.size(), std::size_t{4});
    QCOMPARE(QString::fromStdString(v[0].platform), QString("nuc"));
    QCOMPARE(v[0].status, RequirementStatus::Pass);
    QCOMPARE(QString::fromStdString(v[0].margin),
             QString("run 25.0 min >= 20 min; stability 99.0 % >= 97 %, 2.0 points to spare"));
    QCOMPARE(QString::fromStdString(v[0].record), QString("nuc flops, 25.0 min"));
    QCOMPARE(QString::fromStdString(v[1].platform), QString("jetson"));
    QCOMPARE(v[1].status, RequirementStatus::Fail);
    QCOMPARE(QString::fromStdString(v[1].reason), QString("stability 91.2 % < 97 %, 5.8 points short"));
    QCOMPARE(QString::fromStdString(v[1].checks[1].name), QString("stability"));
    QCOMPARE(*v[1].checks[1].actual, 91.2);
    QVERIFY(qAbs(v[1].checks[1].margin + 5.8) < 1e-9);
    QCOMPARE(v[2].status, RequirementStatus::Unknown);
    QCOMPARE(v[3].status, RequirementStatus::Unknown);
    QCOMPARE(QString::fromStdString(verdict_of(v, "pi").reason),
             QString("run lasted 5.0 min < 20 min required: cannot say"));
    QCOMPARE(QString::fromStdString(verdict_of(v, "orin").reason), QString("no sustained run of this platform"));
  }

  // Worst / best over a longer run can only be lower: a short run that already fails stability fails.
  void a_short_run_fails_what_it_already_shows() {
    const std::vector<SustainRun> runs = {record("pi", steady(5, 100, 2, 80))};
    const std::vector<SustainVerdict> v =
        evaluate_sustain(parse_sustain_requirement("stability>=97%,minutes>=20"), runs, {});
    QCOMPARE(v[0].status, RequirementStatus::Fail);
    QCOMPARE(QString::fromStdString(v[0].reason), QString("stability 80.0 % < 97 %, 17.0 points short"));
  }

  void throttling_found_or_unknown() {
    const SustainRequirement r = parse_sustain_requirement("throttle=none");
    SustainRun hot = record("nuc", steady(20, 100), 1);
    add_clock(hot, 10, 1.8e9);  // 60 % of its maximum from 10 s on
    SustainRun cool = record("robot", steady(20, 100), 1);
    add_clock(cool, 20, 3e9);
    SustainRun blind = record("pi", steady(20, 100), 1);
    blind.not_exposed = {"no cpufreq under /sys/devices/system/cpu: no CPU clock"};
    const std::vector<SustainRun> runs = {hot, cool, blind};
    const std::vector<SustainVerdict> v = evaluate_sustain(r, runs, {});
    QCOMPARE(verdict_of(v, "robot").status, RequirementStatus::Pass);
    const SustainVerdict& nuc = verdict_of(v, "nuc");
    QCOMPARE(nuc.status, RequirementStatus::Fail);
    QVERIFY2(QString::fromStdString(nuc.reason).startsWith("throttled from 10.0 s (cpu0 at 1.8"), nuc.reason.c_str());
    QCOMPARE(*nuc.checks[0].actual, 10.0);  // 10 s of 20 throttled
    const SustainVerdict& pi = verdict_of(v, "pi");
    QCOMPARE(pi.status, RequirementStatus::Unknown);
    QVERIFY2(QString::fromStdString(pi.reason).startsWith("throttling unknown: no cpufreq under"), pi.reason.c_str());
  }

  // An imported log (tegrastats) has clocks but no load rate: it judges throttling and nothing else, never a pass
  // on a rate it does not have.
  void a_log_without_rate_judges_throttling_only() {
    SustainRun log = record("jetson", {}, 1);
    log.rate_unit.clear();
    log.load.clear();
    log.t_s = {1, 2, 3, 4};
    add_clock(log, 4, 3e9);
    const std::vector<SustainRun> runs = {log};
    QCOMPARE(evaluate_sustain(parse_sustain_requirement("throttle=none"), runs, {})[0].status, RequirementStatus::Pass);
    const SustainVerdict s = evaluate_sustain(parse_sustain_requirement("stability>=97%,throttle=none"), runs, {})[0];
    QCOMPARE(s.status, RequirementStatus::Unknown);
    QCOMPARE(QString::fromStdString(s.reason),
             QString("no load rate in the record (an imported log): stability cannot be judged"));
    QVERIFY(QString::fromStdString(s.record).endsWith("no load rate"));
    const SustainVerdict t = evaluate_sustain(parse_sustain_requirement("sustained>=10"), runs, {})[0];
    QCOMPARE(t.status, RequirementStatus::Unknown);
  }

  void the_sustained_rate_against_its_floor() {
    // 30 intervals: 100 for the first 20, 80 for the last third.
    std::vector<double> rates(30, 100);
    for (std::size_t i = 20; i < 30; ++i) rates[i] = 80;
    const std::vector<SustainRun> runs = {record("nuc", rates)};
    const SustainVerdict v = evaluate_sustain(parse_sustain_requirement("sustained>=90"), runs, {})[0];
    QCOMPARE(v.status, RequirementStatus::Fail);
    QCOMPARE(QString::fromStdString(v.reason), QString("sustained rate 80.0 GFLOPS < 90 GFLOPS, 10.0 GFLOPS short"));
    QCOMPARE(evaluate_sustain(parse_sustain_requirement("sustained>=75"), runs, {})[0].status, RequirementStatus::Pass);
  }

  // The longest record that answers every term judges; when none does, the newest says why.
  void which_record_judges() {
    SustainRun long_old = record("nuc", steady(30, 100));
    long_old.label = "long";
    long_old.provenance.date = "2026-01-01";
    SustainRun short_new = record("nuc", steady(10, 100));
    short_new.label = "short";
    short_new.provenance.date = "2026-02-01";
    const std::vector<SustainRun> runs = {long_old, short_new};
    const SustainVerdict a = evaluate_sustain(parse_sustain_requirement("minutes>=20,stability>=97%"), runs, {})[0];
    QCOMPARE(a.status, RequirementStatus::Pass);
    QCOMPARE(QString::fromStdString(a.record), QString("long, 2026-01-01, 30.0 min"));
    const SustainVerdict b = evaluate_sustain(parse_sustain_requirement("minutes>=40,stability>=97%"), runs, {})[0];
    QCOMPARE(b.status, RequirementStatus::Unknown);
    QCOMPARE(QString::fromStdString(b.record), QString("short, 2026-02-01, 10.0 min"));
    QCOMPARE(QString::fromStdString(b.reason), QString("run lasted 10.0 min < 40 min required: cannot say"));
  }

  void recommendation_counts_the_requirement() {
    // nuc: most compute, fails; jetson: no record, unknown, never passing.
    std::vector<PlatformVerdict> verdicts =
        bs::test::verdicts_meeting_all({{"nuc", 5e12}, {"robot", 1e12}, {"jetson", 3e12}});
    const std::vector<SustainRun> runs = {record("nuc", steady(25, 100, 3, 91.2)), record("robot", steady(25, 100))};
    const auto s =
        evaluate_sustain(parse_sustain_requirement("stability>=97%,minutes>=20"), runs, {"nuc", "robot", "jetson"});
    apply_sustain(verdicts, s);
    QVERIFY(!verdicts[0].meets_all && !verdicts[0].recommended);
    QVERIFY(verdicts[1].meets_all && verdicts[1].recommended);
    QVERIFY(!verdicts[2].meets_all && !verdicts[2].recommended);
    QCOMPARE(QString::fromStdString(unmet_text(verdicts[0].checks.back())),
             QString("stability 91.20 % of best (5.80 % of best short)"));
    QCOMPARE(QString::fromStdString(unmet_text(verdicts[2].checks.back())),
             QString("sustained: no sustained run of this platform"));
  }
};

QTEST_APPLESS_MAIN(TestSustainRequirement)
#include "test_sustain_requirement.moc"
