// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli import WORKSPACE PATH... : files are parsed completely first; by default one bad file means
// nothing is imported, so a workspace never holds half of a batch the user asked for.
#include <iostream>
#include <optional>

#include "common/args.h"
#include "common/command.h"
#include "common/signals.h"
#include "frames/frame_raw.h"
#include "store/workspace.h"
#include "workspace/import_service.h"

namespace bs::cli {
namespace {

int run_import(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err) {
  const ParsedArgs args =
      parse_args(raw, {"--keep-going", "--quiet", "--copy-frames"}, {"--raw-geometry", "--platform"});
  if (args.positional.size() < 2) throw UsageError("import needs a workspace and at least one file or folder");
  const bool keep_going = args.has("--keep-going");
  const bool quiet = args.has("--quiet");
  ImportOptions options;
  // Without --keep-going every file is parsed before anything is written, and all of them go in one transaction.
  options.atomicity = keep_going ? ImportAtomicity::EachFile : ImportAtomicity::AllOrNothing;
  options.frames = args.has("--copy-frames") ? FrameStorage::Copy : FrameStorage::Reference;
  // A .raw file without a sidecar is read with --raw-geometry when given; everything else is sniffed.
  if (const auto g = args.value("--raw-geometry")) {
    try {
      options.raw_geometry = parse_raw_geometry(*g);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--raw-geometry: ") + e.what());
    }
    options.raw_geometry_source = "--raw-geometry";
  }
  // A power log whose file names no platform gets this one, else a guess from its metadata and the workspace.
  options.log_platform = args.value("--platform").value_or("");
  const std::vector<std::string> paths(args.positional.begin() + 1, args.positional.end());
  const ImportResult result = import_paths(args.positional[0], paths, options, interrupt_token());

  using Kind = FileOutcome::Kind;
  // What parsing found, file by file: warnings and errors on stderr (one line per failed file: scripts grep it),
  // skipped files on stdout.
  for (const FileOutcome& f : result.files) {
    for (const auto& w : f.warnings) err << "benchscope-cli: warning: " << w << '\n';
    if (f.kind == Kind::NotData && !quiet) out << "skipped " << f.path << ": " << f.reason << '\n';
    if (f.kind == Kind::Failed) err << "benchscope-cli: error: " << f.reason << '\n';
  }
  const int failures = result.count(Kind::Failed);
  if (failures > 0 && !keep_going) {
    if (!quiet)
      out << "nothing imported: " << failures << (failures == 1 ? " file" : " files")
          << " failed (--keep-going imports the others)\n";
    return 1;
  }
  // Then what was stored. A duplicate is not a failure: the data is in the workspace already.
  for (const FileOutcome& f : result.files) {
    if (quiet) break;
    if (f.kind == Kind::Imported) out << "imported " << f.path << ": " << f.summary << '\n';
    if (f.kind == Kind::Duplicate) out << f.path << ": " << f.reason << " (skipped)\n";
  }
  // A tree of results: what was taken and passed over, per computer.
  if (!quiet && result.files.size() > 1) {
    out << "per computer:\n";
    for (const std::string& line : per_computer_report(result)) out << "  " << line << '\n';
  }
  if (result.cancelled) {
    err << "benchscope-cli: error: cancelled by the user"
        << (keep_going ? "; the files listed as imported are stored\n" : "; nothing imported\n");
    return 1;
  }
  if (result.count(Kind::Imported) + result.count(Kind::Duplicate) == 0) {
    err << "benchscope-cli: error: no importable files found\n";
    return 1;
  }
  return failures > 0 ? 1 : 0;
}

const CommandRegistrar registrar({
    "import",
    "import benchmark, power and frame files or folders into a workspace",
    "usage: benchscope-cli import WORKSPACE PATH... [--keep-going] [--quiet] [--copy-frames]\n"
    "         [--raw-geometry WxH[:PATTERN[:BITS[:le|be]]]] [--platform NAME]\n"
    "  Imports files (formats recognised by content) and folders (walked recursively) into WORKSPACE (an SQLite\n"
    "  .bsw file, created when missing). Every file is parsed before anything is written; if one fails, nothing is\n"
    "  imported unless --keep-going is given; all files go in one transaction (with --keep-going, one per file). A\n  "
    "file whose content was imported before is skipped.\n"
    "  Frames (.raw + JSON sidecar, PGM/PPM, PNG, TIFF) are kept by reference (path + content hash, the file is read\n"
    "  again when opened) unless --copy-frames stores their pixels in the workspace. --raw-geometry gives the size,\n"
    "  Bayer pattern (BGGR, RGGB, GRBG, GBRG or grey), bit depth and byte order of .raw files that have no sidecar.\n"
    "  A power log whose file names no platform gets --platform NAME, else one its metadata names (host name), else\n"
    "  \"unassigned: LOG\" (the workspace's only platform is never taken without --platform); the summary line says\n"
    "  which. An MLPerf LoadGen summary takes its computer from the system JSON beside it (never the harness's SUT\n"
    "  name) or from --platform; its detail log and spl.txt are read with it. A folder import ends with what was\n"
    "  taken and passed over per computer.",
    run_import,
});

}  // namespace
}  // namespace bs::cli
