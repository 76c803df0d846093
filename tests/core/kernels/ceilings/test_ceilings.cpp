// SPDX-License-Identifier: GPL-3.0-or-later
// The empirical-ceiling micro-kernels: they run exactly the steps they are counted for (checked against the closed
// form on a small case, which a step more or less would miss), return finite positive rates, and --isa ids map to
// targets. No timing is judged here: speed is a benchmark's business (bench kernels).
#include <QTest>
#include <cmath>
#include <vector>

#include <QTemporaryDir>
#include <fstream>

#include "kernels/ceilings/ceiling_cache.h"
#include "kernels/ceilings/ceilings.h"
#include "kernels/rotation/rotation.h"
#include "kernels/rotation/rotation_simd.h"
#include "util/host_clock.h"

using namespace bs::kernels;

class TestCeilings : public QObject {
  Q_OBJECT
 private slots:
  void rotation_mix_runs_exactly_the_counted_steps() {
    for (const SimdTarget& t : available_simd_targets())
      for (int chains : ceiling_mix_chain_options(t.isa)) {
        const int lanes = ceiling_lanes(t.isa);
        QCOMPARE(lanes, t.lanes);
        const int n = chains * lanes;
        std::vector<float> xs(static_cast<std::size_t>(n)), ys(xs.size());
        for (int i = 0; i < n; ++i)
          xs[i] = static_cast<float>(std::cos(0.1 * i)), ys[i] = static_cast<float>(std::sin(0.1 * i));
        const std::int64_t steps = 1000;
        QVERIFY(ceiling_rotation_mix(t.isa, chains, xs.data(), ys.data(), steps, rotation_cos(), rotation_sin()));
        // Every lane of every chain was rotated by 2 rad exactly `steps` times: (cos(0.1 i + 2 steps), sin(...)).
        // So the counted work, 6 flops x lanes x chains x steps, was done. Float error ~1.2e-7 per step.
        for (int i = 0; i < n; ++i) {
          const double a = 0.1 * i + 2.0 * steps;
          const QByteArray where =
              QString("%1, %2 chains, lane %3").arg(QString::fromStdString(t.name)).arg(chains).arg(i).toUtf8();
          QVERIFY2(std::abs(xs[i] - std::cos(a)) < 1e-3 && std::abs(ys[i] - std::sin(a)) < 1e-3, where.constData());
          // One step fewer would sit 2 rad away: the check can tell the step count.
          QVERIFY(std::abs(xs[i] - std::cos(a - 2.0)) + std::abs(ys[i] - std::sin(a - 2.0)) > 0.1);
        }
      }
  }
  void rotation_mix_refuses_chain_counts_it_has_no_kernel_for() {
    std::vector<float> xs(64 * 16), ys(xs.size());
    QVERIFY(!ceiling_rotation_mix(best_simd_target().isa, 7, xs.data(), ys.data(), 10, 1.0f, 0.0f));
  }
  void fma_runs_exactly_the_counted_steps() {
    for (const SimdTarget& t : available_simd_targets()) {
      const int chains = ceiling_fma_chains(t.isa);
      if (chains == 0) {
        QVERIFY(!t.fma || t.isa == Isa::Generic);  // only ISAs without FMA have no FMA ceiling
        std::vector<float> acc(64);
        QVERIFY(!ceiling_fma(t.isa, acc.data(), 10, 0.5f, 0.5f));
        continue;
      }
      const int n = chains * ceiling_lanes(t.isa);
      std::vector<float> acc(static_cast<std::size_t>(n));
      for (int i = 0; i < n; ++i) acc[i] = static_cast<float>(i);
      // acc_k = a acc_{k-1} + b with a = 0.5, b = 1: acc_n = 2 + (acc_0 - 2) / 2^n. After 3 steps from i: 2 + (i-2)/8,
      // exact in float; 2 or 4 steps would give (i-2)/4 or (i-2)/16.
      QVERIFY(ceiling_fma(t.isa, acc.data(), 3, 0.5f, 1.0f));
      for (int i = 0; i < n; ++i) QCOMPARE(acc[i], 2.0f + (static_cast<float>(i) - 2.0f) / 8.0f);
    }
  }
  // On ARM64 NEON has FMA, so fma_runs_exactly_the_counted_steps verified the FMA kernel's work there (not only its
  // refusal, as for SSE4.1 and the generic x86 code).
  void arm64_has_an_fma_ceiling() {
#if defined(__aarch64__)
    QVERIFY(ceiling_fma_chains(Isa::Generic) > 0);
    QCOMPARE(ceiling_lanes(Isa::Generic), 4);
#elif defined(__FMA__)
    QVERIFY(ceiling_fma_chains(Isa::Generic) > 0);  // built with -march=... that has FMA
#else
    QCOMPARE(ceiling_fma_chains(Isa::Generic), 0);  // x86's generic code has no FMA without -mfma
#endif
  }
  void meter_gives_finite_positive_rates_and_says_how() {
    const SimdTarget t = best_simd_target();
    CeilingMeter meter(t, 2, 0.005);  // short repetitions: this checks values, not speed
    bool offered = false;
    for (int k : ceiling_mix_chain_options(t.isa)) offered |= k == meter.mix_chains();
    QVERIFY(offered);
    const CeilingSample mix = meter.time_rotation_mix();
    QVERIFY(std::isfinite(mix.rate()) && mix.rate() > 0);
    QVERIFY(std::isfinite(mix.rate_per_cpu_s()) && mix.rate_per_cpu_s() > 0);
    QVERIFY(meter.mix_how().find("independent chains") != std::string::npos);
    bool winner_offered = false;
    for (int k : ceiling_mix_chain_options(t.isa)) winner_offered |= k == meter.last_best_chains();
    QVERIFY(winner_offered);
    if (meter.has_fma()) {
      const CeilingSample f = meter.time_fma();
      QVERIFY(std::isfinite(f.rate()) && f.rate() > 0);
    }
    const CeilingSample bw = time_bandwidth(4, bs::CancelToken{});
    QVERIFY(std::isfinite(bw.rate()) && bw.rate() > 0);
    QCOMPARE(bw.work, 12.0 * 4 * 1024 * 1024 / 4);
  }
  void measured_set_becomes_a_result_set() {
    CpuInfo cpu = detect_cpu(false);
    cpu.clock_hz = 2e9;
    use_simd_target(cpu, best_simd_target());
    const CeilingSet set = measure_ceilings(cpu, {2, true, 4}, bs::CancelToken{});
    QCOMPARE(set.rotation_mix.values.size(), std::size_t{2});
    QCOMPARE(set.bandwidth.values.size(), std::size_t{2});
    QCOMPARE(set.isa, isa_id(cpu.simd.isa));
    const bs::ResultSet rs = ceiling_result_set(set);
    QCOMPARE(rs.source_format, std::string(kCeilingSource));
    QCOMPARE(rs.measurements.front().name, "rotation-mix/" + set.isa);
    QCOMPARE(rs.measurements.front().unit, std::string("FLOP/s"));
    QVERIFY(!rs.provenance.date.empty());
    QVERIFY(rs.provenance.note.find("rotation mix") != std::string::npos);
  }
  void isa_ids_select_targets() {
    for (const SimdTarget& t : available_simd_targets()) QCOMPARE(simd_target_by_id(isa_id(t.isa)).name, t.name);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, simd_target_by_id("avx1024"));
    CpuInfo cpu = detect_cpu(false);
    cpu.clock_hz = 3e9;
    use_simd_target(cpu, simd_target_by_id("generic"));
    QCOMPARE(cpu.simd.lanes, 4);
    QCOMPARE(cpu.peak_flops, cpu.threads * 3e9 * cpu.flops_per_cycle);
  }
  void cache_keeps_one_entry_per_host_cpu_isa_and_threads() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("sub/ceilings.json").toStdString();
    CpuInfo cpu = detect_cpu(false);
    QVERIFY(!cached_ceilings(cpu, path));
    CeilingSet s;
    s.host = bs::host_name();
    s.cpu_model = cpu.model;
    s.isa = isa_id(cpu.simd.isa);
    s.threads = cpu.threads;
    s.date = "2026-11-23T22:00:00Z";
    s.rotation_mix = {"FLOP/s", {1e11, 1.1e11}, {1.2e11, 1.3e11}, "rotation mix: test"};
    store_ceilings(s, path);
    s.rotation_mix.values = {2e11};  // a newer measurement replaces the entry
    store_ceilings(s, path);
    CeilingSet other = s;
    other.threads = s.threads + 1;  // another thread count is another entry, never shown for this one
    store_ceilings(other, path);
    QCOMPARE(load_ceiling_cache(path).size(), std::size_t{2});
    const auto got = cached_ceilings(cpu, path);
    QVERIFY(got);
    QCOMPARE(got->rotation_mix.values, std::vector<double>{2e11});
    QCOMPARE(got->rotation_mix.how, std::string("rotation mix: test"));
    QCOMPARE(got->date, s.date);
    { std::ofstream(path) << "{\"format\": \"benchscope-ceilings-cache\", \"entries\": [{\"host\": 1}]}"; }
    try {
      load_ceiling_cache(path);
      QFAIL("a damaged entry must be reported");
    } catch (const std::runtime_error& e) {
      QVERIFY2(std::string(e.what()).find(path + ": entries[0]") == 0, e.what());
    }
    QVERIFY(!cached_ceilings(cpu, path));  // damaged: as good as none
  }
};

QTEST_GUILESS_MAIN(TestCeilings)
#include "test_ceilings.moc"
