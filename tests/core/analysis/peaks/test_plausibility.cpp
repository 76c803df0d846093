// SPDX-License-Identifier: GPL-3.0-or-later
// The device table (resources/devices/devices.json), name matching, and plausibility flags of FLOPS and power.
#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "../../../support/paper_sample.h"
#include "analysis/peaks/device_table.h"
#include "analysis/peaks/flops.h"
#include "analysis/peaks/plausibility.h"
#include "util/resources.h"

namespace {

const bs::DeviceTable& table() {
  const bs::BundledDeviceTable& b = bs::bundled_device_table();
  if (!b.error.empty()) qFatal("%s", b.error.c_str());
  return b.table;
}

std::string matched(std::string_view device, bs::DeviceKind kind, std::string_view platform = {}) {
  const bs::DeviceSpec* s = bs::match_device(table(), device, kind, platform);
  return s ? s->id : std::string("(none)");
}

bool has_code(const std::vector<bs::PlausibilityFlag>& flags, std::string_view code) {
  for (const auto& f : flags)
    if (f.code == code) return true;
  return false;
}

const bs::PeakRow& row_of(const std::vector<bs::PeakRow>& rows, std::string_view device, std::string_view backend,
                          int dims) {
  for (const auto& r : rows)
    if (r.device == device && r.backend == backend && r.dims == dims) return r;
  qFatal("no row for %s", std::string(device).c_str());
}

bs::PowerTrace trace_of(bs::PowerQuantity q, std::vector<double> values) {
  bs::PowerTrace t;
  t.platform = "P";
  t.label = "log";
  for (std::size_t i = 0; i < values.size(); ++i) t.time_s.push_back(0.1 * static_cast<double>(i));
  t.channels.push_back({q == bs::PowerQuantity::Power ? "power" : "current", q, std::move(values)});
  return t;
}

}  // namespace

class TestPlausibility : public QObject {
  Q_OBJECT
 private slots:
  void bundled_table_loads_with_sources() {
    const bs::DeviceTable& t = table();
    QVERIFY(t.devices.size() >= 45);
    for (const auto& d : t.devices) {
      QVERIFY2(!d.source_title.empty(), d.id.c_str());  // the parser refuses an entry without a source
      QVERIFY2(d.fp32_peak_flops > 1e9 && d.fp32_peak_flops < 1e15, d.id.c_str());
    }
  }
  // Every FP32 peak is units x FP32 FLOP per unit per cycle x clock (summed over a heterogeneous CPU's clusters)
  // within 2 %, or the entry says why not: a typo in a peak or a clock shows here, not as a wrong flag later.
  void every_peak_is_the_sum_of_its_terms() {
    int checked = 0;
    for (const bs::DeviceSpec& d : table().devices) {
      if (d.peak_terms.empty()) {
        QVERIFY2(!d.peak_exempt.empty(), qPrintable(QString::fromStdString(d.id) + ": no peak_terms and no reason"));
        continue;
      }
      const double ratio = d.peak_from_terms() / d.fp32_peak_flops;
      const QString what = QString("%1: terms give %2 FLOP/s, the table %3 (ratio %4)")
                               .arg(QString::fromStdString(d.id))
                               .arg(d.peak_from_terms(), 0, 'g', 6)
                               .arg(d.fp32_peak_flops, 0, 'g', 6)
                               .arg(ratio, 0, 'f', 4);
      if (std::fabs(ratio - 1) > 0.02) {
        QVERIFY2(!d.peak_exempt.empty(), qPrintable(what + " and no peak_exempt"));
      } else {
        QVERIFY2(d.peak_exempt.empty(), qPrintable(what + ": agrees, so peak_exempt is stale"));
        ++checked;
      }
      // The derivation a person reads names the same unit counts.
      for (const bs::PeakTerm& t : d.peak_terms)
        QVERIFY2(d.derivation.find(std::to_string(static_cast<long long>(t.units))) != std::string::npos,
                 qPrintable(QString::fromStdString(d.id + ": derivation does not name " + t.unit)));
    }
    QVERIFY(checked >= 45);
  }
  void rules_of_thumb_per_unit_hold() {
    // GPUs: 2 FLOP/cycle per CUDA core or stream processor (4 with RDNA 3 dual issue or CDNA 3 matrix), 16 per Intel
    // EU; CPUs: 8 or 16 (128-bit NEON FMA pipes) or 32 (two 256-bit FMA units) per core.
    for (const bs::DeviceSpec& d : table().devices)
      for (const bs::PeakTerm& t : d.peak_terms) {
        const double f = t.flop_per_unit_per_cycle;
        const bool ok = t.unit == "EUs"                 ? f == 16
                        : d.kind == bs::DeviceKind::Gpu ? (f == 2 || f == 4)
                                                        : (f == 8 || f == 16 || f == 32);
        QVERIFY2(ok, qPrintable(QString::fromStdString(d.id + " " + t.unit) + QString(": %1 FLOP/cycle").arg(f)));
        QVERIFY2(t.clock_ghz > 0.3 && t.clock_ghz < 6, qPrintable(QString::fromStdString(d.id)));
      }
  }
  void sources_and_unverified_fields() {
    for (const bs::DeviceSpec& d : table().devices) {
      const QString id = QString::fromStdString(d.id);
      // An entry with no page behind it says which of its values are unconfirmed.
      if (d.source_url.empty()) QVERIFY2(d.peak_unverified(), qPrintable(id));
      QVERIFY2(d.source_url.empty() || d.source_url.rfind("http", 0) == 0, qPrintable(id));
      for (const std::string& u : d.source_more_urls) QVERIFY2(u.rfind("http", 0) == 0, qPrintable(id));
    }
    // The paper's NUC and GTX 1080 Ti entries are confirmed; the TX2's memory bandwidth is not.
    for (const char* id : {"intel-iris-plus-650", "intel-i7-7567u", "nvidia-gtx-1080-ti"}) {
      const auto it = std::find_if(table().devices.begin(), table().devices.end(),
                                   [&](const bs::DeviceSpec& d) { return d.id == id; });
      QVERIFY(it != table().devices.end());
      QVERIFY2(it->unverified.empty() && !it->source_url.empty(), id);
    }
    const bs::DeviceSpec* tx2 = bs::match_device(table(), "Jetson TX2 GPU", bs::DeviceKind::Gpu);
    QVERIFY(tx2 && tx2->is_unverified("memory_bandwidth_bytes_per_s") && !tx2->peak_unverified());
  }
  void peak_terms_and_unverified_are_parsed_and_checked() {
    const auto entry = [](const std::string& extra) {
      return R"({"format":"benchscope-device-specs","version":1,"devices":[{"id":"x","name":"X","kind":"cpu",
        "fp32_peak_flops":128e9,"derivation":"d","source":{"title":"s","more":["https://b"]})" +
             extra + "}]}";
    };
    const bs::DeviceTable t = bs::parse_device_table(
        entry(R"(,"peak_terms":[{"units":4,"unit":"A57","flop_per_unit_per_cycle":8,"clock_ghz":2},
          {"units":2,"unit":"Denver 2","flop_per_unit_per_cycle":16,"clock_ghz":2}],"unverified":["clock_ghz"])"),
        "t.json");
    const bs::DeviceSpec& d = t.devices.front();
    QCOMPARE(d.peak_terms.size(), std::size_t{2});
    QCOMPARE(d.peak_from_terms(), 128e9);
    QCOMPARE(d.source_more_urls, (std::vector<std::string>{"https://b"}));
    QVERIFY(d.peak_unverified() && d.is_unverified("clock_ghz") && !d.is_unverified("tdp_w"));
    // Without the new fields an entry still loads, with nothing unverified.
    QVERIFY(bs::parse_device_table(entry(""), "t.json").devices.front().unverified.empty());
    const auto refused = [&](const std::string& extra, const char* where) {
      try {
        bs::parse_device_table(entry(extra), "t.json");
      } catch (const std::runtime_error& e) {
        return std::string(e.what()).find(where) != std::string::npos;
      }
      return false;
    };
    QVERIFY(refused(R"(,"unverified":["clock"])", "devices[0].unverified"));  // a typo is not silently ignored
    QVERIFY(refused(R"(,"peak_terms":[{"units":4,"unit":"c","flop_per_unit_per_cycle":8}])", "clock_ghz"));
    QVERIFY(refused(R"(,"peak_terms":[{"units":-4,"unit":"c","flop_per_unit_per_cycle":8,"clock_ghz":2}])",
                    "peak_terms[0].units"));
    QVERIFY(refused(R"(,"peak_terms":{})", "peak_terms"));
  }
  void tokens_split_letters_from_digits_and_drop_vendor_words() {
    QCOMPARE(bs::device_name_tokens("GTX1080Ti"), (std::vector<std::string>{"gtx", "1080", "ti"}));
    QCOMPARE(bs::device_name_tokens("Intel(R) Iris(TM) Plus Graphics 650"),
             (std::vector<std::string>{"iris", "plus", "650"}));
    QCOMPARE(bs::device_name_tokens("Intel\xC2\xAE Core\xE2\x84\xA2 i7-7567U"),
             (std::vector<std::string>{"i", "7", "7567", "u"}));
  }
  void matches_names_aliases_and_platforms() {
    using K = bs::DeviceKind;
    QCOMPARE(matched("NUC GPU (Iris Plus 650)", K::Gpu), std::string("intel-iris-plus-650"));
    QCOMPARE(matched("Intel(R) Iris(TM) Plus Graphics 650", K::Gpu), std::string("intel-iris-plus-650"));
    QCOMPARE(matched("GTX1080Ti", K::Gpu), std::string("nvidia-gtx-1080-ti"));
    QCOMPARE(matched("NVIDIA GeForce GTX 1080 Ti", K::Other), std::string("nvidia-gtx-1080-ti"));
    QCOMPARE(matched("NVIDIA GeForce RTX 3060 Ti", K::Gpu), std::string("nvidia-rtx-3060-ti"));  // longest wins
    QCOMPARE(matched("NVIDIA GeForce RTX 3060", K::Gpu), std::string("nvidia-rtx-3060"));
    QCOMPARE(matched("NVIDIA H100 PCIe", K::Gpu), std::string("nvidia-h100-pcie"));
    QCOMPARE(matched("NVIDIA H100 80GB HBM3", K::Gpu), std::string("nvidia-h100-sxm"));
    QCOMPARE(matched("Jetson Orin Nano", K::Gpu), std::string("nvidia-jetson-orin-nano-gpu"));
    QCOMPARE(matched("Orin", K::Gpu), std::string("nvidia-jetson-agx-orin-gpu"));  // CUDA's name of every Orin
    QCOMPARE(matched("Intel(R) Core(TM) i7-7567U CPU @ 3.50GHz", K::Cpu), std::string("intel-i7-7567u"));
    QCOMPARE(matched("NUC CPU (i7-7567U)", K::Cpu), std::string("intel-i7-7567u"));
    // The paper's Jetson devices: the device name, else the platform name, of the right kind.
    QCOMPARE(matched("Jetson GPU (Pascal, 256 cores)", K::Gpu, "Jetson TX2"), std::string("nvidia-jetson-tx2-gpu"));
    QCOMPARE(matched("Jetson CPU (ARM A57 + Denver2)", K::Cpu, "Jetson TX2"), std::string("nvidia-jetson-tx2-cpu"));
    QCOMPARE(matched("CPU", K::Cpu, "Raspberry Pi 5"), std::string("raspberry-pi-5-cpu"));
    // The kind filters; a tie between different entries is no match; unknown devices match nothing.
    QCOMPARE(matched("i7-7567U", K::Gpu), std::string("(none)"));
    QCOMPARE(matched("Jetson TX2", K::Other), std::string("(none)"));
    QCOMPARE(matched("Mali-G610", K::Gpu), std::string("(none)"));
    QCOMPARE(bs::platform_tdp_w(table(), "Jetson TX2").value_or(0), 15.0);
  }
  void malformed_tables_are_refused_with_the_field() {
    const char* no_source = R"({"format":"benchscope-device-specs","version":1,"devices":[{"id":"x","name":"X",
      "kind":"gpu","fp32_peak_flops":1e12,"derivation":"d"}]})";
    try {
      bs::parse_device_table(no_source, "t.json");
      QFAIL("accepted an entry without a source");
    } catch (const std::runtime_error& e) {
      QVERIFY2(std::string(e.what()).find("devices[0].source") != std::string::npos, e.what());
    }
    const char* bad_kind = R"({"format":"benchscope-device-specs","version":1,"devices":[{"id":"x","name":"X",
      "kind":"npu","fp32_peak_flops":1e12,"derivation":"d","source":{"title":"s"}}]})";
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, bs::parse_device_table(bad_kind, "t.json"));
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, bs::parse_device_table("{}", "t.json"));
  }

  // The paper's NUC GPU figure, 5.25 TFLOPS (OpenCL, D = 4), against the Iris Plus 650's spec peak:
  // 48 EUs x 16 FP32 FLOP/cycle x 1.15 GHz = 883.2 GFLOPS; 5.25e12 / 883.2e9 = 5.94, far above 1.3.
  void paper_nuc_gpu_is_flagged_and_gtx1080ti_is_not() {
    const auto sample = bs::test::load_paper_sample();
    const auto rows = bs::peak_table(sample.runs);
    const bs::PeakRow& nuc = row_of(rows, "NUC GPU (Iris Plus 650)", "OpenCL", 4);
    QVERIFY(std::fabs(nuc.peak.flops - 5.25e12) < 0.01e12);
    QVERIFY(nuc.spec);
    QCOMPARE(nuc.spec->id, std::string("intel-iris-plus-650"));
    QCOMPARE(nuc.spec->fp32_peak_flops, 883.2e9);
    QVERIFY(std::fabs(*nuc.fraction_of_spec - 5.944) < 0.01);
    QVERIFY(has_code(nuc.flags, bs::flag_code::kAboveSpecPeak));
    const std::string& why = nuc.flags.front().reason;
    QVERIFY2(why.find("5.9x") != std::string::npos, why.c_str());
    QVERIFY2(why.find("compiler") != std::string::npos, why.c_str());      // FLOPs not executed
    QVERIFY2(why.find("asynchronous") != std::string::npos, why.c_str());  // timing wrong
    // GTX 1080 Ti, 9.14 TFLOPS (OpenCL, D = 4): 3584 x 2 x 1.582 GHz = 11.34 TFLOPS; 9.14 / 11.34 = 0.806.
    const bs::PeakRow& gtx = row_of(rows, "GTX1080Ti", "OpenCL", 4);
    QVERIFY(std::fabs(gtx.peak.flops - 9.14e12) < 0.01e12);
    QVERIFY(std::fabs(*gtx.fraction_of_spec - 0.806) < 0.001);
    QVERIFY(gtx.flags.empty());
    // The Jetson GPU, 0.49 TFLOPS: 256 x 2 x 1.30 GHz = 665.6 GFLOPS; 0.736 of it, plausible.
    const bs::PeakRow& jetson = row_of(rows, "Jetson GPU (Pascal, 256 cores)", "CUDA", 4);
    QVERIFY(std::fabs(*jetson.fraction_of_spec - 0.736) < 0.001);
    QVERIFY(jetson.flags.empty());
    // The paper's HD 630 figure (2.40 TFLOPS) is 5.4x its 441.6 GFLOPS peak: the same suspicion.
    QVERIFY(has_code(row_of(rows, "Intel HD Graphics 630", "OpenCL", 4).flags, bs::flag_code::kAboveSpecPeak));
    // The CPUs are far below their peaks (the paper's one-chain-per-task kernel): 49.68 / 768 GFLOPS = 6.5 %.
    QVERIFY(row_of(rows, "i7-7800X", "CPU SIMD (AVX/SSE)", 4).flags.empty());
  }
  void flops_above_theoretical_peak_is_flagged() {
    const bs::DeviceSpec* gtx = bs::match_device(table(), "GTX1080Ti", bs::DeviceKind::Gpu);
    QVERIFY(bs::check_flops(14.0e12, gtx).empty());  // 1.23x: within boost clocks above the rated 1582 MHz
    QVERIFY(has_code(bs::check_flops(15.0e12, gtx), bs::flag_code::kAboveSpecPeak));  // 1.32x
    QVERIFY(bs::check_flops(1.05e12, nullptr, 1e12).empty());
    const auto flags = bs::check_flops(1.2e12, nullptr, 1e12);
    QCOMPARE(flags.size(), std::size_t{1});
    QCOMPARE(flags.front().code, std::string(bs::flag_code::kAboveTheoreticalPeak));
  }

  void power_flags() {
    using Q = bs::PowerQuantity;
    // Sensor offset around zero (-5 mA; median |I| 1.2 A, allowance 12 mA) is noise, not a flag.
    QVERIFY(bs::check_power_trace(trace_of(Q::Current, {0.5, -0.005, 2.0, 1.9})).empty());
    const auto negative = bs::check_power_trace(trace_of(Q::Current, {-0.5, -0.6, -2.0}));
    QCOMPARE(negative.size(), std::size_t{1});
    QCOMPARE(negative.front().code, std::string(bs::flag_code::kNegativeValue));
    QVERIFY2(negative.front().reason.find("3 samples, first at 0.000 s") != std::string::npos,
             negative.front().reason.c_str());
    // A spike does not hide a negative sample: the noise allowance is 1 % of the median |value| (9.2 W: 0.092 W).
    const auto spiked = bs::check_power_trace(trace_of(Q::Power, {9.1, 9.3, -9.2, 9200, 9.4, 9.0, 9.2, 9.1, 9.3, 9.2,
                                                                  9.1, 9.3, 9.2,  9.1,  9.3, 9.2, 9.1, 9.3, 9.2, 9.1}));
    QVERIFY(has_code(spiked, bs::flag_code::kNegativeValue));
    QVERIFY(has_code(spiked, bs::flag_code::kMagnitudeJump));  // 9.4 W -> 9.2 kW
    QVERIFY(has_code(bs::check_power_trace(trace_of(Q::Power, {40, 41, 12e3, 12e3, 12e3})),
                     bs::flag_code::kImplausibleMagnitude));
    // 2.5 A then 2500 A (a sample in mA): three orders of magnitude between neighbours; idle -> load is not.
    const auto jump = bs::check_power_trace(trace_of(Q::Current, {2.5, 2.4, 2500, 2.6, 2.5}));
    QVERIFY(has_code(jump, bs::flag_code::kMagnitudeJump));
    QVERIFY(has_code(jump, bs::flag_code::kImplausibleMagnitude));  // 2.5 kA: above 1 kA too
    // 0.5 W then 60 W (120x) stays below every absolute limit: the jump alone is flagged.
    const auto jump_only = bs::check_power_trace(trace_of(Q::Power, {0.5, 0.5, 60, 0.5}));
    QCOMPARE(jump_only.size(), std::size_t{1});
    QCOMPARE(jump_only.front().code, std::string(bs::flag_code::kMagnitudeJump));
    QVERIFY2(jump_only.front().reason.find("120x (500.00 mW to 60.00 W)") != std::string::npos,
             jump_only.front().reason.c_str());
    QVERIFY(bs::check_power_trace(trace_of(Q::Current, {0.0001, 0.3, 2.5, 2.4, 0.3})).empty());
    QVERIFY(bs::check_power_trace(trace_of(Q::Current, {1.0, NAN, 1.1})).empty());
    // 200 W on a platform whose TDP is 15 W (13x): above 10x the TDP.
    QVERIFY(
        has_code(bs::check_power_trace(trace_of(Q::Power, {9, 200, 10}), 15.0), bs::flag_code::kAbovePlatformPower));
    QVERIFY(bs::check_power_trace(trace_of(Q::Power, {9, 20, 10}), 15.0).empty());
    // The paper's logs (NUC 2.53 A, Jetson 0.59 A at 16 V) are plausible.
    for (const auto& t : bs::test::load_paper_sample().traces) QVERIFY(bs::check_power_trace_bundled(t).empty());
  }
};

QTEST_APPLESS_MAIN(TestPlausibility)
#include "test_plausibility.moc"
