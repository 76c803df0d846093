// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli check WORKSPACE [--remove-damaged]: every finding about a workspace file (docs/workspace-check.md),
// one line each; exit 1 when there is any. Nothing is written unless --remove-damaged says so.
#include <iostream>

#include "common/args.h"
#include "common/command.h"
#include "common/signals.h"
#include "store/workspace.h"
#include "store/workspace_check.h"

namespace bs::cli {
namespace {

int print_report(const std::string& path, const CheckReport& r, std::ostream& out) {
  for (const CheckFinding& f : r.findings) out << path << ": " << f.item << ": " << f.reason << '\n';
  if (r.findings.empty()) {
    out << path << ": ok (schema " << r.schema_version << "; SQLite integrity, foreign keys, every value, sample "
        << "chunks and summaries checked)\n";
    return 0;
  }
  out << path << ": " << r.findings.size() << (r.findings.size() == 1 ? " finding" : " findings") << '\n';
  return 1;
}

int run_check(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err) {
  const ParsedArgs args = parse_args(raw, {"--remove-damaged"}, {});
  if (args.positional.size() != 1) throw UsageError("check needs exactly one workspace");
  const std::string& path = args.positional[0];
  if (args.has("--remove-damaged")) {
    try {
      Workspace ws(path);
      const std::size_t items = ws.damage().size();
      const std::size_t rows = ws.remove_damaged();
      out << path << ": removed " << items << " damaged item" << (items == 1 ? "" : "s") << " (" << rows
          << (rows == 1 ? " row" : " rows") << " and what belonged to them)\n";
    } catch (const WorkspaceError& e) {
      err << "benchscope-cli: error: " << e.what() << '\n';
      return 1;
    }
  }
  return print_report(path, check_workspace(path, &interrupt_token()), out);
}

const CommandRegistrar registrar({
    "check",
    "check a workspace file: SQLite integrity and every stored value; list what is damaged",
    "usage: benchscope-cli check WORKSPACE [--remove-damaged]\n"
    "  Reads WORKSPACE without writing to it and prints one line per finding: SQLite's integrity check and foreign\n"
    "  keys, every stored value against the import rules (counts within the limits, times > 0, numbers finite,\n"
    "  known names, JSON within the limits), sample chunks that follow each other and add up, every sample finite,\n"
    "  and each power log's cached summary equal to the one its samples give. Exit 0 when nothing is found, 1\n"
    "  otherwise (also for a file that is not a workspace, a newer schema, a truncated file).\n"
    "  --remove-damaged  first delete every damaged item (a run with its timings, a power log with its samples, a\n"
    "                    frame, ...; a damaged device with its runs), then check again. Other BenchScope commands\n"
    "                    leave damaged items out with a warning and refuse to write to the workspace until then.\n"
    "  See docs/workspace-check.md.",
    run_check,
});

}  // namespace
}  // namespace bs::cli
