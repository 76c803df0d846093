// SPDX-License-Identifier: GPL-3.0-or-later
// The STREAM triad on every backend that has one: verified results become a result set in B/s, one value per
// repetition, with measured provenance; cancellation and bad sizes are refused cleanly.
#include <QTest>

#include "kernels/ceilings/bandwidth.h"

using namespace bs::kernels;

class TestBandwidth : public QObject {
  Q_OBJECT
 private slots:
  void every_backend_with_a_triad() {
    const CpuInfo cpu = detect_cpu(false);
    int measured = 0;
    for (const Backend& b : available_backends(cpu)) {
      if (!b.run_triad) continue;
      const bs::ResultSet set = measure_bandwidth(b, cpu, {.mib_per_array = 4, .repeats = 2}, bs::CancelToken{});
      QCOMPARE(set.source_format, std::string(kBandwidthSource));
      QCOMPARE(set.device, b.device_name);
      QCOMPARE(set.measurements.size(), std::size_t{1});
      const bs::Measurement& m = set.measurements[0];
      QCOMPARE(m.unit, std::string("B/s"));
      QCOMPARE(m.values.size(), std::size_t{2});
      for (double v : m.values) QVERIFY(v > 1e6 && std::isfinite(v));
      QCOMPARE(set.provenance.origin, bs::DataOrigin::Measured);
      ++measured;
    }
    QVERIFY(measured >= 2);  // cpu-simd and cpu-scalar at least
  }
  void refusals() {
    const CpuInfo cpu = detect_cpu(false);
    Backend none;
    none.id = "none";
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, measure_bandwidth(none, cpu, {}, bs::CancelToken{}));
    const Backend cpu_backend = cpu_backends(cpu).front();
    QVERIFY_THROWS_EXCEPTION(
        std::invalid_argument,
        measure_bandwidth(cpu_backend, cpu, {.mib_per_array = 0, .repeats = 1}, bs::CancelToken{}));
    bs::CancelToken cancelled;
    cancelled.cancel();
    QVERIFY_THROWS_EXCEPTION(bs::Cancelled,
                             measure_bandwidth(cpu_backend, cpu, {.mib_per_array = 1, .repeats = 1}, cancelled));
  }
};

QTEST_APPLESS_MAIN(TestBandwidth)
#include "test_bandwidth.moc"
