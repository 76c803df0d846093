// SPDX-License-Identifier: GPL-3.0-or-later
// workspace_holder WORKSPACE RUN_TEMPLATE WORK_DIR ROUND: a long-lived workspace, as the GUI holds one (issue #50),
// for tests that run CLI processes beside it and kill it with SIGKILL at random points
// (tests/app/workspace/test_workspace_sharing.cpp). It does what the GUI does with an open workspace, over and over:
//  - an edit on its own long-lived connection (a setting, as the Battery and Platforms tabs store theirs);
//  - every third step an import through the import service (a second connection, as File > Import makes);
//  - every third step a read through a read-only connection (as the Power tab's sample loader makes);
// and after each step checks what it holds: its POSIX locks on the workspace and its -shm file, and that no
// descriptor of it points at a deleted -wal. It prints one line per fact, flushed at once:
//   "committed ROUND I"          the edit I is committed (the test then expects it in the file whatever happens)
//   "imported ROUND I NAME"      the import of NAME is committed
//   "locks-lost ROUND I DB SHM"  a check found no lock on the file (DB) or its -shm (SHM): the bug of #50
//   "wal-deleted ROUND I"        a descriptor points at a deleted WAL
//   "error MESSAGE"              anything thrown (exit 1)
// It stops after 10,000 steps or when killed.
#include <sys/prctl.h>
#include <unistd.h>

#include <csignal>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "process_locks.h"
#include "store/workspace.h"
#include "workspace/import_service.h"

namespace {

std::string read_all(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

void say(const std::string& line) {
  std::fputs((line + '\n').c_str(), stdout);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::cerr << "usage: workspace_holder WORKSPACE RUN_TEMPLATE WORK_DIR ROUND\n";
    return 2;
  }
  const std::string path = argv[1], work = argv[3], round = argv[4];
  const std::string tmpl = read_all(argv[2]);
  const std::string marker = "\"generator\": \"hand-written fixture\"";
  if (tmpl.find(marker) == std::string::npos) {
    std::cerr << "workspace_holder: the template has no " << marker << '\n';
    return 2;
  }
  // A test that dies (a Qt Test timeout aborts it) takes its holder along: an orphan would go on editing and
  // loading the machine under the tests that follow.
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() == 1) return 1;  // the parent died before the line above
  try {
    bs::Workspace ws(path);  // the GUI's connection, open for the whole session
    const long pid = static_cast<long>(::getpid());
    for (int i = 0; i < 10000; ++i) {
      const std::string step = round + " " + std::to_string(i);
      ws.set_setting("holder/" + round + "/edit/" + std::to_string(i), std::to_string(i));
      say("committed " + step);
      if (i % 3 == 0) {
        const std::string name = "run-" + round + "-" + std::to_string(i) + ".json";
        std::string text = tmpl;
        text.replace(text.find(marker), marker.size(), "\"generator\": \"holder " + step + "\"");
        std::ofstream(work + "/" + name, std::ios::binary) << text;
        const bs::ImportResult r = bs::import_paths(path, {work + "/" + name});
        if (r.committed && r.count(bs::FileOutcome::Kind::Imported) == 1) say("imported " + step + " " + name);
      } else if (i % 3 == 1) {
        const bs::Workspace reader(path, bs::Workspace::OpenMode::ReadOnly);
        (void)reader.runs();
        (void)reader.power_trace_summaries();
      }
      const int db = bs::test::posix_locks_on(pid, path), shm = bs::test::posix_locks_on(pid, path + "-shm");
      if (db == 0 || shm == 0) say("locks-lost " + step + " " + std::to_string(db) + " " + std::to_string(shm));
      if (bs::test::holds_deleted_wal(pid, path)) say("wal-deleted " + step);
    }
  } catch (const std::exception& e) {
    say(std::string("error ") + e.what());
    return 1;
  }
  return 0;
}
