// SPDX-License-Identifier: GPL-3.0-or-later
// `platforms --require-sustained` (#53) on the paper's sample data, which has no sustained run: every platform is
// unknown with the reason, in text and JSON, and none is recommended; --store keeps the requirement, later runs use
// it (and say so), constraints given replace it, --no-stored ignores it; a requirement that does not parse is a
// usage error naming the term.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include "../../support/cli_harness.h"
#include "../../support/platforms_json.h"

using namespace bs::test;  // the CLI harness (run_cli, kPaper) and the readers of its output

class TestCliSustained : public QObject {
  Q_OBJECT
 private slots:
  void unknown_without_a_sustained_run() {
    QByteArray out, err;
    QCOMPARE(run_cli({"platforms", kPaper, "--require-sustained", "stability>=97%,minutes>=20", "--json"}, &out), 0);
    const QJsonObject s = QJsonDocument::fromJson(out).object()["sustained"].toObject();
    QCOMPARE(s["requirement"].toString(), QString("stability>=97%,minutes>=20"));
    QCOMPARE(s["described"].toString(), QString("stability >= 97 %, at least 20 min"));
    const QJsonArray list = s["platforms"].toArray();
    QVERIFY(list.size() >= 2);
    for (const auto v : list) {
      const QJsonObject p = v.toObject();
      QCOMPARE(p["status"].toString(), QString("unknown"));
      QCOMPARE(p["reason"].toString(), QString("no sustained run of this platform"));
      QCOMPARE(p["record"].toString(), QString());
    }
    // Unknown never passes: the NUC, chosen without it, is not chosen now, and its checks say why.
    QCOMPARE(recommended(out), QString());
    bool named = false;
    for (const auto v : QJsonDocument::fromJson(out).object()["platforms"].toArray())
      for (const auto k : v.toObject()["checks"].toArray())
        named |= k.toObject()["name"].toString() == "sustained: no sustained run of this platform";
    QVERIFY(named);
    QCOMPARE(run_cli({"platforms", kPaper, "--require-sustained", "throttle=none"}, &out), 0);
    QVERIFY2(out.contains("sustained: no throttling") && out.contains("no sustained run of this platform"),
             out.constData());
    QCOMPARE(run_cli({"platforms", kPaper, "--require-sustained", "stability>=97%,speed>=3"}, &out, &err), 2);
    QVERIFY2(err.contains("--require-sustained: sustained requirement term 'speed>=3': unknown term 'speed'"),
             err.constData());
  }

  void the_stored_decision_keeps_it() {
    QTemporaryDir dir;
    const QString ws = dir.filePath("paper.bsw");
    QCOMPARE(run_cli({"import", ws, kPaper, "--quiet"}), 0);
    QByteArray out, err;
    QCOMPARE(run_cli({"platforms", ws, "--require-sustained", "minutes>=20", "--store"}, &out, &err), 0);
    QVERIFY2(err.contains("sustained at least 20 min"), err.constData());
    QCOMPARE(run_cli({"platforms", ws, "--json"}, &out), 0);
    const QJsonObject stored = QJsonDocument::fromJson(out).object();
    QCOMPARE(stored["sustained"].toObject()["requirement"].toString(), QString("minutes>=20"));
    QVERIFY2(stored["stored_in_workspace"].toString().contains("sustained at least 20 min"), out.constData());
    QCOMPARE(recommended(out), QString());
    QCOMPARE(run_cli({"platforms", ws, "--budget", "10", "--json"}, &out), 0);  // given: replaces it
    QVERIFY(QJsonDocument::fromJson(out).object()["sustained"].isNull());
    QCOMPARE(recommended(out), QString("Jetson TX2"));
    QCOMPARE(run_cli({"platforms", ws, "--no-stored", "--json"}, &out), 0);
    QVERIFY(QJsonDocument::fromJson(out).object()["sustained"].isNull());
    QCOMPARE(recommended(out), QString("NUC"));
  }
};

QTEST_GUILESS_MAIN(TestCliSustained)
#include "test_cli_sustained.moc"
