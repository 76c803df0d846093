// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Running benchscope-cli from a test as a user would: a separate process, its exit code, stdout and stderr.
// Shared by every tests/app/test_cli_*.cpp instead of a private QProcess helper in each.
#include <QByteArray>
#include <QFile>
#include <QProcess>
#include <QString>
#include <QStringList>

#include "file_bytes.h"  // bytes_of, for the files a command wrote
#include "paper_dir.h"   // kPaper, what most commands are tried on

namespace bs::test {

inline const QString kCli = BENCHSCOPE_BINARY_DIR "/app/cli/benchscope-cli";

struct CliResult {
  int code = -1;  // exit code; -1 when it crashed, -2 when it ran past the time limit
  QByteArray out, err;
};

// Runs benchscope-cli ARGS in `env` and waits up to `timeout_ms` (the pipeline tests measure, so the default is
// generous).
inline CliResult cli(const QStringList& args, const QProcessEnvironment& env, int timeout_ms = 300000) {
  QProcess p;
  p.setProcessEnvironment(env);
  p.start(kCli, args);
  if (!p.waitForFinished(timeout_ms)) {
    p.kill();
    p.waitForFinished();
    return {-2, p.readAllStandardOutput(), p.readAllStandardError()};
  }
  return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAllStandardOutput(),
          p.readAllStandardError()};
}

// ... in this process's environment.
inline CliResult cli(const QStringList& args, int timeout_ms = 300000) {
  return cli(args, QProcessEnvironment::systemEnvironment(), timeout_ms);
}

// The exit code alone, with stdout and stderr where the caller wants them.
inline int run_cli(const QStringList& args, QByteArray* out = nullptr, QByteArray* err = nullptr) {
  CliResult r = cli(args);
  if (out) *out = std::move(r.out);
  if (err) *err = std::move(r.err);
  return r.code;
}

}  // namespace bs::test
