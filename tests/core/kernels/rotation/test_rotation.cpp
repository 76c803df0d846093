// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>
#include <cmath>

#include "kernels/cpu/cpu_info.h"
#include "kernels/rotation/rotation.h"
#include "kernels/rotation/rotation_simd.h"
#include "kernels/step_chunker.h"

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
            const QByteArray where = QString("%1 %2 D=%3 W=%4")
                                         .arg(QString::fromStdString(t.name), QString::fromStdString(variant_name(v)))
                                         .arg(d)
                                         .arg(w)
                                         .toUtf8();
            QVERIFY2(first_wrong_output(out, p) == -1, where.constData());
            for (std::size_t i = 0; i < out.size(); ++i) QVERIFY2(std::abs(out[i] - ref[i]) < 1e-3, where.constData());
          }
  }
  // The kernels the tests above compared are this CPU's own: on ARM64 the generic 128-bit code is NEON with FMA
  // (fmla), the only target there; on x86 the generic one comes last, after the -m flag builds the CPU supports.
  void the_targets_are_the_platforms_own() {
    const std::vector<SimdTarget> targets = available_simd_targets();
    QVERIFY(!targets.empty());
#if defined(__aarch64__)
    QCOMPARE(targets.size(), std::size_t{1});
    QCOMPARE(targets.front().name, std::string("NEON"));
    QCOMPARE(targets.front().isa, Isa::Generic);
    QCOMPARE(targets.front().lanes, 4);
    QVERIFY(targets.front().fma);
#else
    QCOMPARE(targets.back().isa, Isa::Generic);
    QCOMPARE(targets.back().lanes, 4);
#endif
  }
  void cancellable_run_equals_advance() {
    for (const SimdTarget& t : available_simd_targets())
      for (Variant v : {Variant::Paper, Variant::Throughput}) {
        const RotationParams p{4, 3000};
        SimdRotation a(t, v, p, 300), b(t, v, p, 300);
        a.advance(p.iterations);
        b.run(p.iterations, bs::CancelToken{});
        std::vector<float> oa(300), ob(300);
        a.outputs(oa);
        b.outputs(ob);
        QCOMPARE(oa, ob);
        QCOMPARE(first_wrong_output(ob, p), std::int64_t{-1});
        bs::CancelToken cancel;
        cancel.cancel();
        QVERIFY_THROWS_EXCEPTION(bs::Cancelled, b.run(p.iterations, cancel));
      }
  }
  void scalar_in_chunks_equals_one_go() {
    const RotationParams p{4, 1000};
    ScalarRotation chunked(p, 3);
    chunked.advance(1);
    chunked.advance(299);
    chunked.advance(700);
    std::vector<float> a(3), b(3);
    chunked.outputs(a);
    rotate_scalar(p, b);
    QCOMPARE(a, b);  // same operations in the same order: bit-identical
  }
  void rejects_bad_sizes() {
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, SimdRotation(best_simd_target(), Variant::Throughput, {4, 10}, 0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, SimdRotation(best_simd_target(), Variant::Paper, {0, 10}, 4));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ScalarRotation({4, 0}, 4));
    // Refused before allocating: 2^27 workers x 4 points is twice the state limit.
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, check_problem_size({4, 10}, kMaxStatePoints / 2));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, check_problem_size({64, 10}, std::int64_t{1} << 62));
    check_problem_size({4, 40000}, 1'024'000);  // the paper's largest point
  }
  void peak_model_counts_pipes_and_lanes() {
    // With FMA: 2 mul + 2 FMA per vector step on the mul/FMA pipes.
    QCOMPARE(rotation_flops_per_cycle(16, true, 2, false), 48.0);  // AVX-512, 2 FMA pipes
    QCOMPARE(rotation_flops_per_cycle(16, true, 1, true), 24.0);   // AVX-512 double-pumped (Zen 4)
    QCOMPARE(rotation_flops_per_cycle(8, true, 2, false), 24.0);   // AVX2 + FMA
    QCOMPARE(rotation_flops_per_cycle(4, true, 2, true), 12.0);    // NEON
    // Without FMA: 4 mul + 2 add; separate add pipes leave the 4 muls as the bound.
    QCOMPARE(rotation_flops_per_cycle(4, false, 2, false), 8.0);  // SSE4.1, Intel shared ports
    QCOMPARE(rotation_flops_per_cycle(4, false, 2, true), 12.0);  // SSE4.1, AMD
    QCOMPARE(rotation_flops_per_cycle(1, false, 2, false), 2.0);  // scalar reference
  }
  void cpu_detection_is_consistent() {
    const CpuInfo cpu = detect_cpu(false);
    QVERIFY(!cpu.model.empty());
    QVERIFY(cpu.threads >= 1);
    QCOMPARE(cpu.simd.name, best_simd_target().name);
    QCOMPARE(cpu.flops_per_cycle,
             rotation_flops_per_cycle(cpu.simd.lanes, cpu.simd.fma, cpu.fma_ports, cpu.separate_add_pipes));
    QCOMPARE(cpu.peak_flops, 0.0);  // not calibrated
  }
  void chunker_covers_every_step_once() {
    for (std::int64_t total : {std::int64_t{1}, std::int64_t{7}, std::int64_t{40000}, std::int64_t{3'000'000'000}}) {
      StepChunker chunks(total, 1);
      std::int64_t done = 0, launches = 0;
      while (!chunks.done()) {
        const std::int64_t n = chunks.next();
        QVERIFY(n >= 1 && n <= total - done && n <= StepChunker::kMaxChunk);
        done += n;
        chunks.completed(n, 1e-9 * static_cast<double>(n));  // 1 ns per step: 40e6 steps per 40 ms chunk
        QVERIFY(++launches < 1000);
      }
      QCOMPARE(done, total);
    }
  }
  void chunker_sizes_chunks_to_the_target_time() {
    // First chunk: ~1e6 point-steps.
    StepChunker chunks(1'000'000'000, 1000, 0.04);
    QCOMPARE(chunks.next(), std::int64_t{1000});
    // A device doing 1000 steps in 1 ms may grow 8x at a time, not straight to the 40 ms target.
    chunks.completed(1000, 0.001);
    QCOMPARE(chunks.next(), std::int64_t{8000});
    chunks.completed(8000, 0.008);
    QVERIFY(std::abs(chunks.next() - 40000) <= 1);  // 40 ms at 1 step/us (rounding of the rate)
    // When the device slows down (another process), the next chunk shrinks to the target at the new rate.
    chunks.completed(chunks.next(), 0.4);
    QVERIFY(std::abs(chunks.next() - 4000) <= 1);
    // An untimeable chunk (0 s) only grows by the 8x limit.
    const std::int64_t before = chunks.next();
    chunks.completed(before, 0.0);
    QCOMPARE(chunks.next(), before * 8);
    // Huge W: one step per launch at least.
    QCOMPARE(StepChunker(10, std::int64_t{1} << 40).next(), std::int64_t{1});
  }
};

QTEST_APPLESS_MAIN(TestRotation)
#include "test_rotation.moc"
