// SPDX-License-Identifier: GPL-3.0-or-later
#include <QtTest>
#include <cmath>

#include "kernels/rotation.h"
#include "kernels/rotation_simd.h"

using namespace bs::kernels;

class TestRotation : public QObject {
  Q_OBJECT
 private slots:
  void scalar_matches_closed_form() {
    for (int d : {1, 2, 4}) {
      const RotationParams p{d, 1000};
      std::vector<float> out(5);
      rotate_scalar(p, out);
      QCOMPARE(first_wrong_output(out, p), std::int64_t{-1});
      QVERIFY(std::abs(out[0] - d * (std::cos(2000.0) + std::sin(2000.0))) < 1e-3);
    }
  }
  void closed_form_check_catches_wrong_values() {
    const RotationParams p{2, 100};
    std::vector<float> out(3, static_cast<float>(closed_form_output(p)));
    QCOMPARE(first_wrong_output(out, p), std::int64_t{-1});
    out[1] += 0.1f;
    QCOMPARE(first_wrong_output(out, p), std::int64_t{1});
    out[1] = std::nanf("");
    QCOMPARE(first_wrong_output(out, p), std::int64_t{1});
  }
  void every_isa_and_variant_matches_the_scalar_reference() {
    for (const SimdTarget& t : available_simd_targets())
      for (Variant v : {Variant::Paper, Variant::Throughput})
        for (int d : {1, 2, 4, 5})
          for (std::int64_t w : {1, 3, 17, 100}) {
            const RotationParams p{d, 1000};
            SimdRotation rot(t, v, p, w);
            rot.advance(400);  // in two chunks, as a cancellable run does
            rot.advance(600);
            std::vector<float> out(static_cast<std::size_t>(w));
            rot.outputs(out);
            std::vector<float> ref(static_cast<std::size_t>(w));
            rotate_scalar(p, ref);
            const QByteArray where = QString("%1 %2 D=%3 W=%4").arg(QString::fromStdString(t.name),
                                                                     QString::fromStdString(variant_name(v))).arg(d).arg(w).toUtf8();
            QVERIFY2(first_wrong_output(out, p) == -1, where.constData());
            for (std::size_t i = 0; i < out.size(); ++i) QVERIFY2(std::abs(out[i] - ref[i]) < 1e-3, where.constData());
          }
  }
  void rejects_bad_sizes() {
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, SimdRotation(best_simd_target(), Variant::Throughput, {4, 10}, 0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, SimdRotation(best_simd_target(), Variant::Paper, {0, 10}, 4));
  }
};

QTEST_APPLESS_MAIN(TestRotation)
#include "test_rotation.moc"
