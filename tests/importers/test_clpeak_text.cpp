// SPDX-License-Identifier: GPL-3.0-or-later
// clpeak text output: devices, sections and SI conversion, CRLF, skipped/failed tests, clpeak 2 spelling, errors.
#include <QTest>

#include "clpeak_text.h"

#include "../support/import_errors.h"

namespace {
const std::string kData = BENCHSCOPE_TEST_DATA_DIR "/importers/clpeak/";

bs::ImportBatch parse_file(const std::string& name) {
  const bs::CancelToken cancel;
  return bs::ClpeakTextImporter().parse(kData + name, {}, cancel);
}

const bs::Measurement* find(const bs::ResultSet& s, const std::string& name, const std::string& metric) {
  for (const auto& m : s.measurements)
    if (m.name == name && m.metric == metric) return &m;
  return nullptr;
}

bool near(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); }

bs::ImportError error_of(const std::string& text) {
  return bs::test::import_error_of([&] { return bs::parse_clpeak_text(text, "c.txt"); });
}
}  // namespace

class TestClpeakText : public QObject {
  Q_OBJECT
 private slots:
  void parses_two_platforms() {
    const auto batch = parse_file("gtx1080ti.txt");
    QCOMPARE(batch.result_sets.size(), std::size_t{2});
    const bs::ResultSet& gpu = batch.result_sets[0];
    QCOMPARE(gpu.platform, std::string("NVIDIA CUDA"));
    QCOMPARE(gpu.device, std::string("GeForce GTX 1080 Ti"));
    QCOMPARE(gpu.device_kind, bs::DeviceKind::Gpu);
    QCOMPARE(gpu.backend, std::string("OpenCL"));
    QCOMPARE(gpu.source_format, std::string("clpeak-text"));
    QCOMPARE(gpu.provenance.gpu_model, std::string("GeForce GTX 1080 Ti"));
    QVERIFY(gpu.provenance.note.find("Compute units: 28") != std::string::npos);
    int sp = 0;
    double best = 0;
    for (const auto& m : gpu.measurements) {
      QCOMPARE(m.values.size(), std::size_t{1});
      if (m.metric == "single-precision compute") {
        ++sp;
        QCOMPARE(m.unit, std::string("FLOP/s"));
        best = std::max(best, m.values[0]);
      }
    }
    QCOMPARE(sp, 5);
    QCOMPARE(best, 11461.23e9);
    QCOMPARE(find(gpu, "kernel launch latency", "kernel launch latency")->unit, std::string("s"));
    QVERIFY(near(find(gpu, "kernel launch latency", "kernel launch latency")->values[0], 5.32e-6));
    QVERIFY(near(find(gpu, "memcpy from mapped ptr", "transfer bandwidth")->values[0], 10.35e9));
    QCOMPARE(find(gpu, "float4", "global memory bandwidth")->unit, std::string("B/s"));
    QCOMPARE(find(gpu, "int16", "integer compute")->unit, std::string("1/s"));
    QVERIFY(near(find(gpu, "int16", "integer compute")->values[0], 3757.27e9));
    QVERIFY(near(find(gpu, "double", "double-precision compute")->values[0], 357.79e9));
    QVERIFY(!find(gpu, "half", "half-precision compute"));  // "No half precision support! Skipped"
    QCOMPARE(batch.result_sets[1].device_kind, bs::DeviceKind::Cpu);  // PoCL pthread device
    QCOMPARE(batch.result_sets[1].platform, std::string("Portable Computing Language"));
    QVERIFY(batch.warnings.empty());
  }

  void crlf_failed_tests_and_build_failures() {
    const auto batch = parse_file("nuc-iris650-crlf.txt");
    // The PoCL device's kernels did not build: left out with a warning.
    QCOMPARE(batch.result_sets.size(), std::size_t{1});
    const bs::ResultSet& gpu = batch.result_sets[0];
    QCOMPARE(gpu.platform, std::string("Intel(R) OpenCL HD Graphics"));
    QCOMPARE(gpu.device, std::string("Intel(R) Iris(R) Plus Graphics 650 [0x5927]"));
    QCOMPARE(gpu.device_kind, bs::DeviceKind::Gpu);
    QVERIFY(near(find(gpu, "half2", "half-precision compute")->values[0], 1634.17e9));
    QVERIFY(near(find(gpu, "double", "double-precision compute")->values[0], 203.47e9));
    QVERIFY(!find(gpu, "double2", "double-precision compute"));  // clEnqueueNDRangeKernel (-5)
    QVERIFY(!find(gpu, "int2", "double-precision compute"));       // the section ended at the failure
    QVERIFY(near(find(gpu, "int", "integer compute fast 24bit")->values[0], 269.02e9));
    QVERIFY(near(find(gpu, "kernel launch latency", "kernel launch latency")->values[0], 27.81e-6));
    QVERIFY(gpu.provenance.note.find("Driver version: 21.49.21786 (Linux x64)") != std::string::npos);
    for (const auto& m : gpu.measurements) QVERIFY2(m.name.find('\r') == std::string::npos, m.name.c_str());
    QCOMPARE(batch.warnings.size(), std::size_t{3});  // failed test, build log, device left out
    QVERIFY(batch.warnings[0].starts_with(kData + "nuc-iris650-crlf.txt:32: "));
    QVERIFY(batch.warnings[0].find("double2") != std::string::npos);
    QVERIFY(batch.warnings[2].find("cpu-haswell") != std::string::npos);
  }

  void clpeak2_backends_and_units() {
    const auto batch = parse_file("clpeak2-backends.txt");
    QCOMPARE(batch.result_sets.size(), std::size_t{2});
    const bs::ResultSet& gpu = batch.result_sets[0];
    QCOMPARE(gpu.platform, std::string("NVIDIA CUDA"));
    QCOMPARE(gpu.device, std::string("NVIDIA GeForce GTX 1080 Ti"));
    QCOMPARE(gpu.backend, std::string("OpenCL"));
    QVERIFY(near(find(gpu, "float4", "single-precision compute")->values[0], 11455.09e9));  // "(was ...)" ignored
    QVERIFY(!find(gpu, "half", "half-precision compute"));                                   // [unsupported]
    QCOMPARE(find(gpu, "float4", "global memory bandwidth")->unit, std::string("B/s"));       // (GB/s)
    QVERIFY(near(find(gpu, "launch", "kernel launch latency")->values[0], 5.41e-6));          // (µs)
    const bs::ResultSet& cpu = batch.result_sets[1];
    QCOMPARE(cpu.backend, std::string("CPU"));
    QCOMPARE(cpu.platform, std::string("CPU"));
    QCOMPARE(cpu.device_kind, bs::DeviceKind::Cpu);
    QCOMPARE(cpu.provenance.cpu_model, cpu.device);
    QVERIFY(near(find(cpu, "fma", "single-precision compute [AVX-512]")->values[0], 1104.37e9));
    QVERIFY(batch.warnings.empty());
  }

  void device_type_hint_marks_a_cpu() {
    const auto batch = bs::parse_clpeak_text(
        "Platform: Vendor X\n  Device: Accelerator 9000\n    Device type : CPU\n"
        "    Single-precision compute (GFLOPS)\n      float : 2.5\n",
        "hint.txt");
    QCOMPARE(batch.result_sets[0].device_kind, bs::DeviceKind::Cpu);
  }

  void crlf_and_bad_number() {
    const auto ok = bs::parse_clpeak_text(
        "Platform: P\r\n  Device: D\r\n    Single-precision compute (GFLOPS)\r\n      float : 1.5\r\n", "c.txt");
    QCOMPARE(ok.result_sets[0].measurements[0].values[0], 1.5e9);
    const bs::ImportError e = error_of(
        "Platform: P\n  Device: D\n    Single-precision compute (GFLOPS)\n      float : fast\n");
    QCOMPARE(e.category(), bs::ImportErrorCategory::Syntax);
    QCOMPARE(e.location().line, std::size_t{4});
    QCOMPARE(e.location().field, std::string("float"));
    QVERIFY(std::string(e.what()).starts_with("c.txt:4:"));
    QCOMPARE(error_of("Platform: P\n Device: D\n  Integer compute (GIOPS)\n   int : -3\n").category(),
             bs::ImportErrorCategory::InvalidValue);
  }

  void files_without_devices_are_errors() {
    const bs::ImportError platform_only = error_of("clpeak banner\n\nPlatform: NVIDIA CUDA\n\n");
    QCOMPARE(platform_only.category(), bs::ImportErrorCategory::MissingField);
    QCOMPARE(platform_only.location().line, std::size_t{3});
    QVERIFY(std::string(platform_only.what()).find("Device") != std::string::npos);
    const bs::ImportError nothing = error_of("nothing to see\n");
    QCOMPARE(nothing.category(), bs::ImportErrorCategory::MissingField);
    QCOMPARE(nothing.location().line, std::size_t{1});
    const bs::ImportError orphan = error_of("  Device: D\n");
    QCOMPARE(orphan.category(), bs::ImportErrorCategory::Syntax);
    QCOMPARE(orphan.location().line, std::size_t{1});
    const bs::ImportError all_skipped =
        error_of("Platform: P\n  Device: D\n    No half precision support! Skipped\n");
    QCOMPARE(all_skipped.category(), bs::ImportErrorCategory::MissingField);
    QCOMPARE(all_skipped.location().line, std::size_t{2});
  }

  void sniffs_clpeak_only() {
    const bs::ClpeakTextImporter imp;
    QVERIFY(imp.sniff("Platform: P\n  Device: D\n    Single-precision compute (GFLOPS)\n", "x.json") >= 90);
    QVERIFY(imp.sniff("Backend: OpenCL\n  Platform 0: P\n    Device 0: D\n", "x") > 0);
    QCOMPARE(imp.sniff("time_s,current_A\n0,1\n", "power.txt"), 0);
  }
};

QTEST_GUILESS_MAIN(TestClpeakText)
#include "test_clpeak_text.moc"
