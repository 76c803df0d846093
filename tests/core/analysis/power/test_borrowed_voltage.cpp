// SPDX-License-Identifier: GPL-3.0-or-later
// A current-only log's voltage borrowed from another log (issue #32.2): interpolated on the current log's time
// axis, lined up by absolute start times, NaN (never extrapolated) outside the source; and the words saying why a
// log gives no power.
#include <QTest>
#include <cmath>

#include "analysis/power/borrowed_voltage.h"
#include "analysis/power/power.h"
#include "common/log_platform.h"

namespace {

bs::PowerTrace clamp() {
  bs::PowerTrace t;
  t.label = "clamp";
  t.start_time = "2026-11-26T10:00:01";
  t.time_s = {0, 1, 2, 3, 4};
  t.channels.push_back({"I", bs::PowerQuantity::Current, {1, 1, 1, 1, 1}});
  return t;
}

bs::PowerTrace supply() {
  bs::PowerTrace t;
  t.label = "supply";
  t.start_time = "2026-11-26T10:00:00";  // one second before the clamp's first sample
  t.time_s = {0, 2, 4};
  t.channels.push_back({"V", bs::PowerQuantity::Voltage, {10, 12, 14}});
  return t;
}

}  // namespace

class TestBorrowedVoltage : public QObject {
  Q_OBJECT
 private slots:
  void interpolated_on_the_shared_time_axis() {
    bs::PowerTrace t = clamp();
    QVERIFY(bs::why_no_power(t));
    QVERIFY(bs::borrow_voltage(t, supply(), "V"));
    QCOMPARE(t.channels.size(), std::size_t{2});
    const bs::PowerChannel& v = t.channels[1];
    QCOMPARE(v.name, std::string("V from supply"));
    QVERIFY(v.quantity == bs::PowerQuantity::Voltage);
    // Clamp time k is supply time k + 1: 11, 12, 13, 14 V, then past the supply's last sample: missing.
    QCOMPARE(v.values[0], 11.0);
    QCOMPARE(v.values[1], 12.0);
    QCOMPARE(v.values[2], 13.0);
    QCOMPARE(v.values[3], 14.0);
    QVERIFY(std::isnan(v.values[4]));
    QVERIFY(!bs::why_no_power(t));
    QCOMPARE(bs::power_series(t)[2], 13.0);
    // Borrowing again replaces the borrowed channel instead of adding a second one.
    QVERIFY(bs::borrow_voltage(t, supply(), "V"));
    QCOMPARE(t.channels.size(), std::size_t{2});
  }

  void without_absolute_times_both_start_at_zero() {
    bs::PowerTrace t = clamp(), s = supply();
    t.start_time.clear();
    QVERIFY(bs::borrow_voltage(t, s, "V"));
    QCOMPARE(t.channels[1].values[1], 11.0);
  }

  void nothing_to_borrow() {
    bs::PowerTrace t = clamp();
    QVERIFY(!bs::borrow_voltage(t, supply(), "missing"));
    QVERIFY(!bs::borrow_voltage(t, clamp(), "I"));  // a current channel is no voltage
    QCOMPARE(t.channels.size(), std::size_t{1});
    QVERIFY(bs::why_no_power(t)->find("current only") == 0);
    bs::PowerTrace none;
    none.time_s = {0, 1};
    none.channels.push_back({"V", bs::PowerQuantity::Voltage, {5, 5}});
    QCOMPARE(*bs::why_no_power(none), std::string("no current or power channel"));
    t.supply_voltage_v = 16;
    QVERIFY(!bs::why_no_power(t));
  }

  void a_log_platform_is_never_blank() {
    bs::PowerTrace t = clamp();
    QCOMPARE(bs::infer_log_platform(t, {}).platform, std::string("unassigned: clamp"));
    QCOMPARE(bs::infer_log_platform(t, {"NUC"}).platform, std::string("NUC"));
    QCOMPARE(bs::infer_log_platform(t, {"NUC"}).how, std::string("the workspace's only platform"));
    QCOMPARE(bs::infer_log_platform(t, {"NUC", "Jetson"}).platform, std::string("unassigned: clamp"));
    t.provenance.host = "nuc";
    QCOMPARE(bs::infer_log_platform(t, {"NUC", "Jetson"}).platform, std::string("NUC"));  // the workspace's spelling
    t.provenance.settings.push_back({"Device", "Jetson TX2"});
    QCOMPARE(bs::infer_log_platform(t, {}).platform, std::string("Jetson TX2"));
    t.platform = "Named";
    QCOMPARE(bs::infer_log_platform(t, {}).platform, std::string("Named"));
  }
};

QTEST_APPLESS_MAIN(TestBorrowedVoltage)
#include "test_borrowed_voltage.moc"
