// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli lens circle / refine-lines / show on a synthetic room capture with known truth (issue #20).
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>

#include "../../support/cli_harness.h"

using bs::test::bytes_of;
using bs::test::cli;

namespace {

// The true lens: Kannala-Brandt, centre (652.3, 498.7), 195 degrees, rim radius 592.23 px (r_pp 0.0031).
const char* kTruth = R"({"format":"benchscope-lens","version":1,"lens":{"model":"kannala-brandt","r_pp":0.0031,
"k":[0.06,-0.02,0.003,0],"cx":652.3,"cy":498.7,"fov_deg":195,"width":1280,"height":1024},"view":{"width":1280,
"height":1024,"fov_deg":150,"yaw_deg":0,"pitch_deg":0,"roll_deg":0}})";

// The true lens written into `dir` and the room rendered through it (16 bit, vignetting, noise) as dir/room*.
bs::test::CliResult render_room(const QTemporaryDir& dir) {
  const QString truth = dir.filePath("truth.json");
  QFile f(truth);
  if (!f.open(QIODevice::WriteOnly)) return {1, {}, "cannot write " + truth.toUtf8()};
  f.write(kTruth);
  f.close();
  return cli({"synth-frame", "--scene", "room", "--lens", truth, "--seed", "5", "--vignetting", "0.4", "--noise",
              "0.01", "--bits", "16", "--out", dir.filePath("room")});
}

QJsonObject lens_of(const QString& path) { return QJsonDocument::fromJson(bytes_of(path)).object()["lens"].toObject(); }

}  // namespace

class TestCliLens : public QObject {
  Q_OBJECT
 private slots:
  void circle_then_lines_recover_the_true_lens() {
    QTemporaryDir dir;
    auto r = render_room(dir);
    QVERIFY2(r.code == 0, r.err.constData());
    const QString prefix = dir.filePath("room");
    QVERIFY(r.out.contains("-lines.json"));
    const QString circle = dir.filePath("circle.json");
    r = cli({"lens", "circle", prefix + "-truth.png", "--out", circle});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY2(r.out.contains("calibration: circle-fit, RMS"), r.out.constData());
    QJsonObject l = lens_of(circle);
    qInfo("circle fit: centre (%.3f, %.3f)", l["cx"].toDouble(), l["cy"].toDouble());
    QVERIFY(std::hypot(l["cx"].toDouble() - 652.3, l["cy"].toDouble() - 498.7) < 0.5);
    QCOMPARE(l["calibration"].toObject()["method"].toString(), QString("circle-fit"));
    // The grid lines' true points: the refined lens is the truth (exact clicks pin all 7 parameters).
    const QString refined = dir.filePath("refined.json");
    r = cli({"lens", "refine-lines", circle, prefix + "-lines.json", "--out", refined});
    QVERIFY2(r.code == 0, r.err.constData());
    qInfo("%s", r.out.constData());
    l = lens_of(refined);
    QCOMPARE(l["model"].toString(), QString("kannala-brandt"));
    QVERIFY(std::hypot(l["cx"].toDouble() - 652.3, l["cy"].toDouble() - 498.7) < 0.1);
    QVERIFY(std::abs(l["r_pp"].toDouble() - 0.0031) / 0.0031 < 0.002);
    QVERIFY(std::abs(l["k"].toArray()[0].toDouble() - 0.06) < 0.002);
    const QJsonObject cal = l["calibration"].toObject();
    QCOMPARE(cal["method"].toString(), QString("line-fit"));
    QVERIFY(cal["detail"].toString().contains("before"));
    r = cli({"lens", "show", refined});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains("calibration: line-fit, RMS"), r.out.constData());
    // --fix keeps a parameter; a bad name is a usage error.
    r = cli({"lens", "refine-lines", circle, prefix + "-lines.json", "--fix", "r_pp", "--out", refined});
    QCOMPARE(r.code, 0);
    QCOMPARE(lens_of(refined)["r_pp"].toDouble(), lens_of(circle)["r_pp"].toDouble());
    QCOMPARE(cli({"lens", "refine-lines", circle, prefix + "-lines.json", "--fix", "focal"}).code, 2);
  }
  void proposed_lines_refine_the_circle_fit() {
    // lens propose-lines on the same capture, then refine-lines --propose from the circle fit's lens. Measured:
    // 80 lines; the fit leaves 6 out and lands 0.07 px from the true centre with r_pp 0.08 % off.
    QTemporaryDir dir;
    auto r = render_room(dir);
    QVERIFY2(r.code == 0, r.err.constData());
    const QString prefix = dir.filePath("room");
    const QString image = prefix + "-truth.png", circle = dir.filePath("circle.json");
    QCOMPARE(cli({"lens", "circle", image, "--out", circle}).code, 0);
    r = cli({"lens", "propose-lines", image, "--lens", circle});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY2(r.out.startsWith("80 proposed lines from"), r.out.constData());
    QVERIFY(r.out.contains("line 80: "));
    const QString lines = dir.filePath("lines.json");
    r = cli({"lens", "propose-lines", image, "--lens", circle, "--json", "--out", lines, "--max-lines", "30"});
    QVERIFY2(r.code == 0, r.err.constData());
    const QJsonObject j = QJsonDocument::fromJson(r.out).object();
    QCOMPARE(j["format"].toString(), QString("benchscope-lines"));
    QCOMPARE(j["lines"].toArray().size(), 30);
    QCOMPARE(j["proposals"].toArray().size(), 30);
    QVERIFY(j["proposals"].toArray()[0].toObject()["length_px"].toDouble() >= 80);
    QCOMPARE(QJsonDocument::fromJson(bytes_of(lines)).object()["lines"].toArray().size(), 30);
    // The lines file feeds refine-lines as clicked lines do; --propose does both in one go.
    QCOMPARE(cli({"lens", "refine-lines", circle, lines}).code, 0);
    const QString refined = dir.filePath("refined.json");
    r = cli({"lens", "refine-lines", circle, "--propose", image, "--out", refined});
    QVERIFY2(r.code == 0, r.err.constData());
    qInfo("%s", r.out.constData());
    QVERIFY(r.out.contains("proposed 80 lines") && r.out.contains("left out"));
    const QJsonObject l = lens_of(refined);
    const double centre_err = std::hypot(l["cx"].toDouble() - 652.3, l["cy"].toDouble() - 498.7);
    const double r_pp_err = std::abs(l["r_pp"].toDouble() - 0.0031) / 0.0031;
    qInfo("refine-lines --propose: centre error %.3f px, r_pp error %.3f %%", centre_err, 100 * r_pp_err);
    QVERIFY(centre_err < 0.5);
    QVERIFY(r_pp_err < 0.005);
    // Usage errors: no --lens; proposal options without --propose; a bad --reject-lines.
    QCOMPARE(cli({"lens", "propose-lines", image}).code, 2);
    QCOMPARE(cli({"lens", "refine-lines", circle, lines, "--max-bend", "3"}).code, 2);
    QCOMPARE(cli({"lens", "refine-lines", circle, "--propose", image, "--reject-lines", "-1"}).code, 2);
  }
  void bad_lines_files_name_the_file_and_field() {
    QTemporaryDir dir;
    const QString lines = dir.filePath("lines.json");
    QFile f(lines);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({"format": "benchscope-lines", "version": 1, "lines": [[[1, 2], [3, "x"]]]})");
    f.close();
    const QString lens = dir.filePath("lens.json");
    QFile lf(lens);
    QVERIFY(lf.open(QIODevice::WriteOnly));
    lf.write(kTruth);
    lf.close();
    auto r = cli({"lens", "refine-lines", lens, lines});
    QVERIFY(r.code != 0);
    QVERIFY2(r.err.contains("lines.json") && r.err.contains("/lines/0/1"), r.err.constData());
    // Too few lines: says so.
    f.open(QIODevice::WriteOnly | QIODevice::Truncate);
    f.write(R"({"format": "benchscope-lines", "version": 1, "lines": [[[1, 2], [3, 4], [5, 7]]]})");
    f.close();
    r = cli({"lens", "refine-lines", lens, lines});
    QVERIFY(r.code != 0);
    QVERIFY2(r.err.contains("at least 3 lines"), r.err.constData());
  }

  void circle_on_a_raw_capture_with_its_sidecar() {
    // Issue #32.8: a .raw capture with its sidecar is read (it was "cannot read the image"); issue #32.6: the
    // proposal is compared with the lens recorded with it, and a 12 % difference is reported with both values.
    const QString capture = BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018/frames/paper-capture.raw";
    auto r = cli({"lens", "circle", capture});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY2(r.out.contains("image circle: centre"), r.out.constData());
    QVERIFY2(r.out.contains("warning: the proposed r_pp") && r.out.contains("0.0026589"), r.out.constData());
    // Told the angle the lit disc spans, it agrees with the recorded lens: no warning.
    r = cli({"lens", "circle", capture, "--circle-fov", "174"});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY2(!r.out.contains("warning"), r.out.constData());
  }

  void frames_names_the_lens_it_used() {
    // Issue #32.8: `frames --lens FILE` said "(paper default)"; it names the file now, and without --lens the
    // recorded lens.
    QTemporaryDir dir;
    const QString ws = dir.filePath("f.bsw");
    auto r = cli({"import", ws, BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018/frames"});
    QVERIFY2(r.code == 0, r.err.constData());
    QFile lens(dir.filePath("lens.json"));
    QVERIFY(lens.open(QIODevice::WriteOnly));
    lens.write(QByteArray(kTruth));
    lens.close();
    r = cli({"frames", ws, "--triptych", "1", "--out", dir.filePath("t"), "--lens", lens.fileName()});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY2(r.out.contains("(from " + lens.fileName().toUtf8() + ")"), r.out.constData());
    QVERIFY(!r.out.contains("paper default"));
    r = cli({"frames", ws, "--triptych", "1", "--out", dir.filePath("u")});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY2(r.out.contains("(recorded with the capture)"), r.out.constData());
  }
};

QTEST_GUILESS_MAIN(TestCliLens)
#include "test_cli_lens.moc"
