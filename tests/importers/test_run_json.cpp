// SPDX-License-Identifier: GPL-3.0-or-later
#include <QtTest>

#include <nlohmann/json.hpp>
#include <fstream>
#include <set>

#include "run_json.h"

namespace {
const std::string kData = BENCHSCOPE_TEST_DATA_DIR "/importers/";

void collect_keys(const nlohmann::json& j, std::set<std::string>& keys) {
  if (j.is_object())
    for (const auto& [k, v] : j.items()) {
      keys.insert(k);
      collect_keys(v, keys);
    }
  if (j.is_array())
    for (const auto& v : j) collect_keys(v, keys);
}
}  // namespace

class TestRunJson : public QObject {
  Q_OBJECT
 private slots:
  void parses_fixture() {
    const bs::CancelToken cancel;
    const auto batch = bs::RunJsonImporter().parse(kData + "run-json/two-runs.json", {}, cancel);
    QCOMPARE(batch.runs.size(), std::size_t{2});
    const bs::FlopsRun& cpu = batch.runs[0];
    QCOMPARE(cpu.device_kind, bs::DeviceKind::Cpu);
    QCOMPARE(cpu.dims, 4);
    QCOMPARE(cpu.iterations, std::int64_t{1000});
    QCOMPARE(cpu.samples.size(), std::size_t{2});
    QCOMPARE(cpu.samples[0].seconds.size(), std::size_t{3});
    QCOMPARE(*cpu.theoretical_peak_flops, 1.0e11);
    QCOMPARE(cpu.provenance.origin, bs::DataOrigin::Measured);  // file-level default
    QCOMPARE(cpu.provenance.host, std::string("lab-pc"));
    const bs::FlopsRun& gpu = batch.runs[1];
    QCOMPARE(gpu.variant, std::string("float16x4"));
    QCOMPARE(gpu.kernel, std::string("rotation2d"));  // default
    QCOMPARE(gpu.provenance.origin, bs::DataOrigin::Reconstructed);  // run-level override
    QCOMPARE(gpu.provenance.host, std::string("lab-pc"));              // inherited
    QVERIFY(batch.warnings.empty());
  }
  void round_trip_is_identical() {
    const bs::CancelToken cancel;
    const auto first = bs::RunJsonImporter().parse(kData + "run-json/two-runs.json", {}, cancel);
    const std::string text = bs::write_run_json(first.runs);
    const auto second = bs::parse_run_json(text, "memory");
    QCOMPARE(second.runs.size(), first.runs.size());
    for (std::size_t i = 0; i < first.runs.size(); ++i) {
      const auto& a = first.runs[i];
      const auto& b = second.runs[i];
      QCOMPARE(b.device, a.device);
      QCOMPARE(b.variant, a.variant);
      QCOMPARE(b.reported_peak_flops, a.reported_peak_flops);
      QCOMPARE(b.samples.size(), a.samples.size());
      for (std::size_t k = 0; k < a.samples.size(); ++k) QVERIFY(b.samples[k].seconds == a.samples[k].seconds);
      QCOMPARE(b.provenance.note, a.provenance.note);
    }
    QVERIFY(second.warnings.empty());  // the writer's flops_mean agrees with the timings
  }
  void stated_flops_mismatch_is_a_warning() {
    const auto batch = bs::parse_run_json(
        R"({"format":"benchscope-run","version":1,"runs":[{"platform":"p","device":"d","backend":"b",
        "params":{"iterations":10,"dims":1},"samples":[{"workers":1,"seconds":[1.0],"flops_mean":999}]}]})", "m.json");
    QCOMPARE(batch.warnings.size(), std::size_t{1});
    QVERIFY(batch.warnings[0].find("/runs/0/samples/0/flops_mean") != std::string::npos);
  }
  void every_written_key_is_in_the_schema() {
    std::ifstream f(BENCHSCOPE_SOURCE_DIR "/resources/schema/benchscope-run-v1.schema.json");
    QVERIFY(f.good());
    const auto schema = nlohmann::json::parse(f);
    std::set<std::string> schema_keys;
    collect_keys(schema, schema_keys);
    const bs::CancelToken cancel;
    const auto batch = bs::RunJsonImporter().parse(kData + "run-json/two-runs.json", {}, cancel);
    std::set<std::string> written;
    collect_keys(nlohmann::json::parse(bs::write_run_json(batch.runs)), written);
    for (const std::string& k : written) QVERIFY2(schema_keys.count(k), k.c_str());
  }
  void save_is_atomic_and_readable() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("out.json").toStdString();
    const bs::CancelToken cancel;
    const auto batch = bs::RunJsonImporter().parse(kData + "run-json/two-runs.json", {}, cancel);
    bs::save_run_json(path, batch.runs);
    QVERIFY(!QFile::exists(QString::fromStdString(path + ".tmp")));
    QCOMPARE(bs::RunJsonImporter().parse(path, {}, cancel).runs.size(), std::size_t{2});
  }
  void too_deep_is_rejected_before_building() {
    std::string deep(10000, '[');
    deep += std::string(10000, ']');
    try {
      bs::parse_run_json(deep, "deep.json");
      QFAIL("accepted");
    } catch (const bs::ImportError& e) {
      QCOMPARE(e.category(), bs::ImportErrorCategory::TooDeep);
      QVERIFY(std::string(e.what()).starts_with("deep.json"));
    }
  }
  void too_many_samples_is_rejected() {
    bs::ImportLimits limits;
    limits.max_samples = 3;
    try {
      bs::parse_run_json(R"({"format":"benchscope-run","version":1,"runs":[{"platform":"p","device":"d","backend":"b",
        "params":{"iterations":10,"dims":1},"samples":[{"workers":1,"seconds":[1,1,1,1]}]}]})", "big.json", limits);
      QFAIL("accepted");
    } catch (const bs::ImportError& e) {
      QCOMPARE(e.category(), bs::ImportErrorCategory::TooLarge);
    }
  }
};

QTEST_GUILESS_MAIN(TestRunJson)
#include "test_run_json.moc"
