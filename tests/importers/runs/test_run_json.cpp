// SPDX-License-Identifier: GPL-3.0-or-later
// Run JSON v1: reading the fixture, exact write -> read round trips, located errors, limits, the schema and doc.
#include <QDir>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "common/json_access.h"
#include "runs/run_json.h"

#include "../../support/import_errors.h"
#include "../../support/importer_parse.h"

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

// Every property name the schema declares (keys of any "properties" object), not every word in it.
void collect_declared(const nlohmann::json& j, std::set<std::string>& names) {
  if (j.is_object()) {
    for (const auto& [k, v] : j.items()) {
      if (k == "properties" && v.is_object())
        for (const auto& [name, sub] : v.items()) names.insert(name);
      collect_declared(v, names);
    }
  }
  if (j.is_array())
    for (const auto& v : j) collect_declared(v, names);
}

std::string read_text(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

bs::ImportBatch load_fixture() {
  return bs::test::parse_with(bs::kRunJsonFileFormat, kData + "run-json/two-runs.json");
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expect_same_runs(const std::vector<bs::FlopsRun>& a, const std::vector<bs::FlopsRun>& b) {
  QCOMPARE(b.size(), a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const bs::FlopsRun& x = a[i];
    const bs::FlopsRun& y = b[i];
    QCOMPARE(y.platform, x.platform);
    QCOMPARE(y.device, x.device);
    QCOMPARE(y.device_kind, x.device_kind);
    QCOMPARE(y.backend, x.backend);
    QCOMPARE(y.kernel, x.kernel);
    QCOMPARE(y.variant, x.variant);
    QCOMPARE(y.iterations, x.iterations);
    QCOMPARE(y.dims, x.dims);
    QCOMPARE(y.reported_peak_flops.has_value(), x.reported_peak_flops.has_value());
    if (x.reported_peak_flops) QVERIFY(same_bits(*y.reported_peak_flops, *x.reported_peak_flops));
    QCOMPARE(y.theoretical_peak_flops.has_value(), x.theoretical_peak_flops.has_value());
    if (x.theoretical_peak_flops) QVERIFY(same_bits(*y.theoretical_peak_flops, *x.theoretical_peak_flops));
    QCOMPARE(y.samples.size(), x.samples.size());
    for (std::size_t k = 0; k < x.samples.size(); ++k) {
      QCOMPARE(y.samples[k].workers, x.samples[k].workers);
      QCOMPARE(y.samples[k].seconds.size(), x.samples[k].seconds.size());
      for (std::size_t r = 0; r < x.samples[k].seconds.size(); ++r)
        QVERIFY2(same_bits(y.samples[k].seconds[r], x.samples[k].seconds[r]), "a time changed in the round trip");
    }
    const bs::Provenance& p = x.provenance;
    const bs::Provenance& q = y.provenance;
    QCOMPARE(q.origin, p.origin);
    QCOMPARE(q.host, p.host);
    QCOMPARE(q.cpu_model, p.cpu_model);
    QCOMPARE(q.gpu_model, p.gpu_model);
    QCOMPARE(q.os, p.os);
    QCOMPARE(q.compiler, p.compiler);
    QCOMPARE(q.tool, p.tool);
    QCOMPARE(q.git_revision, p.git_revision);
    QCOMPARE(q.date, p.date);
    QCOMPARE(q.note, p.note);
  }
}

bs::FlopsRun awkward_run() {
  bs::FlopsRun run;
  run.platform = "Jetson TX2 \xE2\x80\x94 \"lab\" \\ unit";  // em dash, quotes, backslash
  run.device = "Pascal GPU";
  run.device_kind = bs::DeviceKind::Gpu;
  run.backend = "CUDA";
  run.variant = "float16x4";
  run.iterations = 40000;
  run.dims = 4;
  run.reported_peak_flops = 0.1;
  run.theoretical_peak_flops = 1.7976931348623157e308;
  run.samples = {{1, {1.0 / 3.0, 0.1, 5e-324}},
                 {256, {123456789.123456789, 2.2250738585072014e-308}},
                 {std::int64_t{1} << 40, {std::nextafter(1.0, 2.0)}}};
  run.provenance.origin = bs::DataOrigin::Measured;
  run.provenance.host = "tx2";
  run.provenance.note = "line one\nline two";
  return run;
}

bs::ImportError error_of(const std::string& text, const std::string& file = "e.json") {
  return bs::test::import_error_of([&] { return bs::parse_run_json(text, file); });
}

const char* const kLocated = R"({
  "format": "benchscope-run",
  "version": 1,
  "runs": [
    {"platform": "p", "device": "d", "backend": "b", "params": {"iterations": 10, "dims": 1},
     "samples": [
       {"workers": 1, "seconds": [0.5]},
       {"workers": 2, "seconds": [0.25, -1]}
     ]}
  ]
})";
}  // namespace

class TestRunJson : public QObject {
  Q_OBJECT
 private slots:
  void parses_fixture() {
    const auto batch = load_fixture();
    QCOMPARE(batch.format, std::string("benchscope-run-v1"));
    QCOMPARE(batch.runs.size(), std::size_t{2});
    const bs::FlopsRun& cpu = batch.runs[0];
    QCOMPARE(cpu.device_kind, bs::DeviceKind::Cpu);
    QCOMPARE(cpu.dims, 4);
    QCOMPARE(cpu.iterations, std::int64_t{1000});
    QCOMPARE(cpu.samples.size(), std::size_t{2});
    QCOMPARE(cpu.samples[0].seconds.size(), std::size_t{3});
    QCOMPARE(cpu.samples[0].seconds[1], 0.0011);
    QCOMPARE(*cpu.theoretical_peak_flops, 1.0e11);
    QVERIFY(!cpu.reported_peak_flops);
    QCOMPARE(cpu.provenance.origin, bs::DataOrigin::Measured);  // file-level default
    QCOMPARE(cpu.provenance.host, std::string("lab-pc"));
    QCOMPARE(cpu.provenance.source_file, kData + "run-json/two-runs.json");
    const bs::FlopsRun& gpu = batch.runs[1];
    QCOMPARE(gpu.variant, std::string("float16x4"));
    QCOMPARE(gpu.kernel, std::string("rotation2d"));                 // default
    QCOMPARE(gpu.provenance.origin, bs::DataOrigin::Reconstructed);  // run-level override
    QCOMPARE(gpu.provenance.host, std::string("lab-pc"));            // inherited field by field
    QCOMPARE(gpu.provenance.note, std::string("from a table"));
    QVERIFY2(batch.warnings.empty(), batch.warnings.empty() ? "" : batch.warnings[0].c_str());
  }

  void round_trip_is_identical() {
    const auto first = load_fixture();
    const std::string text = bs::write_run_json(first.runs);
    const auto second = bs::parse_run_json(text, "memory");
    expect_same_runs(first.runs, second.runs);
    QVERIFY(second.warnings.empty());                 // the writer's flops_mean agrees with the timings
    QCOMPARE(bs::write_run_json(second.runs), text);  // stable text: same runs, same bytes
  }

  void awkward_values_round_trip_bit_exact() {
    const std::vector<bs::FlopsRun> runs = {awkward_run()};
    const auto back = bs::parse_run_json(bs::write_run_json(runs), "memory");
    expect_same_runs(runs, back.runs);
    QVERIFY(back.warnings.empty());
  }

  void file_default_provenance_is_factored_out() {
    auto runs = load_fixture().runs;
    bs::Provenance common = runs[0].provenance;
    common.source_file.clear();
    const std::string text = bs::write_run_json(runs, &common);
    const auto doc = nlohmann::json::parse(text);
    QCOMPARE(doc["provenance"]["host"].get<std::string>(), std::string("lab-pc"));
    QVERIFY(!doc["runs"][0].contains("provenance"));  // equal to the default: inherited
    QVERIFY(doc["runs"][1].contains("provenance"));   // differs: written in full
    expect_same_runs(runs, bs::parse_run_json(text, "memory").runs);
  }

  void keys_are_written_in_a_fixed_order() {
    const std::string text = bs::write_run_json(load_fixture().runs);
    auto before = [&](const char* a, const char* b) {
      const auto pa = text.find(a);
      const auto pb = text.find(b);
      return pa != std::string::npos && pb != std::string::npos && pa < pb;
    };
    QVERIFY(before("\"format\"", "\"version\""));
    QVERIFY(before("\"version\"", "\"generator\""));
    QVERIFY(before("\"generator\"", "\"runs\""));
    QVERIFY(before("\"platform\"", "\"device\""));
    QVERIFY(before("\"backend\"", "\"params\""));
    QVERIFY(before("\"iterations\"", "\"dims\""));
    QVERIFY(before("\"workers\"", "\"seconds\""));
    QVERIFY(before("\"seconds\"", "\"flops_mean\""));
    QVERIFY(text.find('\n') != std::string::npos);  // pretty
    // flops_mean = 6 * D * N * W / t averaged over repetitions: D=4, N=1000, W=8, t=0.002 -> 9.6e7 FLOP/s.
    QCOMPARE(nlohmann::json::parse(text)["runs"][0]["samples"][1]["flops_mean"].get<double>(), 9.6e7);
  }

  void writer_refuses_what_the_reader_would() {
    bs::FlopsRun run = awkward_run();
    run.samples[1].seconds[0] = 0;
    std::vector<bs::FlopsRun> runs = {run};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::write_run_json(runs));
    runs[0] = awkward_run();
    runs[0].samples[1].workers = 1;  // not ascending
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::write_run_json(runs));
    runs[0] = awkward_run();
    runs[0].reported_peak_flops = std::numeric_limits<double>::quiet_NaN();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::write_run_json(runs));
  }

  void every_written_key_is_in_the_schema() {
    const auto schema =
        nlohmann::json::parse(read_text(BENCHSCOPE_SOURCE_DIR "/resources/schema/benchscope-run-v1.schema.json"));
    QCOMPARE(schema["$schema"].get<std::string>(), std::string("https://json-schema.org/draft/2020-12/schema"));
    std::set<std::string> declared;
    collect_declared(schema, declared);
    auto runs = load_fixture().runs;
    runs.push_back(awkward_run());  // has both peaks
    bs::Provenance common;
    common.host = "lab-pc";
    std::set<std::string> written;
    collect_keys(nlohmann::json::parse(bs::write_run_json(runs, &common)), written);
    QVERIFY(written.count("flops_mean") && written.count("reported_peak_flops") && written.count("git_revision"));
    for (const std::string& k : written) QVERIFY2(declared.count(k), ("not in the schema: " + k).c_str());
    // and the schema's required lists are what the reader requires
    QVERIFY(schema["required"] == nlohmann::json({"format", "version", "runs"}));
    QVERIFY(schema["$defs"]["run"]["required"] ==
            nlohmann::json({"platform", "device", "backend", "params", "samples"}));
  }

  void documented_example_reads_cleanly() {
    const std::string doc = read_text(BENCHSCOPE_SOURCE_DIR "/docs/run-json-v1.md");
    const auto open = doc.find("```json\n");
    QVERIFY(open != std::string::npos);
    const auto close = doc.find("```", open + 8);
    const auto batch = bs::parse_run_json(doc.substr(open + 8, close - open - 8), "run-json-v1.md");
    QCOMPARE(batch.runs.size(), std::size_t{1});
    QVERIFY2(batch.warnings.empty(), batch.warnings.empty() ? "" : batch.warnings[0].c_str());
  }

  void semantic_errors_carry_pointer_and_line() {
    const bs::ImportError e = error_of(kLocated, "located.json");
    QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(e.location().field, std::string("/runs/0/samples/1/seconds/1"));
    QCOMPARE(e.location().line, std::size_t{8});
    QCOMPARE(e.location().column, std::size_t{41});  // the "-1"
    QVERIFY(std::string(e.what()).starts_with("located.json:8:41: /runs/0/samples/1/seconds/1: "));
  }

  void missing_field_points_at_its_object() {
    std::string text = kLocated;
    text.replace(text.find("\"dims\": 1"), 9, "\"dim\": 1 ");
    const bs::ImportError e = error_of(text);
    QCOMPARE(e.category(), bs::ImportErrorCategory::MissingField);
    QCOMPARE(e.location().field, std::string("/runs/0/params/dims"));
    QCOMPARE(e.location().line, std::size_t{5});
    QCOMPARE(e.location().column, std::size_t{64});  // the '{' of params
  }

  void syntax_errors_carry_line_and_column() {
    const bs::ImportError e = error_of("{\n  \"format\": \"benchscope-run\",\n  \"version\": 1,,\n}");
    QCOMPARE(e.category(), bs::ImportErrorCategory::Syntax);
    QCOMPARE(e.location().line, std::size_t{3});
    QCOMPARE(e.location().column, std::size_t{16});
    const bs::ImportError t = error_of("{\"format\": \"benchscope-run\", \"runs\": [");
    QCOMPARE(t.category(), bs::ImportErrorCategory::Syntax);
    QVERIFY(std::string(t.what()).find("unexpected end of file") != std::string::npos);
  }

  void non_finite_numbers_are_refused() {
    const bs::ImportError nan = error_of("{\"format\": \"benchscope-run\",\n \"x\": NaN}");
    QCOMPARE(nan.category(), bs::ImportErrorCategory::Syntax);
    QCOMPARE(nan.location().line, std::size_t{2});
    const bs::ImportError inf = error_of("{\"format\": \"benchscope-run\",\n \"x\": -Infinity}");
    QCOMPARE(inf.category(), bs::ImportErrorCategory::Syntax);
    const bs::ImportError big = error_of("{\"format\": \"benchscope-run\",\n  \"x\": [1e5, -1e999]}");
    QCOMPARE(big.category(), bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(big.location().line, std::size_t{2});
    QCOMPARE(big.location().column, std::size_t{14});
    QVERIFY(std::string(big.what()).find("-1e999") != std::string::npos);
  }

  void stated_flops_mismatch_is_a_warning() {
    const auto batch = bs::parse_run_json(
        R"({"format":"benchscope-run","version":1,"runs":[{"platform":"p","device":"d","backend":"b",
        "params":{"iterations":10,"dims":1},"samples":[{"workers":1,"seconds":[1.0],"flops_mean":999}]}]})",
        "m.json");
    QCOMPARE(batch.runs.size(), std::size_t{1});
    QCOMPARE(batch.warnings.size(), std::size_t{1});
    QVERIFY(batch.warnings[0].starts_with("m.json:2:"));
    QVERIFY(batch.warnings[0].find("/runs/0/samples/0/flops_mean") != std::string::npos);
  }

  void wrong_enums_and_types_are_refused() {
    const std::string base = R"({"format":"benchscope-run","version":1,"runs":[{"platform":"p","device":"d",
      "backend":"b","device_kind":KIND,"params":{"iterations":ITER,"dims":1},"samples":[{"workers":1,"seconds":[1]}]}]})";
    auto with = [&](const std::string& kind, const std::string& iter) {
      std::string t = base;
      t.replace(t.find("KIND"), 4, kind);
      t.replace(t.find("ITER"), 4, iter);
      return error_of(t);
    };
    QCOMPARE(with("\"fpga\"", "10").category(), bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(with("3", "10").category(), bs::ImportErrorCategory::WrongType);
    QCOMPARE(with("\"gpu\"", "2.5").category(), bs::ImportErrorCategory::WrongType);
    QCOMPARE(with("\"gpu\"", "0").category(), bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(with("\"gpu\"", "\"10\"").location().field, std::string("/runs/0/params/iterations"));
    QCOMPARE(error_of(R"({"format":"benchscope-run","version":1,"runs":[]})").category(),
             bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(error_of(R"({"format":"other","version":1,"runs":[]})").location().field, std::string("/format"));
    QCOMPARE(error_of(R"([1, 2])").category(), bs::ImportErrorCategory::WrongType);
  }

  void save_is_atomic_and_readable() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("out.json").toStdString();
    const auto batch = load_fixture();
    bs::save_run_json(path, batch.runs);
    bs::save_run_json(path, batch.runs);                                         // replaces an existing file
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{"out.json"});  // no temporary left behind
    expect_same_runs(batch.runs, bs::test::parse_with(bs::kRunJsonFileFormat, path).runs);
    QVERIFY_THROWS_EXCEPTION(std::runtime_error,
                             bs::save_run_json(dir.filePath("no-such-dir/out.json").toStdString(), batch.runs));
  }

  void too_deep_is_rejected_before_building() {
    // Brace balance kept per string literal: moc reads this file too.
    std::string deep = std::string(1, '{') + "\"format\": \"benchscope-run\", \"version\": 1, \"runs\": ";
    deep += std::string(10000, '[') + std::string(10000, ']') + std::string(1, '}');
    try {
      bs::parse_run_json(deep, "deep.json");
      QFAIL("accepted");
    } catch (const bs::ImportError& e) {
      QCOMPARE(e.category(), bs::ImportErrorCategory::TooDeep);
      QVERIFY(std::string(e.what()).starts_with("deep.json:1:"));
      QVERIFY(std::string(e.what()).find("64") != std::string::npos);
    }
  }

  void too_many_samples_or_values_are_rejected() {
    bs::ImportLimits limits;
    limits.max_samples = 3;
    const char* const text =
        R"({"format":"benchscope-run","version":1,"runs":[{"platform":"p","device":"d","backend":"b",
        "params":{"iterations":10,"dims":1},"samples":[{"workers":1,"seconds":[1,1,1,1]}]}]})";
    try {
      bs::parse_run_json(text, "big.json", {}, limits);
      QFAIL("accepted");
    } catch (const bs::ImportError& e) {
      QCOMPARE(e.category(), bs::ImportErrorCategory::TooLarge);
    }
    bs::ImportLimits values;
    values.max_json_values = 10;
    try {
      bs::parse_run_json(text, "big.json", {}, values);
      QFAIL("accepted");
    } catch (const bs::ImportError& e) {
      QCOMPARE(e.category(), bs::ImportErrorCategory::TooLarge);
    }
  }

  void cancelling_stops_the_import() {
    bs::CancelToken cancel;
    cancel.cancel();
    QVERIFY_THROWS_EXCEPTION(bs::Cancelled,
                             bs::kRunJsonFileFormat.parse(kData + "run-json/two-runs.json", {}, {}, cancel));
  }

  void pointers_map_to_offsets() {
    const std::string text = "{\"a\": {\"b~c\": [10, {\"d/e\": 7}]}, \"f\": \"}\"}";
    QCOMPARE(bs::json_access::offset_of_pointer(text, "/a/b~0c/1/d~1e"), text.find('7'));
    QCOMPARE(bs::json_access::offset_of_pointer(text, "/f"), text.find("\"}\""));
    QCOMPARE(bs::json_access::offset_of_pointer(text, "/a/missing"), text.find("{\"b"));
    QCOMPARE(bs::json_access::offset_of_pointer(text, "/a/b~0c/5"), text.find('['));
    QCOMPARE(bs::json_access::child("/x", "a/b~c"), std::string("/x/a~1b~0c"));
  }

  // nlohmann keeps the last of two equal keys without a word; every JSON importer refuses them instead.
  void duplicate_keys_are_refused_at_their_second_occurrence() {
    const auto error_of = [](const std::string& text) -> std::optional<bs::ImportError> {
      try {
        (void)bs::json_access::parse(text, "d.json", {});
      } catch (const bs::ImportError& e) {
        return e;
      }
      return std::nullopt;
    };
    // Line 3 holds the second "dims"; the field names the object's pointer.
    auto e = error_of("{\"runs\": [{\"x\": 1},\n {\"params\": {\"dims\": 4,\n  \"dims\": 2}}]}");
    QVERIFY(e);
    QCOMPARE(e->category(), bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(e->location().field, std::string("/runs/1/params/dims"));
    QCOMPARE(e->location().line, std::size_t{3});
    QCOMPARE(e->location().column, std::size_t{3});
    QVERIFY(e->reason().find("\"dims\" appears twice") != std::string::npos);
    // An object or array twice cannot be compared cheaply and is refused too; at the top level the pointer is "".
    e = error_of("{\"a\": [1], \"b\": 2, \"a\": [1]}");
    QVERIFY(e && e->location().field == "/a" && e->reason().find("object or array") != std::string::npos);
    // The same scalar twice loses nothing and is accepted; keys of different objects never clash.
    QVERIFY(!error_of("{\"a\": 1.5, \"a\": 1.5, \"b\": {\"a\": 2}, \"c\": [{\"a\": 3}, {\"a\": 4}]}"));
    QVERIFY(error_of("{\"a\": \"x\", \"a\": \"y\"}"));
    QVERIFY(error_of("{\"a\": 1, \"a\": 1.0}"));  // integer and float are different JSON values here
  }
};

QTEST_GUILESS_MAIN(TestRunJson)
#include "test_run_json.moc"
