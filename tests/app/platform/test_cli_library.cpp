// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli library` without the library's kept sources (third-party files, never installed, issue #41):
// list and show work from library.json alone, show gives the URL and each value's line, and says where a kept copy
// would be ($BENCHSCOPE_PUBLIC_DATA_DIR/resources/library/...) and whether it is there. With the shared folder of
// third-party files present (the configured BENCHSCOPE_PUBLIC_DATA_DIR), show finds the copy.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include "../../support/cli_harness.h"
#include "../../support/public_data.h"

namespace {

// Orin MaxQ ResNet-50 SingleStream: its summary's line 7 holds the 90th percentile latency (test_library).
const QString kId = "mlperf-v3.0-orin_trt_maxq-resnet50-singlestream";
const QString kKept =
    "resources/library/sources/mlcommons+inference_results_v3.0/closed/NVIDIA/results/Orin_TRT_MaxQ/resnet50/"
    "SingleStream/performance/run_1/mlperf_log_summary.txt";

// benchscope-cli ARGS with BENCHSCOPE_PUBLIC_DATA_DIR set to `public_data`.
bs::test::CliResult cli_with(const QString& public_data, const QStringList& args) {
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert("BENCHSCOPE_PUBLIC_DATA_DIR", public_data);
  return bs::test::cli(args, env);
}

}  // namespace

class TestCliLibrary : public QObject {
  Q_OBJECT
 private slots:
  void list_and_show_work_without_the_kept_sources() {
    QTemporaryDir empty;  // a shared folder without any third-party file
    const auto list = cli_with(empty.path(), {"library", "list"});
    QCOMPARE(list.code, 0);
    QVERIFY2(list.out.contains(kId.toUtf8()) && list.out.contains("published results for"), list.out);

    const auto show = cli_with(empty.path(), {"library", "show", kId});
    QCOMPARE(show.code, 0);
    const QString out = QString::fromUtf8(show.out);
    QVERIFY2(out.contains("source:      https://github.com/mlcommons/inference_results_v3.0"), show.out);
    QVERIFY2(out.contains(QRegularExpression("line 7: +90th percentile latency \\(ns\\)")), show.out);
    QVERIFY2(out.contains("kept copy:   " + empty.path() + "/" + kKept + "  (not here:"), show.out);
    QVERIFY2(out.contains("BENCHSCOPE_PUBLIC_DATA_DIR"), show.out);

    const auto json = cli_with(empty.path(), {"library", "show", kId, "--json"});
    QCOMPARE(json.code, 0);
    const QJsonObject source = QJsonDocument::fromJson(json.out).object()["source"].toObject();
    QCOMPARE(source["kept_copy"].toString(), empty.path() + "/" + kKept);
    QCOMPARE(source["kept_copy_present"].toBool(), false);
  }

  // #46: the chosen computers' ROS 2 graph benchmarks, in the terminal and as JSON, each saying what its value is.
  void compare_gives_graph_benchmarks_with_what_each_value_is() {
    QTemporaryDir empty;
    const auto text = cli_with(empty.path(), {"library", "compare", "orin"});
    QCOMPARE(text.code, 0);
    QVERIFY2(text.out.contains("ROS 2 graph benchmarks: compared within one tool, node, input, release and measure"),
             text.out);
    QVERIFY2(text.out.contains("the latency of the FIRST message only"), text.out);
    const auto json = cli_with(empty.path(), {"library", "compare", "orin", "--json"});
    QCOMPARE(json.code, 0);
    const QJsonArray classes = QJsonDocument::fromJson(json.out).object()["graph_benchmarks"].toArray();
    QVERIFY(classes.size() >= 10);
    bool jitter_is_a_maximum = false;
    for (const auto& c : classes)
      for (const auto& row : c.toObject()["rows"].toArray()) {
        const QJsonObject r = row.toObject();
        QVERIFY(r["source"].toString().startsWith("https://github.com/"));
        QVERIFY(!r["what_the_value_is"].toString().isEmpty());
        if (r["id"].toString() == "ros2bench-jetson-agx-orin-rectifynode-jitter-peak")
          jitter_is_a_maximum = r["what_the_value_is"].toString().contains("a maximum") && r["unit"] == "s";
      }
    QVERIFY(jitter_is_a_maximum);
    // A computer with no graph benchmarks gives none, not an empty heading.
    const auto pi5 = cli_with(empty.path(), {"library", "compare", "pi5"});
    QCOMPARE(pi5.code, 0);
    QVERIFY(!pi5.out.contains("ROS 2 graph benchmarks"));
  }

  void show_finds_the_kept_copy_in_the_shared_folder() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA("resources/library/sources");
    const QString dir = QString::fromUtf8(bs::test::kPublicDataDir);
    const auto show = cli_with(dir, {"library", "show", kId});
    QCOMPARE(show.code, 0);
    QVERIFY2(show.out.contains(("kept copy:   " + dir + "/" + kKept + "\n").toUtf8()), show.out);
    const auto json = cli_with(dir, {"library", "show", kId, "--json"});
    QCOMPARE(QJsonDocument::fromJson(json.out).object()["source"].toObject()["kept_copy_present"].toBool(), true);
  }
};

QTEST_GUILESS_MAIN(TestCliLibrary)
#include "test_cli_library.moc"
