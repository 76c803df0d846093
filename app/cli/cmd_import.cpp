// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli import WORKSPACE PATH... : files are parsed completely first; by default one bad file means
// nothing is imported, so a workspace never holds half of a batch the user asked for.
#include <filesystem>
#include <iostream>
#include <optional>

#include "args.h"
#include "command.h"
#include "frame_raw.h"
#include "importer.h"
#include "inputs.h"
#include "signals.h"
#include "store/workspace.h"

namespace bs::cli {
namespace {

struct Parsed {
  std::string path;
  ImportBatch batch;
};

std::string summary(const ImportBatch& b) {
  std::string s = b.runs.empty() && !b.frames.empty()
                      ? std::string()
                      : std::to_string(b.runs.size()) + (b.runs.size() == 1 ? " run" : " runs");
  if (!b.result_sets.empty()) s += ", " + std::to_string(b.result_sets.size()) + " result sets";
  if (!b.power_traces.empty()) s += ", " + std::to_string(b.power_traces.size()) + " power traces";
  for (const Frame& f : b.frames)
    s += std::string(s.empty() ? "" : ", ") + "frame " + std::to_string(f.width) + "x" + std::to_string(f.height) + " " +
         (f.pattern.empty() ? (f.channels == 3 ? "colour" : "grey") : f.pattern) + " " + std::to_string(f.bit_depth) +
         "-bit" + (f.synthetic ? " synthetic" : "") + (f.storage == FrameStorage::Copy ? " (copied)" : " (by reference)");
  if (!b.pipeline_runs.empty())
    s += ", " + std::to_string(b.pipeline_runs.size()) + (b.pipeline_runs.size() == 1 ? " pipeline run" : " pipeline runs");
  return s + " (" + b.format + ")";
}

// "already imported on <date> (skipped)", naming the earlier file when it had another name.
std::string duplicate_note(const Workspace& ws, const std::string& hash, const WorkspaceError& e) {
  for (const ImportRecord& r : ws.imports())
    if (r.content_hash == hash) return "already imported on " + r.imported_at + " as " + r.path + " (skipped)";
  return std::string(e.what()) + " (skipped)";
}

int run_import(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err) {
  const ParsedArgs args = parse_args(raw, {"--keep-going", "--quiet", "--copy-frames"}, {"--raw-geometry"});
  if (args.positional.size() < 2) throw UsageError("import needs a workspace and at least one file or folder");
  const std::string workspace_path = args.positional[0];
  const bool keep_going = args.has("--keep-going");
  const bool quiet = args.has("--quiet");
  const CancelToken& cancel = interrupt_token();
  const FrameStorage storage = args.has("--copy-frames") ? FrameStorage::Copy : FrameStorage::Reference;
  std::optional<RawFrameOptions> raw_geometry;
  if (const auto g = args.value("--raw-geometry")) {
    try {
      raw_geometry = parse_raw_geometry(*g);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--raw-geometry: ") + e.what());
    }
  }
  // A .raw file without a sidecar is read with --raw-geometry when given; everything else is sniffed.
  const auto parse_one = [&](const std::string& path) {
    return import_file_with_raw_geometry(path, raw_geometry, cancel, "--raw-geometry");
  };

  std::vector<Parsed> parsed;
  int failures = 0;
  const std::vector<std::string> paths(args.positional.begin() + 1, args.positional.end());
  for (const InputFile& in : expand_inputs(paths)) {
    try {
      parsed.push_back({in.path, parse_one(in.path)});
      for (Frame& f : parsed.back().batch.frames) f.storage = storage;
      for (const auto& w : parsed.back().batch.warnings) err << "benchscope-cli: warning: " << w << '\n';
    } catch (const ImportError& e) {
      if (in.from_folder && skippable_in_folder(e)) {
        if (!quiet) out << "skipped " << in.path << ": " << e.reason() << '\n';
        continue;
      }
      err << "benchscope-cli: error: " << e.what() << '\n';
      ++failures;
    }
  }
  if (failures > 0 && !keep_going) {
    // stderr keeps exactly one line per failed file (scripts grep it); the hint goes with the normal output.
    if (!quiet)
      out << "nothing imported: " << failures << (failures == 1 ? " file" : " files")
          << " failed (--keep-going imports the others)\n";
    return 1;
  }
  if (parsed.empty()) {
    err << "benchscope-cli: error: no importable files found\n";
    return 1;
  }

  Workspace ws(workspace_path);
  for (const Parsed& p : parsed) {
    const std::string hash = file_content_hash(p.path);
    try {
      ws.add_import(p.batch, hash, &cancel);
      if (!quiet) out << "imported " << p.path << ": " << summary(p.batch) << '\n';
    } catch (const WorkspaceError& e) {
      if (e.kind() != WorkspaceError::Kind::Constraint) throw;
      // The same bytes are already there (under any name): not a failure, the data is in the workspace.
      if (!quiet) out << p.path << ": " << duplicate_note(ws, hash, e) << '\n';
    }
  }
  return failures > 0 ? 1 : 0;
}

const CommandRegistrar registrar({
    "import",
    "import benchmark, power and frame files or folders into a workspace",
    "usage: benchscope-cli import WORKSPACE PATH... [--keep-going] [--quiet] [--copy-frames]\n"
    "         [--raw-geometry WxH[:PATTERN[:BITS[:le|be]]]]\n"
    "  Imports files (formats recognised by content) and folders (walked recursively) into WORKSPACE (an SQLite\n"
    "  .bsw file, created when missing). Every file is parsed before anything is written; if one fails, nothing is\n"
    "  imported unless --keep-going is given. Each file is one transaction. A file imported before is skipped.\n"
    "  Frames (.raw + JSON sidecar, PGM/PPM, PNG, TIFF) are kept by reference (path + content hash, the file is read\n"
    "  again when opened) unless --copy-frames stores their pixels in the workspace. --raw-geometry gives the size,\n"
    "  Bayer pattern (BGGR, RGGB, GRBG, GBRG or grey), bit depth and byte order of .raw files that have no sidecar.",
    [](const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
      try {
        return run_import(args, out, err);
      } catch (const UsageError& e) {
        err << "benchscope-cli: error: " << e.what() << "\nusage: benchscope-cli import WORKSPACE PATH...\n";
        return 2;
      }
    },
});

}  // namespace
}  // namespace bs::cli
