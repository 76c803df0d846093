// SPDX-License-Identifier: GPL-3.0-or-later
// clpeak text output: devices, sections and SI conversion, CRLF, skipped/failed tests, clpeak 2 spelling, errors;
// and real outputs from the clpeak repository's result logs and issue threads, whose single-precision peaks are
// checked by hand in the comments: third-party files in the shared folder's tests/data/importers/clpeak/ (SOURCES
// there), whose functions skip without it.
#include <QTest>

#include <fstream>
#include <iterator>
#include <stdexcept>

#include "runs/clpeak_text.h"

#include "../../support/file_text.h"
#include "../../support/import_errors.h"
#include "../../support/importer_parse.h"
#include "../../support/near.h"
#include "../../support/public_data.h"
#include "../../support/result_set_lookup.h"

using bs::test::file_text;
using bs::test::find_measurement;
using bs::test::near;
using bs::test::parse_with;

namespace {
const std::string kData = BENCHSCOPE_TEST_DATA_DIR "/importers/clpeak/";  // the project's own fixtures
constexpr const char* kRealFolder = "tests/data/importers/clpeak";        // real outputs (third-party)
const std::string kReal = bs::test::public_data("tests/data/importers/clpeak/");

bs::ImportBatch parse_file(const std::string& name) { return parse_with(bs::kClpeakTextFileFormat, kData + name); }

bs::ImportBatch parse_real(const std::string& name) { return parse_with(bs::kClpeakTextFileFormat, kReal + name); }

std::string read_real(const std::string& name) { return file_text(kReal + name); }

const auto error_of = bs::test::import_errors_of(bs::kClpeakTextFileFormat, "c.txt");
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
    QCOMPARE(find_measurement(gpu, "kernel launch latency", "kernel launch latency")->unit, std::string("s"));
    QVERIFY(near(find_measurement(gpu, "kernel launch latency", "kernel launch latency")->values[0], 5.32e-6));
    QVERIFY(near(find_measurement(gpu, "memcpy from mapped ptr", "transfer bandwidth")->values[0], 10.35e9));
    QCOMPARE(find_measurement(gpu, "float4", "global memory bandwidth")->unit, std::string("B/s"));
    QCOMPARE(find_measurement(gpu, "int16", "integer compute")->unit, std::string("1/s"));
    QVERIFY(near(find_measurement(gpu, "int16", "integer compute")->values[0], 3757.27e9));
    QVERIFY(near(find_measurement(gpu, "double", "double-precision compute")->values[0], 357.79e9));
    QVERIFY(!find_measurement(gpu, "half", "half-precision compute"));  // "No half precision support! Skipped"
    QCOMPARE(batch.result_sets[1].device_kind, bs::DeviceKind::Cpu);    // PoCL pthread device
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
    QVERIFY(near(find_measurement(gpu, "half2", "half-precision compute")->values[0], 1634.17e9));
    QVERIFY(near(find_measurement(gpu, "double", "double-precision compute")->values[0], 203.47e9));
    QVERIFY(!find_measurement(gpu, "double2", "double-precision compute"));  // clEnqueueNDRangeKernel (-5)
    QVERIFY(!find_measurement(gpu, "int2", "double-precision compute"));     // the section ended at the failure
    QVERIFY(near(find_measurement(gpu, "int", "integer compute fast 24bit")->values[0], 269.02e9));
    QVERIFY(near(find_measurement(gpu, "kernel launch latency", "kernel launch latency")->values[0], 27.81e-6));
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
    QVERIFY(near(find_measurement(gpu, "float4", "single-precision compute")->values[0],
                 11455.09e9));                                          // "(was ...)" ignored
    QVERIFY(!find_measurement(gpu, "half", "half-precision compute"));  // [unsupported]
    QCOMPARE(find_measurement(gpu, "float4", "global memory bandwidth")->unit, std::string("B/s"));  // (GB/s)
    QVERIFY(near(find_measurement(gpu, "launch", "kernel launch latency")->values[0], 5.41e-6));     // (µs)
    const bs::ResultSet& cpu = batch.result_sets[1];
    QCOMPARE(cpu.backend, std::string("CPU"));
    QCOMPARE(cpu.platform, std::string("CPU"));
    QCOMPARE(cpu.device_kind, bs::DeviceKind::Cpu);
    QCOMPARE(cpu.provenance.cpu_model, cpu.device);
    QVERIFY(near(find_measurement(cpu, "fma", "single-precision compute [AVX-512]")->values[0], 1104.37e9));
    QVERIFY(batch.warnings.empty());
  }

  void device_type_hint_marks_a_cpu() {
    const auto batch = bs::kClpeakTextFileFormat.parse_text(
        "Platform: Vendor X\n  Device: Accelerator 9000\n    Device type : CPU\n"
        "    Single-precision compute (GFLOPS)\n      float : 2.5\n",
        "hint.txt");
    QCOMPARE(batch.result_sets[0].device_kind, bs::DeviceKind::Cpu);
    // Device names from clpeak issue 155: an iGPU named after its CPU under Vulkan and rusticl is a GPU; PoCL's
    // "pthread-" device is the CPU even when the CPU's name mentions its graphics.
    const auto kind_of = [](const std::string& device_line) {
      return bs::kClpeakTextFileFormat
          .parse_text(device_line + "\n  Single-precision compute (GFLOPS)\n    float : 1.0\n", "k.txt")
          .result_sets[0]
          .device_kind;
    };
    QCOMPARE(kind_of("Vulkan Device: AMD Ryzen 9 7900 12-Core Processor (RADV RAPHAEL_MENDOCINO)"),
             bs::DeviceKind::Gpu);
    QCOMPARE(kind_of("  Device: AMD Ryzen 9 7900 12-Core Processor (radeonsi, raphael_mendocino, ACO, DRM 3.64)"),
             bs::DeviceKind::Gpu);
    QCOMPARE(kind_of("  Device: pthread-AMD Ryzen 7 5800H with Radeon Graphics"), bs::DeviceKind::Cpu);
    QCOMPARE(kind_of("Vulkan Device: llvmpipe (LLVM 15.0.6, 256 bits)"), bs::DeviceKind::Cpu);
  }

  void crlf_and_bad_number() {
    const auto ok = bs::kClpeakTextFileFormat.parse_text(
        "Platform: P\r\n  Device: D\r\n    Single-precision compute (GFLOPS)\r\n      float : 1.5\r\n", "c.txt");
    QCOMPARE(ok.result_sets[0].measurements[0].values[0], 1.5e9);
    const bs::ImportError e =
        error_of("Platform: P\n  Device: D\n    Single-precision compute (GFLOPS)\n      float : fast\n");
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
    // A paste that starts at "Device:" is read; with nothing measured it is still an error.
    const bs::ImportError orphan = error_of("  Device: D\n");
    QCOMPARE(orphan.category(), bs::ImportErrorCategory::MissingField);
    QCOMPARE(orphan.location().line, std::size_t{1});
    const bs::ImportError all_skipped = error_of("Platform: P\n  Device: D\n    No half precision support! Skipped\n");
    QCOMPARE(all_skipped.category(), bs::ImportErrorCategory::MissingField);
    QCOMPARE(all_skipped.location().line, std::size_t{2});
  }

  void sniffs_clpeak_only() {
    const bs::FormatImporter imp(bs::kClpeakTextFileFormat);
    QVERIFY(imp.sniff("Platform: P\n  Device: D\n    Single-precision compute (GFLOPS)\n", "x.json") >= 90);
    QVERIFY(imp.sniff("Backend: OpenCL\n  Platform 0: P\n    Device 0: D\n", "x") > 0);
    QCOMPARE(imp.sniff("time_s,current_A\n0,1\n", "power.txt"), 0);
  }

  // --- Real outputs ---------------------------------------------------------------------------------------------

  void every_precision_is_its_own_metric() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kRealFolder);
    // Intel UHD 620 (NEO): half precision runs faster than single. Single-precision compute (GFLOPS): float 436.49,
    // float2 436.33, float4 435.70, float8 434.78, float16 428.94 -> single-precision peak 436.49 GFLOPS (float);
    // Half-precision compute: half 738.24 is the highest -> 738.24 GFLOPS, a different metric.
    const auto batch = parse_real("uhd620-neo.log");
    QCOMPARE(batch.result_sets.size(), std::size_t{1});
    const bs::ResultSet& gpu = batch.result_sets[0];
    QCOMPARE(gpu.device_kind, bs::DeviceKind::Gpu);
    QVERIFY(near(find_measurement(gpu, "float", "single-precision compute")->values[0], 436.49e9));
    QVERIFY(near(find_measurement(gpu, "half", "half-precision compute")->values[0], 738.24e9));
    QVERIFY(near(find_measurement(gpu, "double", "double-precision compute")->values[0], 109.50e9));
    QVERIFY(near(find_measurement(gpu, "int8", "integer compute")->values[0], 145.92e9));
    QCOMPARE(find_measurement(gpu, "float4", "global memory bandwidth")->unit, std::string("B/s"));
    QVERIFY(near(find_measurement(gpu, "enqueueMapBuffer(for read)", "transfer bandwidth")->values[0], 681739.50e9));
    QVERIFY(near(find_measurement(gpu, "kernel launch latency", "kernel launch latency")->values[0], 34.59e-6));
    QCOMPARE(gpu.measurements.size(), std::size_t{5 * 5 + 6 + 1});  // 5 sections x 5 widths, 6 transfers, latency
    QVERIFY(batch.warnings.empty());
  }

  void inf_in_transfer_bandwidth_keeps_the_rest() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kRealFolder);
    // HD 4600 on Windows (CRLF): "enqueueMapBuffer(for read) : inf" (line 27) and "enqueueUnmap(after write) : inf"
    // (line 29). Single precision 211.73 / 345.66 / 343.99 / 375.94 / 373.48 -> peak 375.94 GFLOPS (float8).
    const auto batch = parse_real("hd4600-crlf-inf.log");
    QCOMPARE(batch.result_sets.size(), std::size_t{1});
    const bs::ResultSet& gpu = batch.result_sets[0];
    QCOMPARE(gpu.platform, std::string("Intel(R) OpenCL"));
    QVERIFY(near(find_measurement(gpu, "float8", "single-precision compute")->values[0], 375.94e9));
    QVERIFY(!find_measurement(gpu, "enqueueMapBuffer(for read)", "transfer bandwidth"));
    QVERIFY(near(find_measurement(gpu, "memcpy from mapped ptr", "transfer bandwidth")->values[0], 2.87e9));
    QVERIFY(near(find_measurement(gpu, "kernel launch latency", "kernel launch latency")->values[0], 166.24e-6));
    QCOMPARE(batch.warnings.size(), std::size_t{2});
    QVERIFY2(batch.warnings[0].starts_with(kReal + "hd4600-crlf-inf.log:27: enqueueMapBuffer(for read): 'inf'"),
             batch.warnings[0].c_str());
    QVERIFY(batch.warnings[1].starts_with(kReal + "hd4600-crlf-inf.log:29: "));
    for (const auto& m : gpu.measurements) QVERIFY(m.name.find('\r') == std::string::npos);
  }

  void negative_latency_on_several_devices() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kRealFolder);
    // PoCL on a POWER9 host with four V100s: each V100 reports a negative kernel launch latency (lines 108, 162, 216,
    // 270); every device keeps its compute results. Single-precision peaks by hand: POWER9 float16 910.81; V100s
    // 15600.19 (float2), 15653.73 (float2), 15619.53 (float), 15610.50 (float2) GFLOPS.
    const auto batch = parse_real("pocl-power9-v100-negative-latency.log");
    QCOMPARE(batch.result_sets.size(), std::size_t{5});
    QCOMPARE(batch.result_sets[0].device_kind, bs::DeviceKind::Cpu);  // pthread-POWER9
    QVERIFY(near(find_measurement(batch.result_sets[0], "float16", "single-precision compute")->values[0], 910.81e9));
    QVERIFY(near(find_measurement(batch.result_sets[0], "kernel launch latency", "kernel launch latency")->values[0],
                 76.72e-6));
    const double v100[] = {15600.19e9, 15653.73e9, 15619.53e9, 15610.50e9};
    const char* at[] = {"float2", "float2", "float", "float2"};
    for (std::size_t i = 0; i < 4; ++i) {
      const bs::ResultSet& gpu = batch.result_sets[i + 1];
      QCOMPARE(gpu.device, std::string("Tesla V100-SXM2-16GB"));
      QCOMPARE(gpu.device_kind, bs::DeviceKind::Gpu);
      QVERIFY(near(find_measurement(gpu, at[i], "single-precision compute")->values[0], v100[i]));
      QVERIFY(!find_measurement(gpu, "kernel launch latency", "kernel launch latency"));
    }
    QCOMPARE(batch.warnings.size(), std::size_t{4});
    QVERIFY(batch.warnings[0].starts_with(kReal + "pocl-power9-v100-negative-latency.log:108: kernel launch latency"));
    QVERIFY(batch.warnings[3].find(":270: ") != std::string::npos);
    QVERIFY(batch.warnings[3].find("-10064.30") != std::string::npos);
  }

  void paste_without_platform_line() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kRealFolder);
    // AMD FX-8350 under AMD APP, saved from "Device:" on. Single precision 6.60 / 13.18 / 26.68 / 52.03 / 95.10
    // -> 95.10 GFLOPS (float16); double precision peaks at double8 50.76 (double16 drops to 6.81).
    const bs::FormatImporter imp(bs::kClpeakTextFileFormat);
    const std::string text = read_real("fx8350-no-platform.log");
    QVERIFY(imp.sniff(text, "fx8350.log") >= 80);
    const auto batch = parse_real("fx8350-no-platform.log");
    QCOMPARE(batch.result_sets.size(), std::size_t{1});
    const bs::ResultSet& cpu = batch.result_sets[0];
    QCOMPARE(cpu.platform, std::string("OpenCL"));  // no platform line: the backend stands in
    QCOMPARE(cpu.backend, std::string("OpenCL"));
    QCOMPARE(cpu.device, std::string("AMD FX(tm)-8350 Eight-Core Processor"));
    QCOMPARE(cpu.device_kind, bs::DeviceKind::Cpu);
    QVERIFY(near(find_measurement(cpu, "float16", "single-precision compute")->values[0], 95.10e9));
    QVERIFY(near(find_measurement(cpu, "double8", "double-precision compute")->values[0], 50.76e9));
    QVERIFY(batch.warnings.empty());
  }

  void shell_prompt_and_crash_on_the_last_line() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kRealFolder);
    // pocl issue 72: "$ ./clpeak", then the run dies at double8 with "Speicherzugriffsfehler" (line 27). Single
    // precision 2.06 / 2.87 / 8.44 / 3.18 / 1.39 -> 8.44 GFLOPS (float4); double 2.14 / 6.22 / 1.17 are kept.
    const auto batch = parse_real("pocl-i7-2620m-segfault-prompt.txt");
    QCOMPARE(batch.result_sets.size(), std::size_t{1});
    const bs::ResultSet& cpu = batch.result_sets[0];
    QCOMPARE(cpu.platform, std::string("Portable Computing Language"));
    QCOMPARE(cpu.device_kind, bs::DeviceKind::Cpu);
    QVERIFY(near(find_measurement(cpu, "float4", "single-precision compute")->values[0], 8.44e9));
    QVERIFY(near(find_measurement(cpu, "double2", "double-precision compute")->values[0], 6.22e9));
    QVERIFY(!find_measurement(cpu, "double8", "double-precision compute"));
    QCOMPARE(batch.warnings.size(), std::size_t{1});
    QVERIFY2(batch.warnings[0].starts_with(kReal + "pocl-i7-2620m-segfault-prompt.txt:27: double8: expected a number"),
             batch.warnings[0].c_str());
  }

  void error_code_on_the_last_line() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kRealFolder);
    // Beignet: "Kernel launch latency : clGetEventProfileInfo(-7)" then "Tests skipped". Single precision
    // 41.61 / 45.24 / 45.09 / 44.94 / 44.78 -> 45.24 GFLOPS (float2).
    const auto batch = parse_real("beignet-ivybridge-latency-error.log");
    QCOMPARE(batch.result_sets.size(), std::size_t{1});
    QVERIFY(near(find_measurement(batch.result_sets[0], "float2", "single-precision compute")->values[0], 45.24e9));
    QVERIFY(!find_measurement(batch.result_sets[0], "kernel launch latency", "kernel launch latency"));
    QCOMPARE(batch.warnings.size(), std::size_t{1});
    QVERIFY(batch.warnings[0].find("clGetEventProfileInfo(-7)") != std::string::npos);
  }

  void every_compute_test_failed_but_transfers_ran() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kRealFolder);
    // clpeak issue 47: PoCL fails every compute test with an OpenCL error, two transfer rows are "inf" and the run
    // hangs after "Kernel launch latency : ". The four transfer rows that printed 0.00 are what was measured.
    const auto batch = parse_real("pocl-fx8350-tests-skipped.txt");
    QCOMPARE(batch.result_sets.size(), std::size_t{1});
    const bs::ResultSet& cpu = batch.result_sets[0];
    QCOMPARE(cpu.measurements.size(), std::size_t{4});
    for (const auto& m : cpu.measurements) QCOMPARE(m.metric, std::string("transfer bandwidth"));
    // 1 failed bandwidth test, 3 failed buffer creations, 2 inf, 1 empty latency.
    QCOMPARE(batch.warnings.size(), std::size_t{7});
    QVERIFY(batch.warnings.back().find("kernel launch latency: no value") != std::string::npos);
  }

  void notes_and_platforms_without_devices() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kRealFolder);
    // Jetson Nano (Tegra X1) through PoCL 1.3, with a note after the output. Single precision
    // 214.09 / 229.80 / 230.95 / 229.31 / 228.80 -> 230.95 GFLOPS (float4).
    const auto nano = parse_real("pocl-jetson-nano-note.txt");
    QCOMPARE(nano.result_sets.size(), std::size_t{1});
    QCOMPARE(nano.result_sets[0].device, std::string("NVIDIA Tegra X1"));
    QVERIFY(near(find_measurement(nano.result_sets[0], "float4", "single-precision compute")->values[0], 230.95e9));
    QVERIFY(nano.warnings.empty());
    // Xeon Phi 7120 under Intel OpenCL, then two platforms that list no device. Single precision
    // 2130.58 / 2262.12 / 2255.07 / 2247.39 / 2213.89 -> 2262.12 GFLOPS (float2).
    const auto phi = parse_real("xeon-phi-empty-platforms.log");
    QCOMPARE(phi.result_sets.size(), std::size_t{1});
    QVERIFY(near(find_measurement(phi.result_sets[0], "float2", "single-precision compute")->values[0], 2262.12e9));
  }

  void clpeak2_vulkan_backend_banner_and_tflops() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kRealFolder);
    // clpeak issue 151 (clpeak 2.0, "=== Vulkan backend ===", "Vulkan Device:"). Single precision
    // 27373.58 / 43973.95 / 35605.51 -> 43973.95 GFLOPS (float2); cooperative-matrix FP8 E4M3 386.00 TFLOPS.
    const auto batch = parse_real("vulkan-rx9070xt-clpeak2.txt");
    QCOMPARE(batch.result_sets.size(), std::size_t{1});
    const bs::ResultSet& gpu = batch.result_sets[0];
    QCOMPARE(gpu.backend, std::string("Vulkan"));
    QCOMPARE(gpu.platform, std::string("Vulkan"));
    QCOMPARE(gpu.device, std::string("AMD Radeon RX 9070 XT (RADV GFX1201)"));
    QCOMPARE(gpu.device_kind, bs::DeviceKind::Gpu);
    QVERIFY(gpu.provenance.note.find("VRAM: 16304 MB") != std::string::npos);
    QVERIFY(near(find_measurement(gpu, "float2", "single-precision compute")->values[0], 43973.95e9));
    QVERIFY(near(find_measurement(gpu, "half4", "half-precision compute fp16xfp16+fp16")->values[0], 54536.66e9));
    const auto* fp8 = find_measurement(gpu, "coopmat_fp8_e4m3", "cooperative-matrix fp8(e4m3)xfp8(e4m3)+fp32 16x16x16");
    QVERIFY(fp8);
    QCOMPARE(fp8->unit, std::string("FLOP/s"));
    QVERIFY(near(fp8->values[0], 386.00e12));
    QVERIFY(near(find_measurement(gpu, "int", "integer compute int32")->values[0], 5306.11e9));  // GOPS
    QCOMPARE(find_measurement(gpu, "int", "integer compute int32")->unit, std::string("1/s"));
    QCOMPARE(gpu.measurements.size(), std::size_t{3 * 5 + 4 + 1});
    QVERIFY(batch.warnings.empty());
    QVERIFY(bs::FormatImporter(bs::kClpeakTextFileFormat).sniff(read_real("vulkan-rx9070xt-clpeak2.txt"), "x.txt") >=
            80);
  }

  void clpeak21_numbered_platforms_and_gops() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kRealFolder);
    // PR 157 (clpeak 2.1): single precision 13246.93 / 22060.01 / 25965.27 / 26244.43 / 26556.29 -> 26556.29
    // GFLOPS (float16); half 52259.02 (half4); integer 5508.20 GOPS (int4).
    const auto batch = parse_real("opencl-gfx1201-clpeak2.txt");
    QCOMPARE(batch.result_sets.size(), std::size_t{1});
    const bs::ResultSet& gpu = batch.result_sets[0];
    QCOMPARE(gpu.platform, std::string("AMD Accelerated Parallel Processing"));
    QCOMPARE(gpu.device, std::string("gfx1201"));
    QCOMPARE(gpu.device_kind, bs::DeviceKind::Gpu);
    QVERIFY(near(find_measurement(gpu, "float16", "single-precision compute")->values[0], 26556.29e9));
    QVERIFY(near(find_measurement(gpu, "int4", "integer compute")->values[0], 5508.20e9));
    QVERIFY(near(find_measurement(gpu, "int2", "integer compute fast 24bit")->values[0], 23896.53e9));
    QVERIFY(batch.warnings.empty());
  }

  void clpeak21_units_on_each_value_line() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(kRealFolder);
    // clpeak issue 210: "Divide and square-root throughput [SSE2]" has no unit; each row says "8.48 GFLOPS".
    const auto batch = parse_real("cpu-divsqrt-units-per-line.txt");
    QCOMPARE(batch.result_sets.size(), std::size_t{1});
    const bs::ResultSet& cpu = batch.result_sets[0];
    QCOMPARE(cpu.backend, std::string("CPU"));
    QCOMPARE(cpu.device_kind, bs::DeviceKind::Cpu);
    QCOMPARE(cpu.device, std::string("Virtual CPU @ 2.95GHz"));
    const auto* sse2 = find_measurement(cpu, "fdiv fp32 ST", "divide and square-root throughput [SSE2]");
    QVERIFY(sse2);
    QCOMPARE(sse2->unit, std::string("FLOP/s"));
    QVERIFY(near(sse2->values[0], 8.48e9));
    QVERIFY(near(find_measurement(cpu, "fdiv fp32 MT", "divide and square-root throughput [AVX2]")->values[0], 92.8e9));
    QCOMPARE(cpu.measurements.size(), std::size_t{16});
    QVERIFY(batch.warnings.empty());
  }

  void file_with_no_measurement_is_a_missing_field() {
    // Raspberry Pi 5 (clpeak issue 142): the queue cannot be created, nothing is measured. A third-party bad input
    // (the shared folder's tests/data/bad/, described in tests/data/importers/clpeak/SOURCES there).
    BENCHSCOPE_REQUIRE_PUBLIC_DATA("tests/data/bad");
    const bs::ImportError rpi =
        error_of(file_text(bs::test::public_data("tests/data/bad/clpeak-rpi5-queue-error.txt")));
    QCOMPARE(rpi.category(), bs::ImportErrorCategory::MissingField);
    QCOMPARE(rpi.location().line, std::size_t{3});
  }

  void file_with_no_measurement_names_its_first_bad_value() {
    // Only unreadable values: the first one is the error, with its line.
    const bs::ImportError inf = error_of("Platform: P\n  Device: D\n    Transfer bandwidth (GBPS)\n      a : inf\n");
    QCOMPARE(inf.category(), bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(inf.location().line, std::size_t{4});
  }
};

QTEST_GUILESS_MAIN(TestClpeakText)
#include "test_clpeak_text.moc"
