// SPDX-License-Identifier: GPL-3.0-or-later
// Kernel facts read through a fixture root: a PREEMPT_RT board with isolated CPUs and a generic desktop kernel.
#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include "headroom/kernel_facts.h"

using namespace bs::headroom;

namespace {

void write(const QString& root, const QString& rel, const QByteArray& text) {
  const QString path = root + "/" + rel;
  QDir().mkpath(QFileInfo(path).absolutePath());
  QFile f(path);
  QVERIFY(f.open(QIODevice::WriteOnly));
  f.write(text);
}

}  // namespace

class TestKernelFacts : public QObject {
  Q_OBJECT
 private slots:
  void preempt_rt_board() {
    QTemporaryDir dir;
    const QString r = dir.path();
    write(r, "proc/sys/kernel/osrelease", "6.1.0-18-rt-arm64\n");
    write(r, "proc/sys/kernel/version", "#1 SMP PREEMPT_RT Debian 6.1.76-1 (2024-02-01)\n");
    write(r, "sys/kernel/realtime", "1\n");
    write(r, "proc/cmdline", "console=ttyS0 isolcpus=2,3 rcu_nocbs=2,3 nohz_full=2-3 isolcpus=domain,2-3 quiet\n");
    for (int cpu = 0; cpu < 4; ++cpu)
      write(r, QString("sys/devices/system/cpu/cpu%1/cpufreq/scaling_governor").arg(cpu), "performance\n");
    write(r, "sys/devices/system/cpu/cpufreq/policy0/scaling_governor", "ondemand\n");  // not a cpuN folder
    const KernelFacts k = read_kernel_facts(r.toStdString());
    QCOMPARE(QString::fromStdString(k.release), QString("6.1.0-18-rt-arm64"));
    QCOMPARE(k.preempt_rt, std::optional<bool>(true));
    QCOMPARE(QString::fromStdString(k.preemption), QString("PREEMPT_RT"));
    QCOMPARE(QString::fromStdString(k.isolcpus), QString("domain,2-3"));  // the last one wins, as in the kernel
    QCOMPARE(QString::fromStdString(k.nohz_full), QString("2-3"));
    QCOMPARE(QString::fromStdString(k.governor), QString("performance"));
  }

  void generic_desktop_kernel() {
    QTemporaryDir dir;
    const QString r = dir.path();
    write(r, "proc/sys/kernel/osrelease", "6.1.0-18-amd64");
    write(r, "proc/sys/kernel/version", "#1 SMP PREEMPT_DYNAMIC Debian 6.1.76-1 (2024-02-01)");
    write(r, "proc/cmdline", "BOOT_IMAGE=/vmlinuz root=/dev/sda1 ro quiet");
    QDir().mkpath(r + "/sys/kernel");  // sysfs readable, no realtime file: not RT
    write(r, "sys/devices/system/cpu/cpu0/cpufreq/scaling_governor", "powersave");
    write(r, "sys/devices/system/cpu/cpu1/cpufreq/scaling_governor", "performance");
    write(r, "sys/devices/system/cpu/cpu2/cpufreq/scaling_governor", "powersave");
    const KernelFacts k = read_kernel_facts(r.toStdString());
    QCOMPARE(k.preempt_rt, std::optional<bool>(false));
    QCOMPARE(QString::fromStdString(k.preemption), QString("PREEMPT_DYNAMIC"));
    QVERIFY(k.isolcpus.empty());
    QVERIFY(k.nohz_full.empty());
    QCOMPARE(QString::fromStdString(k.governor), QString("performance x1, powersave x2"));
  }

  void nothing_readable() {
    QTemporaryDir dir;
    const KernelFacts k = read_kernel_facts(dir.path().toStdString());
    QVERIFY(k.release.empty());
    QVERIFY(!k.preempt_rt);  // no sysfs at all: unknown, not "no"
    QVERIFY(k.governor.empty());
  }

  void cmdline_values() {
    QCOMPARE(QString::fromStdString(cmdline_value("a=1 isolcpus=1-3 b", "isolcpus")), QString("1-3"));
    QCOMPARE(QString::fromStdString(cmdline_value("xisolcpus=5", "isolcpus")), QString(""));
  }
};

QTEST_APPLESS_MAIN(TestKernelFacts)
#include "test_kernel_facts.moc"
