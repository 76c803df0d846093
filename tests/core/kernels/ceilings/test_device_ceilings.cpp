// SPDX-License-Identifier: GPL-3.0-or-later
// Empirical ceilings of device backends (OpenCL here, on PoCL's CPU device where no GPU is present; CUDA in
// test_cuda_backend): measured through measure_device_ceilings with every micro-kernel's result checked inside (a
// kernel that skipped work throws), stored in and read back from the per-host cache under the device's own key,
// and turned into a workspace result set of the right device kind. No timing is judged.
#include <QTemporaryDir>
#include <QTest>
#include <fstream>

#include "kernels/backends/backend.h"
#include "kernels/backends/backend_opencl.h"
#include "kernels/ceilings/ceiling_cache.h"
#include "kernels/ceilings/ceilings.h"
#include "util/host_clock.h"

using namespace bs::kernels;

namespace {

CeilingSpec quick_spec() {
  CeilingSpec spec;
  spec.repeats = 2;
  spec.device_target_seconds = 0.02;
  spec.device_copy_mib = 4;
  return spec;
}

}  // namespace

class TestDeviceCeilings : public QObject {
  Q_OBJECT
 private slots:
  void opencl_devices_measure_checked_ceilings() {
    const auto backends = opencl_backends(detect_cpu());
    if (backends.empty()) QSKIP(qPrintable(QString::fromStdString(opencl_unavailable_reason())));
    for (const Backend& b : backends) {
      QVERIFY2(b.ceiling_kernels, b.id.c_str());
      const CeilingSet set = measure_device_ceilings(b, quick_spec(), bs::CancelToken{});
      QCOMPARE(set.isa, std::string("opencl"));
      QCOMPARE(set.cpu_model, b.device_name);
      QCOMPARE(set.backend, b.label);
      QCOMPARE(set.threads, 0);
      QCOMPARE(set.kind, b.kind);
      QCOMPARE(set.computed_peak_flops, b.theoretical_peak_flops);
      for (const Ceiling* c : {&set.rotation_mix, &set.fma, &set.bandwidth}) {
        QCOMPARE(c->values.size(), std::size_t{2});
        for (double v : c->values) QVERIFY(std::isfinite(v) && v > 0);
        QVERIFY(c->per_cpu_second.empty());  // timed on the device: no per-CPU-second figure
        QVERIFY(!c->how.empty());
      }
      QCOMPARE(set.rotation_mix.unit, std::string("FLOP/s"));
      QCOMPARE(set.bandwidth.unit, std::string("B/s"));
      QVERIFY(set.bandwidth.how.find("4 MiB") != std::string::npos);
    }
  }

  void a_cancelled_measurement_stops() {
    const auto backends = opencl_backends(detect_cpu());
    if (backends.empty()) QSKIP("no OpenCL device");
    bs::CancelToken cancel;
    cancel.cancel();
    QVERIFY_THROWS_EXCEPTION(bs::Cancelled, measure_device_ceilings(backends.front(), quick_spec(), cancel));
  }

  void a_backend_without_ceiling_kernels_is_refused() {
    const auto cpu = cpu_backends(detect_cpu());
    for (const Backend& b : cpu) {
      QVERIFY(!b.ceiling_kernels);  // the CPU's ceilings come from measure_ceilings(CpuInfo)
      QVERIFY_THROWS_EXCEPTION(std::invalid_argument, measure_device_ceilings(b, quick_spec(), bs::CancelToken{}));
    }
  }

  void device_ceilings_are_cached_under_the_device() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("ceilings.json").toStdString();
    Backend gpu;
    gpu.id = "cuda:0";
    gpu.label = "CUDA";
    gpu.device_name = "NVIDIA Jetson Orin (test)";
    gpu.kind = bs::DeviceKind::Gpu;
    gpu.ceiling_kernels = [](const CeilingSpec&) -> std::unique_ptr<DeviceCeilingKernels> { return nullptr; };
    QVERIFY(!cached_device_ceilings(gpu, path));
    CeilingSet set;
    set.host = bs::host_name();
    set.cpu_model = gpu.device_name;
    set.backend = gpu.label;
    set.isa = device_ceiling_family(gpu);
    set.kind = bs::DeviceKind::Gpu;
    set.date = "2026-11-26T15:00:00Z";
    set.rotation_mix = {"FLOP/s", {4.9e13, 4.8e13}, {}, "rotation mix: test"};
    set.fma = {"FLOP/s", {6.1e13}, {}, "FMA: test"};
    set.bandwidth = {"B/s", {2.9e12}, {}, "copy: test"};
    store_ceilings(set, path);
    const auto back = cached_device_ceilings(gpu, path);
    QVERIFY(back);
    QCOMPARE(back->isa, std::string("cuda"));
    QCOMPARE(back->kind, bs::DeviceKind::Gpu);
    QCOMPARE(back->rotation_mix.values, set.rotation_mix.values);
    QVERIFY(back->rotation_mix.per_cpu_second.empty());
    // Another device of the same backend family has no entry; neither has a backend without ceiling kernels.
    Backend other = gpu;
    other.device_name = "NVIDIA H100 80GB HBM3";
    QVERIFY(!cached_device_ceilings(other, path));
    Backend none = gpu;
    none.ceiling_kernels = nullptr;
    QVERIFY(!cached_device_ceilings(none, path));
  }

  void a_bad_kind_in_the_cache_is_named() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("ceilings.json").toStdString();
    CeilingSet set;
    set.host = "h";
    set.cpu_model = "d";
    set.isa = "opencl";
    store_ceilings(set, path);
    std::ifstream in(path);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    const auto at = text.find("\"kind\": \"cpu\"");
    QVERIFY(at != std::string::npos);
    text.replace(at, 13, "\"kind\": \"tpu\"");
    std::ofstream(path) << text;
    try {
      load_ceiling_cache(path);
      QFAIL("a bad kind was accepted");
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      QVERIFY2(what.find("entries[0]") != std::string::npos && what.find("kind") != std::string::npos, e.what());
    }
  }

  void a_gpu_result_set_names_the_gpu() {
    CeilingSet set;
    set.host = "robot";
    set.cpu_model = "Orin (nvgpu)";
    set.backend = "CUDA";
    set.isa = "cuda";
    set.kind = bs::DeviceKind::Gpu;
    set.rotation_mix = {"FLOP/s", {1e12}, {}, "mix"};
    set.bandwidth = {"B/s", {1e11}, {}, "copy"};
    const bs::ResultSet rs = ceiling_result_set(set);
    QCOMPARE(rs.device_kind, bs::DeviceKind::Gpu);
    QCOMPARE(rs.device, std::string("Orin (nvgpu)"));
    QCOMPARE(rs.provenance.gpu_model, std::string("Orin (nvgpu)"));
    QVERIFY(rs.provenance.cpu_model.empty());
    QCOMPARE(rs.measurements.size(), std::size_t{2});
    QCOMPARE(rs.measurements[0].name, std::string("rotation-mix/cuda"));
    QCOMPARE(rs.measurements[1].name, std::string("device-copy/cuda"));
    QCOMPARE(rs.measurements[1].metric, std::string("bandwidth"));
  }
};

QTEST_APPLESS_MAIN(TestDeviceCeilings)
#include "test_device_ceilings.moc"
