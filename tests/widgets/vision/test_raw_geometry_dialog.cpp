// SPDX-License-Identifier: GPL-3.0-or-later
// The raw-geometry dialog for a .raw file without a sidecar: OK only when the geometry matches the file's size,
// the answer is remembered, and the import controller reads the file with it.
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QFile>
#include <QPushButton>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

#include "store/workspace.h"
#include "vision/raw_geometry_dialog.h"
#include "workspace/import_controller.h"

class TestRawGeometryDialog : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { QSettings().clear(); }  // each run starts as a fresh machine: nothing remembered

  void checks_size_remembers_and_imports() {
    QTemporaryDir dir;
    const QString raw = dir.filePath("cam.raw");
    QFile f(raw);
    QVERIFY(f.open(QIODevice::WriteOnly));
    QByteArray pixels(64 * 48 * 2, '\0');
    for (int i = 0; i < pixels.size(); i += 2) pixels[i] = static_cast<char>(i % 251);  // 12-bit little endian
    f.write(pixels);
    f.close();
    QVERIFY(bs::raw_without_sidecar(raw.toStdString()));

    QVERIFY(!bs::ui::RawGeometryDialog::remembered());
    bs::ui::RawGeometryDialog d(raw);
    QVERIFY(!d.matches_file());  // the default is the paper's 1280x1024 8-bit
    bs::RawFrameOptions o;
    o.width = 64;
    o.height = 48;
    o.pattern = "RGGB";
    o.bit_depth = 12;
    d.set_options(o);
    QVERIFY(d.matches_file());
    if (const QByteArray shots = qgetenv("BENCHSCOPE_SCREENSHOT_DIR"); !shots.isEmpty()) {
      d.show();
      QVERIFY(QTest::qWaitForWindowExposed(&d));
      d.grab().save(QString::fromLocal8Bit(shots) + "/raw-geometry-dialog.png");
    }
    auto* ok = d.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
    QVERIFY(ok->isEnabled());
    ok->click();
    QCOMPARE(d.result(), int(QDialog::Accepted));
    const auto remembered = bs::ui::RawGeometryDialog::remembered();
    QVERIFY(remembered);
    QCOMPARE(remembered->width, 64);
    QCOMPARE(remembered->pattern, std::string("RGGB"));
    QCOMPARE(remembered->bit_depth, 12);
    o.bit_depth = 8;
    d.set_options(o);
    QVERIFY(!ok->isEnabled());  // 64 x 48 x 1 byte is not the file's size

    const QString ws = dir.filePath("w.bsw");
    auto report = bs::ui::ImportController::import_now(ws, {raw}, bs::CancelToken{});
    QCOMPARE(report.imported, 0);  // without a geometry: a clear failure
    QCOMPARE(report.failures.size(), 1);
    report =
        bs::ui::ImportController::import_now(ws, {raw}, bs::CancelToken{}, {}, bs::FrameStorage::Reference, remembered);
    QCOMPARE(report.imported, 1);
    const bs::Workspace w(ws.toStdString());
    QCOMPARE(w.frames().size(), std::size_t{1});
    QCOMPARE(w.frames()[0].frame.width, 64);
    QCOMPARE(w.frames()[0].frame.bit_depth, 12);
  }
};

QTEST_MAIN(TestRawGeometryDialog)
#include "test_raw_geometry_dialog.moc"
