// SPDX-License-Identifier: GPL-3.0-or-later
// Power sensors on fixture sysfs trees: no real hardware. Every expected energy is the fixture's own arithmetic.
#include <QTemporaryDir>
#include <QTest>

#include <sys/wait.h>
#include <unistd.h>
#include <atomic>
#include <cmath>
#include <thread>

#include "../../support/sysfs_fixture.h"
#include "analysis/power/phase_energy.h"
#include "sensors/discovery.h"
#include "sensors/ina3221.h"
#include "sensors/nvml.h"
#include "sensors/rapl.h"
#include "sensors/recorder.h"

using namespace bs;
using namespace bs::sensors;
namespace fs = std::filesystem;

namespace {

DiscoveryOptions no_nvml(const fs::path& root) { return {root, ""}; }

const Sensor* by_id(const SensorSet& set, const std::string& id) {
  for (const auto& s : set.sensors)
    if (s->info().id == id) return s.get();
  return nullptr;
}

}  // namespace

class TestSensors : public QObject {
  Q_OBJECT
 private slots:
  void counter_delta_wraps_once() {
    QCOMPARE(*counter_delta(100, 350, 1000), 250LL);
    // 900 -> wrap at 1000 -> 150: (1000 - 900) + 150 = 250
    QCOMPARE(*counter_delta(900, 150, 1000), 250LL);
    QVERIFY(!counter_delta(900, 150, 0));  // unknown range: a drop is not sized
  }

  void rapl_zones_and_wraparound_by_hand() {
    QTemporaryDir dir;
    const fs::path root = dir.path().toStdString();
    // max_energy_range_uj as the kernel reports it on a Skylake package: 262143328850 uJ.
    constexpr long long max = 262143328850;
    test::rapl_package(root, 0, max - 1'000'000, max);
    test::rapl_subzone(root, 0, 0, "core", 5'000'000, max);
    test::rapl_subzone(root, 0, 1, "dram", 7'000'000, max);
    SensorSet set = find_sensors(no_nvml(root));
    QCOMPARE(set.sensors.size(), std::size_t{3});
    QCOMPARE(set.sensors[0]->info().id, std::string("rapl:package-0"));
    QCOMPARE(set.sensors[1]->info().id, std::string("rapl:package-0/core"));
    QCOMPARE(set.sensors[2]->info().id, std::string("rapl:package-0/dram"));
    QVERIFY(set.sensors[0]->info().board_total);
    QVERIFY(!set.sensors[1]->info().board_total);
    QCOMPARE(set.sensors[0]->info().source, std::string("/sys/class/powercap/intel-rapl:0/energy_uj"));
    Sensor& pkg = *set.sensors[0];
    QCOMPARE(*pkg.read(), 0.0);  // joules since the first read
    test::put(root, "sys/class/powercap/intel-rapl:0/energy_uj", std::to_string(max - 250'000));
    QCOMPARE(*pkg.read(), 0.75);  // 750,000 uJ
    test::put(root, "sys/class/powercap/intel-rapl:0/energy_uj", "500000");
    // wrapped: (max - (max - 250,000)) + 500,000 = 750,000 uJ more: 1.5 J in all
    QCOMPARE(*pkg.read(), 1.5);
  }

  void rapl_counter_advanced_by_a_thread_with_a_wraparound() {
    QTemporaryDir dir;
    const fs::path root = dir.path().toStdString();
    // 5,000 uJ per step every 2 ms = 2.5 W, counter wrapping at 1,000,000 uJ: starting 300,000 uJ below the top,
    // it wraps after 60 steps (120 ms) of the recording.
    constexpr long long max = 1'000'000, step = 5'000;
    long long counter = max - 300'000;
    test::rapl_package(root, 0, counter, max);
    SensorSet set = find_sensors(no_nvml(root));
    Selection sel = select_sensors(set, "auto");
    QCOMPARE(sel.sensors.front()->info().id, std::string("rapl:package-0"));
    PowerRecorder rec(std::move(sel), std::chrono::milliseconds(20));
    std::atomic<bool> stop{false};
    std::atomic<long long> steps{0};
    rec.start();
    std::thread writer([&] {
      while (!stop) {
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
        counter = (counter + step) % max;  // the register's wrap, in uJ
        test::put(root, "sys/class/powercap/intel-rapl:0/energy_uj", std::to_string(counter));
        ++steps;
      }
    });
    rec.begin_phase("load");
    // Until the writer has gone past the wrap (60 steps) and well beyond, however slow this machine is today.
    for (int i = 0; i < 1000 && steps < 150; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    rec.end_phase();
    stop = true;
    writer.join();
    const PowerTrace trace = rec.finish("fixture");
    QVERIFY(steps >= 150);  // at least one wraparound (60 steps) happened while recording
    QCOMPARE(trace.total_channel, std::string("package-0"));
    QCOMPARE(trace.provenance.measurement, MeasurementKind::OnBoardSensor);
    // The counter's exact advance is what the trace's intervals add up to: sum of P_i * dt_i (i >= 1) equals
    // steps x 5,000 uJ, the wrap included (the recorder's last sample came after the writer stopped).
    const auto& p = trace.channels[0].values;
    double joules = 0;
    for (std::size_t i = 1; i < p.size(); ++i) joules += p[i] * (trace.time_s[i] - trace.time_s[i - 1]);
    QCOMPARE(std::round(joules * 1e6), static_cast<double>(steps.load() * step));
    for (double w : p) QVERIFY(std::isfinite(w) && w >= 0 && w < 100);  // no wrap ever shows as a spike
    // What the sampling thread cost, measured on its own CPU clock: some, and less than the time it ran (it sleeps
    // between samples). The figure travels with the trace's provenance.
    QVERIFY(std::isfinite(rec.sampler_cpu_s()) && rec.sampler_cpu_s() > 0);
    QVERIFY(rec.recorded_s() > 0.1);
    QVERIFY2(rec.sampler_cpu_s() < 0.5 * rec.recorded_s(), qPrintable(QString::number(rec.sampler_cpu_s())));
    bool noted = false;
    for (const auto& [key, value] : trace.provenance.settings)
      noted = noted || (key == "sampler cost" && value.find("% of one core") != std::string::npos);
    QVERIFY(noted);
  }

  void power_from_energy_by_hand() {
    // 0 J, 1 J after 0.5 s, 3 J after 1.5 s: 2 W, then 2 W; the first sample takes the first interval's power.
    const auto w = power_from_energy({0, 0.5, 1.5, 2.0}, {0, 1, 3, NAN});
    QCOMPARE(w[0], 2.0);
    QCOMPARE(w[1], 2.0);
    QCOMPARE(w[2], 2.0);
    QVERIFY(std::isnan(w[3]));  // a failed read is missing, never zero
  }

  void ina3221_jetpack5_hwmon() {
    QTemporaryDir dir;
    const fs::path root = dir.path().toStdString();
    // Orin NX / Xavier NX rails (energymon's JetsonPowerRails.md): VDD_IN, VDD_CPU_GPU_CV, VDD_SOC on 0x40.
    const std::string d = test::ina3221_hwmon_dir("1-0040", 3);
    test::ina3221_hwmon_channel(root, d, 1, "VDD_IN", 5000, 1200);         // 5.000 V x 1.200 A = 6.0 W
    test::ina3221_hwmon_channel(root, d, 2, "VDD_CPU_GPU_CV", 5000, 400);  // 2.0 W
    test::ina3221_hwmon_channel(root, d, 3, "VDD_SOC", 5000, 300);         // 1.5 W
    test::put(root, d + "/in7_label", "Sum of shunt voltages");            // Orin's extra channel: no rail
    test::put(root, d + "/name", "ina3221");
    // The same chip under /sys/class/hwmon is not listed twice.
    test::put(root, "sys/class/hwmon/hwmon3/name", "ina3221");
    SensorSet set = find_sensors(no_nvml(root));
    QCOMPARE(set.sensors.size(), std::size_t{3});
    const Sensor* in = by_id(set, "ina3221:1-0040:VDD_IN");
    QVERIFY(in && in->info().board_total && in->info().readable);
    QVERIFY(!by_id(set, "ina3221:1-0040:VDD_SOC")->info().board_total);
    QCOMPARE(*set.sensors[0]->read(), 6.0);
    QCOMPARE(*set.sensors[1]->read(), 2.0);
    // auto: the input rail is the total, the other rails beside it and never added to it.
    Selection sel = select_sensors(set, "auto");
    QCOMPARE(sel.sensors.size(), std::size_t{3});
    QCOMPARE(sel.total, std::size_t{0});
    QCOMPARE(sel.sensors[0]->info().label, std::string("VDD_IN"));
    PowerRecorder rec(std::move(sel), std::chrono::milliseconds(10));
    rec.start();
    rec.begin_phase("window");
    std::this_thread::sleep_for(std::chrono::milliseconds(120));
    rec.end_phase();
    const PowerTrace t = rec.finish("jetson");
    QCOMPARE(t.total_channel, std::string("VDD_IN"));
    const auto e = phase_energies(t);
    QCOMPARE(e.size(), std::size_t{1});
    // Constant 6.0 W: energy = 6.0 W x the phase's length (1e-9 relative: floating-point sums only).
    QVERIFY(std::abs(e[0].energy_j - 6.0 * (e[0].end_s - e[0].start_s)) < 1e-9);
    QVERIFY(std::abs(e[0].mean_power_w - 6.0) < 1e-9);
  }

  void ina3221x_jetpack4_iio() {
    QTemporaryDir dir;
    const fs::path root = dir.path().toStdString();
    // Nano rails (POM_5V_IN is its input): the values of a Nano tegrastats line "POM_5V_IN 3960/3960 POM_5V_GPU
    // 0/0 POM_5V_CPU 1068/1068".
    test::ina3221x_channel(root, "6-0040", 0, "POM_5V_IN", 3960, 792, 5000);
    test::ina3221x_channel(root, "6-0040", 1, "POM_5V_GPU", 0, 0, 5000);
    test::ina3221x_channel(root, "6-0040", 2, "POM_5V_CPU", 1068, 213, 5000);
    SensorSet set = find_sensors(no_nvml(root));
    QCOMPARE(set.sensors.size(), std::size_t{3});
    QCOMPARE(set.sensors[0]->info().id, std::string("ina3221:6-0040:POM_5V_IN"));
    QCOMPARE(set.sensors[0]->info().unit, std::string("mW"));
    QVERIFY(set.sensors[0]->info().board_total);
    QCOMPARE(*set.sensors[0]->read(), 3.96);
    QCOMPARE(*set.sensors[2]->read(), 1.068);
    QVERIFY(is_input_rail("VDD_IN") && !is_input_rail("VDD_SYS_GPU"));
  }

  void hwmon_power_and_energy() {
    QTemporaryDir dir;
    const fs::path root = dir.path().toStdString();
    // amdgpu: power1_average in uW with a label; amd_energy: energy counters in uJ.
    test::put(root, "sys/class/hwmon/hwmon2/name", "amdgpu");
    test::put(root, "sys/class/hwmon/hwmon2/power1_average", "35000000");  // 35 W
    test::put(root, "sys/class/hwmon/hwmon2/power1_label", "PPT");
    test::put(root, "sys/class/hwmon/hwmon10/name", "amd_energy");
    test::put(root, "sys/class/hwmon/hwmon10/energy1_input", "1000000");
    test::put(root, "sys/class/hwmon/hwmon10/energy1_label", "Esocket0");
    SensorSet set = find_sensors(no_nvml(root));
    QCOMPARE(set.sensors.size(), std::size_t{2});
    QCOMPARE(set.sensors[0]->info().id, std::string("hwmon:hwmon2:power1_average"));  // hwmon2 before hwmon10
    QCOMPARE(set.sensors[0]->info().label, std::string("PPT"));
    QCOMPARE(*set.sensors[0]->read(), 35.0);
    Sensor& e = *set.sensors[1];
    QCOMPARE(e.info().quantity, SensorQuantity::Energy);
    QCOMPARE(*e.read(), 0.0);
    test::put(root, "sys/class/hwmon/hwmon10/energy1_input", "3500000");
    QCOMPARE(*e.read(), 2.5);  // 2,500,000 uJ
  }

  void unreadable_files() {
    QTemporaryDir dir;
    const fs::path root = dir.path().toStdString();
    fs::permissions(root, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                              fs::perms::others_read | fs::perms::others_exec);
    test::rapl_package(root, 0, 1000, 1'000'000);
    // As the kernel has it since 2020: energy_uj mode 0400, owned by root.
    fs::permissions(root / "sys/class/powercap/intel-rapl:0/energy_uj", fs::perms::owner_read);
    // A rail whose value cannot be read at all (a folder where a file should be): the reason is the errno's.
    const std::string d = test::ina3221_hwmon_dir("1-0040", 0);
    test::put(root, d + "/in1_label", "VDD_IN");
    fs::create_directories(root / d / "in1_input");
    test::put(root, d + "/curr1_input", "100");
    SensorSet set = find_sensors(no_nvml(root));
    const Sensor* rail = by_id(set, "ina3221:1-0040:VDD_IN");
    QVERIFY(rail && !rail->info().readable);
    QVERIFY2(rail->info().reason.find("directory") != std::string::npos, rail->info().reason.c_str());
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, select_sensors(set, "ina3221:1-0040:VDD_IN"));
    // Permission denied needs a user who is not root: as root, check it in a child that drops to "nobody".
    const auto check_rapl = [&]() -> bool {
      SensorSet s = find_sensors(no_nvml(root));
      const Sensor* pkg = by_id(s, "rapl:package-0");
      return pkg && !pkg->info().readable && pkg->info().reason.find("root only") != std::string::npos &&
             pkg->info().reason.find("chmod") != std::string::npos;
    };
    if (geteuid() != 0) {
      QVERIFY(check_rapl());
    } else {
      const pid_t pid = fork();
      if (pid == 0) {
        if (setgid(65534) != 0 || setuid(65534) != 0) _exit(3);
        _exit(check_rapl() ? 0 : 1);
      }
      int status = 0;
      QCOMPARE(waitpid(pid, &status, 0), pid);
      QVERIFY(WIFEXITED(status));
      QCOMPARE(WEXITSTATUS(status), 0);
    }
  }

  void no_sensor_at_all() {
    QTemporaryDir dir;
    SensorSet set = find_sensors(no_nvml(dir.path().toStdString()));
    QVERIFY(set.sensors.empty());
    try {
      select_sensors(set, "auto");
      QFAIL("auto chose a sensor from nothing");
    } catch (const std::invalid_argument& e) {
      QCOMPARE(std::string(e.what()), std::string("no power sensors found"));
    }
  }

  void nvml_missing_and_not_supported() {
    const NvmlProbe missing = find_nvml("libbenchscope-no-such-nvml.so");
    QVERIFY(missing.sensors.empty());
    QVERIFY(missing.problem.find("not found") != std::string::npos);
    // A stand-in library with NVML's C interface whose one GPU answers NotSupported, as a Jetson's does.
    const NvmlProbe jetson = find_nvml(BENCHSCOPE_FAKE_NVML);
    QCOMPARE(jetson.sensors.size(), std::size_t{1});
    const SensorInfo& gpu = jetson.sensors[0]->info();
    QCOMPARE(gpu.id, std::string("nvml:0"));
    QCOMPARE(gpu.label, std::string("Orin (nvgpu)"));
    QVERIFY(!gpu.readable);
    QVERIFY(gpu.reason.starts_with("NotSupported"));
  }

  void multi_package_auto_sums_packages() {
    QTemporaryDir dir;
    const fs::path root = dir.path().toStdString();
    test::rapl_package(root, 0, 0, 1'000'000);
    test::rapl_package(root, 1, 0, 1'000'000);
    SensorSet set = find_sensors(no_nvml(root));
    Selection sel = select_sensors(set, "auto");
    QCOMPARE(sel.sensors[0]->info().id, std::string("rapl:packages"));
    QCOMPARE(sel.sensors.size(), std::size_t{3});
    QCOMPARE(*sel.sensors[0]->read(), 0.0);
    test::put(root, "sys/class/powercap/intel-rapl:0/energy_uj", "200000");
    test::put(root, "sys/class/powercap/intel-rapl:1/energy_uj", "300000");
    QCOMPARE(*sel.sensors[0]->read(), 0.5);  // 0.2 J + 0.3 J
  }

  void phase_energy_by_hand() {
    PowerTrace t;
    t.time_s = {0, 1, 2, 3, 4};
    t.channels.push_back({"rail", PowerQuantity::Power, {1, 1, 3, 3, NAN}});
    t.channels.push_back({"total", PowerQuantity::Power, {2, 2, 4, 4, 4}});
    t.total_channel = "total";
    t.phases = {{"a", 0, 1}, {"b", 0.5, 2.5}};
    const auto e = phase_energies(t);
    QCOMPARE(e.size(), std::size_t{2});
    QCOMPARE(e[0].energy_j, 2.0);  // 2 W for 1 s
    // b: 0.5..1 at 2 W = 1.0; 1..2 trapezoid (2+4)/2 = 3.0; 2..2.5 at 4 W = 2.0: 6.0 J over 2 s = 3 W
    QCOMPARE(e[1].energy_j, 6.0);
    QCOMPARE(e[1].mean_power_w, 3.0);
    QCOMPARE(e[1].samples, std::size_t{2});
    QCOMPARE(*joules_per_item(e[1], 4), 1.5);
    QCOMPARE(*gflops_per_watt(30e9, e[1]), 10.0);  // 30 GFLOPS / 3 W
  }
};

QTEST_GUILESS_MAIN(TestSensors)
#include "test_sensors.moc"
