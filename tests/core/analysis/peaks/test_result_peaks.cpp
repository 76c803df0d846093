// SPDX-License-Identifier: GPL-3.0-or-later
// A device's peak from result sets is taken within one precision and kind: a GPU's half2 rate never stands for its
// single-precision peak. Classification of clpeak 1.x / 2.x / Google Benchmark metrics, and the roofline's memory
// ceiling from global memory bandwidth only. Numbers checked by hand against real clpeak outputs: third-party files
// in the shared folder's tests/data/importers/clpeak/ (SOURCES there), whose functions skip without it.
#include <QTest>

#include "analysis/peaks/result_peaks.h"
#include "analysis/roofline/roofline.h"
#include "model/measure_class.h"
#include "runs/clpeak_text.h"

#include "../../../support/near.h"
#include "../../../support/public_data.h"
#include "../../../support/run_on.h"

using bs::test::near;

namespace {

constexpr const char* kRealFolder = "tests/data/importers/clpeak";

std::vector<bs::ResultSet> sets_of(const std::string& fixture) {
  return bs::FormatImporter(bs::kClpeakTextFileFormat)
      .parse(bs::test::public_data(std::string(kRealFolder) + "/" + fixture), {}, {}, bs::CancelToken{})
      .result_sets;
}

bs::MeasureClass cls(const char* metric, const char* name, const char* unit) {
  return bs::classify_measurement(metric, name, unit);
}

}  // namespace

class TestResultPeaks : public QObject {
  Q_OBJECT
 private slots:
  void classifies_clpeak_and_benchmark_metrics() {
    using bs::MeasureKind;
    using bs::Precision;
    const struct {
      const char *metric, *name, *unit;
      MeasureKind kind;
      Precision precision;
    } cases[] = {
        {"single-precision compute", "float4", "FLOP/s", MeasureKind::VectorCompute, Precision::FP32},
        {"single-precision compute [avx-512]", "fma", "FLOP/s", MeasureKind::VectorCompute, Precision::FP32},
        {"single-precision compute (neon)", "fma", "FLOP/s", MeasureKind::VectorCompute, Precision::FP32},
        {"half-precision compute", "half2", "FLOP/s", MeasureKind::VectorCompute, Precision::FP16},
        {"half-precision compute fp16xfp16+fp16", "half4", "FLOP/s", MeasureKind::VectorCompute, Precision::FP16},
        {"mixed-precision compute fp16xfp16+fp32", "mp", "FLOP/s", MeasureKind::VectorCompute,
         Precision::MixedFP16FP32},
        {"bf16 compute bf16xbf16+fp32", "bf16", "FLOP/s", MeasureKind::VectorCompute, Precision::BF16},
        {"double-precision compute", "double8", "FLOP/s", MeasureKind::VectorCompute, Precision::FP64},
        {"integer compute", "int4", "1/s", MeasureKind::VectorCompute, Precision::INT32},
        {"integer compute int32", "int", "1/s", MeasureKind::VectorCompute, Precision::INT32},
        {"integer compute fast 24bit", "int", "1/s", MeasureKind::VectorCompute, Precision::INT24},
        {"integer char (8bit) compute", "char4", "1/s", MeasureKind::VectorCompute, Precision::INT8},
        {"int8 dot-product compute", "dp4a", "1/s", MeasureKind::MatrixCompute, Precision::INT8},
        {"cooperative-matrix fp32xfp32+fp32 16x16x16", "coopmat_fp32", "FLOP/s", MeasureKind::MatrixCompute,
         Precision::FP32},
        {"cooperative-matrix fp16xfp16+fp32 16x16x16", "coopmat_fp16", "FLOP/s", MeasureKind::MatrixCompute,
         Precision::FP16},
        {"cooperative-matrix fp8(e4m3)xfp8(e4m3)+fp32 16x16x16", "coopmat_fp8_e4m3", "FLOP/s",
         MeasureKind::MatrixCompute, Precision::FP8},
        {"divide and square-root throughput [sse2]", "fdiv fp64 MT", "FLOP/s", MeasureKind::OtherCompute,
         Precision::FP64},
        {"global memory bandwidth", "float4", "B/s", MeasureKind::MemoryBandwidth, Precision::Unknown},
        {"bandwidth", "stream-triad/64MiB", "B/s", MeasureKind::MemoryBandwidth, Precision::Unknown},
        {"local memory bandwidth", "float4", "B/s", MeasureKind::OnChipBandwidth, Precision::Unknown},
        {"image memory bandwidth", "float4", "B/s", MeasureKind::OnChipBandwidth, Precision::Unknown},
        {"transfer bandwidth", "enqueueWriteBuffer", "B/s", MeasureKind::TransferBandwidth, Precision::Unknown},
        {"kernel launch latency", "kernel launch latency", "s", MeasureKind::Latency, Precision::Unknown},
        {"FLOPS", "BM_Rotate/4096", "FLOP/s", MeasureKind::VectorCompute, Precision::Unknown},
        {"items_per_second", "BM_Sprint", "1/s", MeasureKind::Other, Precision::Unknown},
    };
    for (const auto& c : cases) {
      const bs::MeasureClass got = cls(c.metric, c.name, c.unit);
      QVERIFY2(got.kind == c.kind, c.metric);
      QVERIFY2(got.precision == c.precision, c.metric);
    }
    QCOMPARE(bs::precision_from_string("single"), std::optional<bs::Precision>(bs::Precision::FP32));
    QCOMPARE(bs::precision_from_string("int24"), std::optional<bs::Precision>(bs::Precision::INT24));
    QVERIFY(!bs::precision_from_string("quad"));
  }

  void single_precision_peak_is_not_the_half_rate() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kRealFolder);
    // UHD 620: half 738.24 GFLOPS > single 436.49 GFLOPS. The default (FP32 vector compute) peak is 436.49.
    const auto sets = sets_of("uhd620-neo.log");
    const auto fp32 = bs::result_peaks(sets);
    QCOMPARE(fp32.size(), std::size_t{1});
    QVERIFY(near(fp32[0].summary.mean, 436.49e9));
    QCOMPARE(fp32[0].measurement->name, std::string("float"));
    QCOMPARE(fp32[0].cls.precision, bs::Precision::FP32);
    const auto fp16 = bs::result_peaks(sets, {bs::Precision::FP16});
    QVERIFY(near(fp16[0].summary.mean, 738.24e9));
    // Left out of the FP32 table: 5 half, 5 double, 5 integer results.
    QCOMPARE(bs::compute_measurements_left_out(sets, {}), std::size_t{15});
  }

  void every_precision_one_row_each() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kRealFolder);
    // RX 9070 XT (clpeak 2.0 Vulkan): vector FP32 43973.95 G, FP16 54536.66 G, FP64 863.23 G, mixed 51072.47 G,
    // BF16 45988.92 G, INT32 5306.11 G; matrix FP16 179.73 T, BF16 179.64 T, FP8 max(386.00, 383.99) = 386.00 T.
    const auto sets = sets_of("vulkan-rx9070xt-clpeak2.txt");
    QVERIFY(near(bs::result_peaks(sets)[0].summary.mean, 43973.95e9));
    const auto all = bs::result_peaks(sets, {std::nullopt});
    QCOMPARE(all.size(), std::size_t{9});
    int fp32_rows = 0;
    for (const auto& p : all) {
      fp32_rows += p.cls.precision == bs::Precision::FP32;
      if (p.cls.kind == bs::MeasureKind::MatrixCompute && p.cls.precision == bs::Precision::FP8) {
        QVERIFY(near(p.summary.mean, 386.00e12));
        QCOMPARE(p.measurement->name, std::string("coopmat_fp8_e4m3"));
      }
    }
    QCOMPARE(fp32_rows, 1);
  }

  void divide_throughput_is_not_a_peak() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kRealFolder);
    // clpeak 2.1 CPU divide/sqrt rows are FP32/FP64 but not FMA peaks: no FP32 vector peak for this device.
    const auto sets = sets_of("cpu-divsqrt-units-per-line.txt");
    QVERIFY(bs::result_peaks(sets).empty());
    const auto other = bs::result_peaks(sets, {bs::Precision::FP32, bs::MeasureKind::OtherCompute});
    QCOMPARE(other.size(), std::size_t{1});
    QVERIFY(near(other[0].summary.mean, 92.8e9));  // fdiv fp32 MT [AVX2], the highest FP32 row
  }

  void roofline_ceiling_is_global_memory_bandwidth() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kRealFolder);
    // UHD 620: transfer "enqueueMapBuffer(for read) : 681739.50" GB/s must not become the memory ceiling; global
    // memory bandwidth peaks at float4 29.73 GB/s.
    const auto sets = sets_of("uhd620-neo.log");
    auto run = bs::test::run_on<bs::FlopsRun>(sets[0].platform, sets[0].device, bs::DeviceKind::Gpu, "OpenCL");
    run.samples = {{1024, {0.001}}};
    const auto ceilings = bs::roofline_ceilings(std::span<const bs::FlopsRun>(&run, 1), sets);
    QCOMPARE(ceilings.size(), std::size_t{1});
    QVERIFY(ceilings[0].bandwidth_bps);
    QVERIFY(near(*ceilings[0].bandwidth_bps, 29.73e9));
  }
};

QTEST_GUILESS_MAIN(TestResultPeaks)
#include "test_result_peaks.moc"
