// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli runs: the FLOPS runs of a workspace with their ids, and the user's labels for them
// (store/run_label_store.h), which legends, tables, figures and the report show after the run's own name.
#include <iostream>
#include <set>

#include "common/args.h"
#include "common/command.h"
#include "common/text_table.h"
#include "store/run_label_store.h"
#include "workspace/inputs.h"

namespace bs::cli {
namespace {

int run_runs(const std::vector<std::string>& raw, std::ostream& out, std::ostream&) {
  const ParsedArgs args = parse_args(raw, {"--clear"}, {"--label", "--run"});
  if (args.positional.size() != 1) throw UsageError("runs needs one workspace");
  const std::string& path = args.positional.front();
  if (!looks_like_workspace(path)) throw UsageError(path + ": not a workspace (.bsw)");
  // Listing only reads: read-only, so it never migrates or checkpoints a file the GUI has open.
  Workspace ws(path, args.value("--run") ? Workspace::OpenMode::ReadWrite : Workspace::OpenMode::ReadOnly);
  const auto runs = ws.runs();
  if (const auto id_text = args.value("--run")) {
    if (!args.value("--label") && !args.has("--clear")) throw UsageError("--run ID needs --label TEXT or --clear");
    std::int64_t id = 0;
    try {
      std::size_t used = 0;
      id = std::stoll(*id_text, &used);
      if (used != id_text->size()) throw std::invalid_argument("junk");
    } catch (const std::exception&) {
      throw UsageError("--run takes a run id (a number from `benchscope-cli runs " + path + "`)");
    }
    const auto it = std::find_if(runs.begin(), runs.end(), [&](const StoredRun& r) { return r.id == id; });
    if (it == runs.end())
      throw std::runtime_error(path + ": no run with id " + *id_text + " (`benchscope-cli runs " + path +
                               "` lists them)");
    set_run_label(ws, *it, args.has("--clear") ? std::string() : *args.value("--label"));
    out << "run " << id << (args.has("--clear") ? ": label removed" : ": labelled \"" + *args.value("--label") + "\"")
        << '\n';
    return 0;
  }
  if (args.value("--label") || args.has("--clear")) throw UsageError("--label and --clear need --run ID");
  const auto labels = run_labels(ws, runs);
  TextTable table({"Id", "Platform", "Device", "Backend", "D", "N", "Date", "Host", "Label"});
  for (const StoredRun& r : runs) {
    const auto label = labels.find(r.id);
    table.add({std::to_string(r.id), r.run.platform, r.run.device, r.run.backend, std::to_string(r.run.dims),
               std::to_string(r.run.iterations), r.run.provenance.date, r.run.provenance.host,
               label == labels.end() ? "" : label->second});
  }
  table.print(out);
  return 0;
}

const CommandRegistrar registrar({
    "runs",
    "list a workspace's FLOPS runs with their ids; label a run (--run ID --label TEXT)",
    "usage: benchscope-cli runs WORKSPACE [--run ID (--label TEXT | --clear)]\n"
    "  Lists the workspace's FLOPS runs: id, platform, device, backend, D, N, date, host and label. With --run ID\n"
    "  --label TEXT the run gets a label (at most 80 characters), shown after the run's own name in the GUI's\n"
    "  legends and tree, `figures` and `report`; --clear removes it. Where two runs would read the same, legends\n"
    "  and tables add what differs (label, date and time, host, N) on their own.",
    run_runs,
});

}  // namespace
}  // namespace bs::cli
