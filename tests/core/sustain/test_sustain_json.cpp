// SPDX-License-Identifier: GPL-3.0-or-later
// A sustained run's stored JSON (#53): written and read back unchanged (NaN as null), and every damage refused
// naming its place (what a hand-edited workspace would hold), before anything is copied; the CLI's result document
// carries the keys the issue names.
#include <QTest>

#include <cmath>
#include <limits>

#include "../../support/sustained_flops.h"
#include "sustain/sustain_json.h"

using namespace bs;
using namespace bs::sustain;
using nlohmann::json;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

SustainRun sample_run() {
  auto r = bs::test::sustained_flops_run("NUC", "flops for 3 s");
  r.t_s = {1.0, 2.001, 3.0};
  r.rate = {10.5, kNaN, 9.5};
  r.clocks = {{"cpu0", 3e9, {3e9, 2e9, kNaN}}, {"devfreq gpu", std::nullopt, {1e9, 1e9, 1e9}}};
  r.temperatures = {{"thermal_zone0 x86_pkg_temp", 95.0, {60, 70, 96}}};
  r.power_w = {20, 21, kNaN};
  r.power_sensor = "rapl:package-0";
  r.not_exposed = {"no hwmon temperature under /sys/class/hwmon"};
  r.provenance.origin = DataOrigin::Measured;
  r.provenance.host = "nuc";
  return r;
}

bool same(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!(a[i] == b[i] || (std::isnan(a[i]) && std::isnan(b[i])))) return false;
  return true;
}

QString refusal(const json& j) {
  try {
    record_from_json(j);
  } catch (const SustainJsonError& e) {
    return QString::fromStdString(e.what());
  }
  return QStringLiteral("(accepted)");
}

}  // namespace

class TestSustainJson : public QObject {
  Q_OBJECT
 private slots:
  void round_trip() {
    const SustainRun r = sample_run();
    const SustainRun b = record_from_json(json::parse(record_to_json(r).dump()));
    QCOMPARE(b.platform, r.platform);
    QCOMPARE(b.label, r.label);
    QCOMPARE(b.load, r.load);
    QCOMPARE(b.rate_unit, r.rate_unit);
    QVERIFY(same(b.t_s, r.t_s));
    QVERIFY(same(b.rate, r.rate));
    QCOMPARE(b.clocks.size(), std::size_t{2});
    QCOMPARE(b.clocks[0].max_hz, r.clocks[0].max_hz);
    QVERIFY(!b.clocks[1].max_hz);
    QVERIFY(same(b.clocks[0].hz, r.clocks[0].hz));
    QCOMPARE(b.temperatures[0].trip_c, r.temperatures[0].trip_c);
    QVERIFY(same(b.temperatures[0].celsius, r.temperatures[0].celsius));
    QVERIFY(same(b.power_w, r.power_w));
    QCOMPARE(b.power_sensor, r.power_sensor);
    QCOMPARE(b.not_exposed, r.not_exposed);
    QCOMPARE(b.provenance.host, std::string("nuc"));
  }

  void a_log_without_rate_round_trips() {
    SustainRun r = sample_run();
    r.rate.clear();
    r.rate_unit.clear();
    r.power_w.clear();
    const SustainRun b = record_from_json(record_to_json(r));
    QVERIFY(b.rate.empty() && b.power_w.empty());
  }

  void damage_is_named() {
    const json good = record_to_json(sample_run());
    json j = good;
    j["clocks"][0]["hz"].erase(0);
    QCOMPARE(refusal(j), QStringLiteral("sustain.clocks[0].hz: 2 values for 3 intervals"));
    j = good;
    j["t_s"][2] = 1.5;
    QCOMPARE(refusal(j), QStringLiteral("sustain.t_s[2]: does not increase"));
    j = good;
    j["rate"][0] = "fast";
    QCOMPARE(refusal(j), QStringLiteral("sustain.rate[0]: '\"fast\"' is not a number"));
    j = good;
    j["rate"][0] = -1;
    QVERIFY(refusal(j).startsWith("sustain.rate[0]: -1 is outside"));
    j = good;
    j.erase("platform");
    QCOMPARE(refusal(j), QStringLiteral("sustain: 'platform' is missing"));
    j = good;
    j["temperatures"] = 5;
    QCOMPARE(refusal(j), QStringLiteral("sustain.temperatures: is not an array"));
    j = good;
    j["rate_unit"] = "";
    QCOMPARE(refusal(j), QStringLiteral("sustain.rate_unit: is empty for a record with a rate"));
    QCOMPARE(refusal(json::array()), QStringLiteral("sustain: is not an object"));
  }

  void result_carries_the_named_keys() {
    const SustainRun r = sample_run();
    const json j = result_json(r, analyse(r));
    for (const char* key : {"intervals", "stability_percent", "stable", "throttle", "sustained_rate", "peak_rate",
                            "rate_unit", "not_exposed", "first_slow", "steady_s"})
      QVERIFY2(j.contains(key), key);
    QCOMPARE(j["intervals"].size(), std::size_t{3});
    QCOMPARE(j["intervals"][0]["t_s"].get<double>(), 1.0);
    QVERIFY(j["intervals"][1]["rate"].is_null());
    QCOMPARE(j["intervals"][1]["clocks_hz"]["cpu0"].get<double>(), 2e9);
    QCOMPARE(j["intervals"][2]["temperatures_c"]["thermal_zone0 x86_pkg_temp"].get<double>(), 96.0);
    QCOMPARE(j["intervals"][0]["power_w"].get<double>(), 20.0);
    QVERIFY(j["throttle"]["detected"].get<bool>());
    QCOMPARE(j["throttle"]["onset_s"].get<double>(), 1.0);  // cpu0 at 2 GHz of 3 from the second interval
    QCOMPARE(j["peak_rate"].get<double>(), 10.5);
  }
};

QTEST_APPLESS_MAIN(TestSustainJson)
#include "test_sustain_json.moc"
