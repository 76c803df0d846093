// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli finds its bundled resources (the device table) from an installed layout, PREFIX/bin/benchscope-cli
// with PREFIX/share/benchscope/resources, before the source tree it was built from; $BENCHSCOPE_RESOURCE_DIR first.
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <filesystem>

namespace {

const QString kCli = BENCHSCOPE_BINARY_DIR "/app/cli/benchscope-cli";

QJsonObject table_json(const QString& program, const QProcessEnvironment& env) {
  QProcess p;
  p.setProcessEnvironment(env);
  p.start(program, {"devices", "--table", "--json"});
  p.waitForFinished(60000);
  if (p.exitCode() != 0) qWarning("%s", p.readAllStandardError().constData());
  return QJsonDocument::fromJson(p.readAllStandardOutput()).object();
}

}  // namespace

class TestCliResources : public QObject {
  Q_OBJECT
 private slots:
  void installed_layout_then_environment() {
    QTemporaryDir prefix;
    namespace fs = std::filesystem;
    const fs::path root = prefix.path().toStdString();
    fs::create_directories(root / "bin");
    fs::create_directories(root / "share/benchscope");
    fs::copy_file(kCli.toStdString(), root / "bin/benchscope-cli");
    fs::copy(fs::path(BENCHSCOPE_SOURCE_DIR) / "resources", root / "share/benchscope/resources",
             fs::copy_options::recursive);
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove("BENCHSCOPE_RESOURCE_DIR");
    const QString installed = QString::fromStdString((root / "bin/benchscope-cli").string());
    const QJsonObject t = table_json(installed, env);
    QCOMPARE(t["format"].toString(), QString("benchscope-device-specs"));
    QVERIFY2(t["path"].toString().startsWith(QDir(prefix.path()).canonicalPath() + "/share/benchscope/resources/"),
             qPrintable(t["path"].toString()));
    QVERIFY(t["devices"].toArray().size() >= 45);
    // The build tree's binary reads the source tree's table.
    QVERIFY(table_json(kCli, env)["path"].toString().startsWith(BENCHSCOPE_SOURCE_DIR));
    // $BENCHSCOPE_RESOURCE_DIR wins over both.
    env.insert("BENCHSCOPE_RESOURCE_DIR", QString::fromStdString((root / "share/benchscope/resources").string()));
    QVERIFY(table_json(kCli, env)["path"].toString().startsWith(QDir(prefix.path()).canonicalPath()));
  }
};

QTEST_APPLESS_MAIN(TestCliResources)
#include "test_cli_resources.moc"
