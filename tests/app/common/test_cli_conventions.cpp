// SPDX-License-Identifier: GPL-3.0-or-later
// What every benchscope-cli command does the same way: `COMMAND --help` and `-h` print its usage and exit 0,
// `--version` names the version, a wrong call exits 2 with the command's usage line, and the bash completion
// (generated from the command registry, committed as resources/completion/benchscope-cli.bash) knows every command.
#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include "../../support/cli_harness.h"

namespace {

using bs::test::cli;

// The command names `benchscope-cli help` lists, i.e. the registry's.
QStringList command_names() {
  const auto r = cli({"help"});
  QStringList names;
  static const QRegularExpression line(R"(^  ([a-z][a-z0-9-]*) +\S)");
  for (const QByteArray& l : r.out.split('\n')) {
    const auto m = line.match(QString::fromUtf8(l));
    if (m.hasMatch()) names << m.captured(1);
  }
  return names;
}

}  // namespace

class TestCliConventions : public QObject {
  Q_OBJECT
 private slots:
  void every_command_answers_help_with_its_usage() {
    const QStringList names = command_names();
    QVERIFY2(names.size() >= 15, qPrintable(names.join(' ')));
    QVERIFY(names.contains("import") && names.contains("completion") && names.contains("help"));
    for (const QString& name : names) {
      for (const char* flag : {"--help", "-h"}) {
        const auto r = cli({name, flag});
        QVERIFY2(r.code == 0, qPrintable(name + " " + flag + ": " + r.err));
        QVERIFY2(r.out.startsWith("usage: benchscope-cli " + name.toUtf8()), qPrintable(name + ": " + r.out));
        QVERIFY2(r.err.isEmpty(), qPrintable(name + ": " + r.err));
        QCOMPARE(r.out, cli({"help", name}).out);  // the same text as `help COMMAND`
      }
    }
    // After "--" a "-h" is an argument like any other, not a request for help.
    QCOMPARE(cli({"import", "--", "-h"}).code, 2);
  }

  void version() {
    const auto r = cli({"--version"});
    QCOMPARE(r.code, 0);
    QVERIFY2(QRegularExpression(R"(^benchscope-cli \d+\.\d+\.\d+\n$)").match(QString::fromUtf8(r.out)).hasMatch(),
             r.out.constData());
  }

  void usage_errors_exit_2_with_the_usage_line() {
    struct Case {
      QStringList args;
      QByteArray says;
    };
    const QList<Case> cases{{{"import", "w.bsw", "--no-such-option"}, "unknown option '--no-such-option'"},
                            {{"import", "only-a-workspace.bsw"}, "needs a workspace and at least one file"},
                            {{"peaks", "--kind"}, "--kind needs a value"},
                            {{"bench", "nothing"}, "expected 'bench kernels'"},
                            {{"lens"}, "expected 'lens circle'"},
                            {{"synth-frame"}, "--out PREFIX is required"},
                            {{"completion", "zsh"}, "bash is the one it writes"}};
    for (const Case& c : cases) {
      const auto r = cli(c.args);
      const QByteArray name = c.args[0].toUtf8();
      QVERIFY2(r.code == 2, qPrintable(c.args.join(' ') + ": exit " + QString::number(r.code) + " " + r.err));
      const QList<QByteArray> lines = r.err.trimmed().split('\n');
      QCOMPARE(lines.size(), 3);
      QVERIFY2(lines[0].startsWith("benchscope-cli: error: ") && lines[0].contains(c.says), r.err.constData());
      QVERIFY2(lines[1].startsWith("usage: benchscope-cli " + name), r.err.constData());
      QCOMPARE(lines[2], "(benchscope-cli " + name + " --help shows the full usage)");
      QVERIFY(r.out.isEmpty());
    }
    QCOMPARE(cli({"no-such-command"}).code, 2);
  }

  void bash_completion_knows_every_command_and_is_committed() {
    const auto r = cli({"completion", "bash"});
    QCOMPARE(r.code, 0);
    const QString script = QString::fromUtf8(r.out);
    for (const QString& name : command_names()) {
      QVERIFY2(QRegularExpression("local commands=\"[^\"]*\\b" + QRegularExpression::escape(name) + "\\b")
                   .match(script)
                   .hasMatch(),
               qPrintable(name + " missing from the command list"));
      if (name != "help")
        QVERIFY2(script.contains("    " + name + ") options=\"--help"), qPrintable(name + " has no options arm"));
    }
    QVERIFY(script.contains("import) options=\"--help --copy-frames --keep-going --platform --quiet --raw-geometry\""));
    // The committed file is exactly this output, so an installed completion matches the build it came with.
    QFile committed(BENCHSCOPE_SOURCE_DIR "/resources/completion/benchscope-cli.bash");
    QVERIFY(committed.open(QIODevice::ReadOnly));
    QVERIFY2(committed.readAll() == r.out,
             "resources/completion/benchscope-cli.bash is stale: regenerate it with "
             "`build/app/cli/benchscope-cli completion bash > resources/completion/benchscope-cli.bash`");
  }

  void bash_completion_completes_in_bash() {
    QTemporaryDir dir;
    const QString script = dir.filePath("c.bash");
    QFile f(script);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(cli({"completion", "bash"}).out);
    f.close();
    // Bash itself: complete "benchscope-cli im" and "benchscope-cli import --k".
    const auto complete = [&](const QString& words, int cword) {
      QProcess bash;
      bash.start("bash", {"-c", "source '" + script + "'; COMP_WORDS=(" + words + "); COMP_CWORD=" +
                                    QString::number(cword) + "; _benchscope_cli; printf '%s\\n' \"${COMPREPLY[@]}\""});
      bash.waitForFinished(20000);
      return QString::fromUtf8(bash.readAllStandardOutput()).split('\n', Qt::SkipEmptyParts);
    };
    QCOMPARE(complete("benchscope-cli im", 1), QStringList{"import"});
    QCOMPARE(complete("benchscope-cli import --k", 2), QStringList{"--keep-going"});
    QCOMPARE(complete("benchscope-cli help sy", 2), (QStringList{"synth-frame", "synth-power"}));
  }
};

QTEST_GUILESS_MAIN(TestCliConventions)
#include "test_cli_conventions.moc"
