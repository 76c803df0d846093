// SPDX-License-Identifier: GPL-3.0-or-later
// Figure templates are data: the bundled paper template parses, selections pick the right runs, and a bad user
// template gives an error naming the file and the field.
#include <QTest>

#include "report/figure_template.h"

class TestFigureTemplate : public QObject {
  Q_OBJECT
 private slots:
  void paper_template() {
    const auto t = bs::load_figure_templates(BENCHSCOPE_SOURCE_DIR "/resources/figures/paper-2018.json");
    QCOMPARE(t.size(), std::size_t{8});  // the paper's figures, the inference figure and the headroom figure (#45)
    QCOMPARE(t[1].id, std::string("fig1b"));
    QCOMPARE(t[1].dims, (std::vector<int>{1, 2, 4}));
    QVERIFY(t[0].log_x);
    QCOMPARE(t[0].y_scale, 1e12);
    QCOMPARE(t[5].kind, std::string("current"));
    QVERIFY(!t[5].optional);
    // The inference-time figure: optional, as most workspaces have no bench dnn run.
    QCOMPARE(t[6].kind, std::string("inference"));
    QVERIFY(t[6].optional);
    QCOMPARE(t[6].y_scale, 1e-3);
  }

  void selection() {
    const auto t = bs::parse_figure_templates(
        R"({"format":"benchscope-figures","version":1,"figures":[
             {"id":"a","kind":"flops","device_kind":"gpu","platforms":["NUC"],"dims":[4]}]})",
        "t.json")[0];
    bs::FlopsRun run;
    run.platform = "NUC";
    run.device_kind = bs::DeviceKind::Gpu;
    run.dims = 4;
    QVERIFY(t.selects(run));
    run.dims = 2;
    QVERIFY(!t.selects(run));
    run.dims = 4;
    run.device_kind = bs::DeviceKind::Cpu;
    QVERIFY(!t.selects(run));
    run.device_kind = bs::DeviceKind::Gpu;
    run.platform = "Jetson TX2";
    QVERIFY(!t.selects(run));
  }

  void bad_templates_name_the_field() {
    const auto error_of = [](const char* json) {
      try {
        bs::parse_figure_templates(json, "t.json");
      } catch (const std::runtime_error& e) {
        return QString(e.what());
      }
      return QString();
    };
    QVERIFY(error_of("{").contains("t.json"));
    QVERIFY(error_of(R"({"format":"x","version":1,"figures":[]})").contains("/format"));
    QVERIFY(error_of(R"({"format":"benchscope-figures","version":2,"figures":[]})").contains("/version"));
    QVERIFY(error_of(R"({"format":"benchscope-figures","version":1,"figures":[{"id":"a","kind":"pie"}]})")
                .contains("/figures/0/kind"));
    QVERIFY(error_of(R"({"format":"benchscope-figures","version":1,"figures":[{"id":"../x","kind":"flops"}]})")
                .contains("/figures/0/id"));
    QVERIFY(
        error_of(R"({"format":"benchscope-figures","version":1,"figures":[{"kind":"flops"}]})").contains("/figures/0"));
    QVERIFY(error_of(R"({"format":"benchscope-figures","version":1,"figures":[{"id":"a","kind":"flops","y_scale":0}]})")
                .contains("y_scale"));
    QVERIFY(!bs::preset_width_mm("a4"));
    QCOMPARE(*bs::preset_width_mm("ieee"), 88.9);
  }
};

QTEST_MAIN(TestFigureTemplate)
#include "test_figure_template.moc"
