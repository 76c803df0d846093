// SPDX-License-Identifier: GPL-3.0-or-later
#include <QtTest>

#include "clpeak_text.h"

class TestClpeakText : public QObject {
  Q_OBJECT
 private slots:
  void parses_two_platforms() {
    const bs::CancelToken cancel;
    const auto batch =
        bs::ClpeakTextImporter().parse(BENCHSCOPE_TEST_DATA_DIR "/importers/clpeak/gtx1080ti.txt", {}, cancel);
    QCOMPARE(batch.result_sets.size(), std::size_t{2});
    const bs::ResultSet& gpu = batch.result_sets[0];
    QCOMPARE(gpu.platform, std::string("NVIDIA CUDA"));
    QCOMPARE(gpu.device, std::string("GeForce GTX 1080 Ti"));
    QCOMPARE(gpu.device_kind, bs::DeviceKind::Gpu);
    QVERIFY(gpu.provenance.note.find("Compute units: 28") != std::string::npos);
    int sp = 0;
    double best = 0;
    for (const auto& m : gpu.measurements) {
      if (m.metric == "single-precision compute") {
        ++sp;
        QCOMPARE(m.unit, std::string("FLOP/s"));
        best = std::max(best, m.values[0]);
      }
      if (m.metric == "kernel launch latency") QVERIFY(std::abs(m.values[0] - 5.32e-6) < 1e-12);
      if (m.name == "memcpy from mapped ptr") QVERIFY(std::abs(m.values[0] - 10.35e9) < 1);
    }
    QCOMPARE(sp, 5);
    QCOMPARE(best, 11461.23e9);
    QCOMPARE(batch.result_sets[1].device_kind, bs::DeviceKind::Cpu);  // PoCL
  }
  void crlf_and_bad_number() {
    const auto ok = bs::parse_clpeak_text("Platform: P\r\n  Device: D\r\n    Single-precision compute (GFLOPS)\r\n      float : 1.5\r\n", "c.txt");
    QCOMPARE(ok.result_sets[0].measurements[0].values[0], 1.5e9);
    try {
      bs::parse_clpeak_text("Platform: P\n  Device: D\n    Single-precision compute (GFLOPS)\n      float : fast\n", "c.txt");
      QFAIL("accepted");
    } catch (const bs::ImportError& e) {
      QCOMPARE(e.location().line, std::size_t{4});
      QVERIFY(std::string(e.what()).starts_with("c.txt:4:"));
    }
  }
};

QTEST_GUILESS_MAIN(TestClpeakText)
#include "test_clpeak_text.moc"
