// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli synth-frame --scene checkerboard` then `benchscope-cli lens calibrate` on its views, as a user
// would: the per-image table with a rejected file named, the lens file with its calibration record, the known
// lens recovered, and usage errors.
#include <QFile>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>

#include <nlohmann/json.hpp>

#include "../../support/cli_harness.h"

using bs::test::cli;

class TestCliLensCalibrate : public QObject {
  Q_OBJECT
 private slots:
  void synthetic_views_give_the_lens_back() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    // The paper's 195 degree equidistant lens at half size (640x512), seven poses from a file.
    QFile poses(dir.filePath("poses.txt"));
    QVERIFY(poses.open(QIODevice::WriteOnly));
    poses.write(
        "# rx,ry,rz,tx,ty,tz\n0,0,0,250,0,0\n0,0,45,220,220,0\n0,0,-45,220,-220,0\n0,-40,0,230,0,200\n"
        "0,40,0,230,0,-200\n20,-30,35,230,150,130\n-20,30,-35,230,-150,-130\n");
    poses.close();
    auto r = cli({"synth-frame", "--scene", "checkerboard", "--size", "640x512", "--poses", poses.fileName(), "--board",
                  "10x7", "--square", "30", "--supersample", "2", "--noise", "1", "--out", dir.filePath("cb/view")});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY(r.out.contains("view-07.png (640x512, 8-bit grey)"));
    QFile truth_file(dir.filePath("cb/view.json"));
    QVERIFY(truth_file.open(QIODevice::ReadOnly));
    const auto truth = nlohmann::json::parse(truth_file.readAll().toStdString());
    QCOMPARE(truth["images"].size(), 7u);
    const double truth_rpp = truth["lens"]["lens"]["r_pp"].get<double>();

    QStringList args{"lens", "calibrate"};
    for (int i = 1; i <= 7; ++i) args << dir.filePath(QString("cb/view-0%1.png").arg(i));
    args << dir.filePath("cb/missing.png") << "--board"
         << "10x7"
         << "--square"
         << "30"
         << "--model"
         << "equidistant"
         << "--out" << dir.filePath("lens.json");
    r = cli(args);
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY2(r.out.contains("missing.png  rejected: no such file"), r.out.constData());
    QVERIFY(r.out.contains("equidistant lens from 7 of 8 images: RMS "));
    QVERIFY(r.err.contains("[8/8] corners:"));
    QFile lens_file(dir.filePath("lens.json"));
    QVERIFY(lens_file.open(QIODevice::ReadOnly));
    const auto lens = nlohmann::json::parse(lens_file.readAll().toStdString())["lens"];
    QCOMPARE(lens["model"].get<std::string>(), std::string("equidistant"));
    QVERIFY(std::abs(lens["r_pp"].get<double>() / truth_rpp - 1) < 0.005);
    QVERIFY(std::abs(lens["cx"].get<double>() - 319.5) < 1.0);
    QVERIFY(std::abs(lens["cy"].get<double>() - 255.5) < 1.0);
    QCOMPARE(lens["calibration"]["method"].get<std::string>(), std::string("checkerboard"));
    QCOMPARE(lens["calibration"]["images_used"].get<int>(), 7);
    QCOMPARE(lens["calibration"]["images_rejected"].get<int>(), 1);
    QVERIFY(lens["calibration"]["rms_px"].get<double>() < 0.3);
  }

  void usage_errors() {
    QCOMPARE(cli({"lens", "calibrate", "a.png", "--square", "30", "--out", "x.json"}).code, 2);  // no --board
    QCOMPARE(cli({"lens", "calibrate", "a.png", "--board", "10x7", "--square", "30"}).code, 2);  // no --out
    QCOMPARE(cli({"lens", "calibrate", "a.png", "--board", "10x7", "--square", "30", "--model", "pinhole", "--out",
                  "x.json"})
                 .code,
             2);
    QCOMPARE(cli({"synth-frame", "--scene", "checkerboard", "--out", "x"}).code, 2);  // no pose
    QCOMPARE(cli({"synth-frame", "--out", "x", "--board", "10x7"}).code, 2);          // board without the scene
    const auto r = cli({"lens", "calibrate", "nothere.png", "--board", "10x7", "--square", "30", "--out", "x.json"});
    QCOMPARE(r.code, 1);
    QVERIFY(r.err.contains("nothere.png: no such file"));
  }
};

QTEST_GUILESS_MAIN(TestCliLensCalibrate)
#include "test_cli_lens_calibrate.moc"
