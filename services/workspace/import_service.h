// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one way files get into a workspace, shared by `benchscope-cli import` and the GUI's import (drag and drop,
// File > Import): which files a folder holds and in what order, which are skipped and why, how many transactions,
// duplicates by content hash, progress and cancel. The front ends only word the outcome. No Qt here.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "common/importer.h"
#include "frames/frame_raw.h"
#include "model/frame.h"

namespace bs {

class Workspace;

// A file to import: named by the user, or found by walking a folder the user named.
struct ImportCandidate {
  std::string path;
  bool from_folder = false;
};

// Files named directly are kept in the order given. Folders are walked recursively; hidden entries (".git",
// ".DS_Store") are left out, and what a folder holds is sorted by path, byte by byte, so the order is the same on
// every machine and file system. Throws ImportError(Io) naming a folder that cannot be listed.
std::vector<ImportCandidate> expand_import_paths(const std::vector<std::string>& paths);

// Files met while walking a folder that are simply not data (READMEs, scripts, images no importer claims): they
// are skipped with a reason, never failures. A file the user named directly that no importer reads is a failure.
bool skippable_in_folder(const ImportError& e);

// How many transactions an import takes.
enum class ImportAtomicity {
  EachFile,      // one transaction per file: a bad file fails alone, the others are stored (the GUI)
  AllOrNothing,  // every file is parsed first; one failure (or a cancel) stores nothing, else one transaction
};

struct ImportOptions {
  ImportAtomicity atomicity = ImportAtomicity::EachFile;
  FrameStorage frames = FrameStorage::Reference;
  // The geometry of .raw files without a sidecar, and where it came from for error messages
  // ("--raw-geometry", "the geometry dialog").
  std::optional<RawFrameOptions> raw_geometry;
  std::string raw_geometry_source;
  // The platform of power logs whose file names none (issue #32.3). `log_platform` (the CLI's --platform) wins;
  // else `choose_log_platform` is asked with the guess (common/log_platform.h) and the workspace's platforms (the
  // GUI's dialog; called on the importing thread); else the guess is taken. An empty answer takes the guess.
  std::string log_platform;
  std::function<std::string(const PowerTrace& log, const std::string& path, const std::string& guess,
                            const std::vector<std::string>& platforms)>
      choose_log_platform;
  // Called before each file with (files done, files in all, the file's path), and once at the end with
  // (total, total, ""). Called on the importing thread.
  std::function<void(int done, int total, const std::string& path)> progress;
};

// What became of one file.
struct FileOutcome {
  enum class Kind {
    Imported,    // stored (or, with AllOrNothing, would have been had nothing failed: see ImportResult::committed)
    Duplicate,   // the same bytes are already in the workspace, or earlier in this import: skipped
    NotData,     // found in a folder and no importer reads it: skipped
    Failed,      // an error; `reason` is the importer's "file:line: field: reason"
    NotReached,  // cancelled, or AllOrNothing after a failure, before it was stored
  };
  std::string path;
  Kind kind = Kind::NotReached;
  std::string reason;   // NotData: why; Duplicate: "already imported on DATE as PATH"; Failed: the error
  std::string summary;  // Imported: what the file held, e.g. "3 runs (benchscope-run-v1)" (describe_batch)
  // Imported: the computers its results and logs belong to (a tree's per-computer report); NotData: the computer
  // a results tree files it under (results/<system>/...), "" when nothing says.
  std::vector<std::string> computers;
  std::string read_with;              // NotData: the file it was read with (an MLPerf summary's companion), else ""
  std::vector<std::string> warnings;  // the importer's warnings, each naming file:line
  std::string content_hash;
  std::int64_t import_id = 0;  // Imported and committed: the workspace's import id
  // Duplicate: the earlier import (path as given then, ISO 8601 UTC time); empty time for a twin in this import.
  std::string earlier_path;
  std::string earlier_imported_at;
};

struct ImportResult {
  std::vector<FileOutcome> files;  // in import order
  bool cancelled = false;
  // False when nothing was written: AllOrNothing with a failure or a cancel, or nothing importable.
  bool committed = false;
  int count(FileOutcome::Kind kind) const;
};

// Imports `paths` (files and folders) into the workspace at `workspace_path`, which is created when missing. The
// workspace is opened only once there is something to store, so a run where every file fails leaves no new file.
// Never throws for a bad file (its outcome says Failed); throws WorkspaceError when the workspace itself cannot be
// opened or written, and ImportError(Io) when a folder cannot be listed.
ImportResult import_paths(const std::string& workspace_path, const std::vector<std::string>& paths,
                          const ImportOptions& options = {}, const CancelToken& cancel = CancelToken{});

// What an import took and passed over, per computer: "NVIDIA Jetson AGX Orin (MaxQ, TensorRT): took 3 (…);
// passed over 2 (…)". Files of no computer are listed under "computer not stated".
std::vector<std::string> per_computer_report(const ImportResult& result);

// One line saying what a batch holds: "5 runs, 2 result sets (google-benchmark-json)", or for a frame
// "frame 1280x1024 BGGR 8-bit synthetic (by reference) (raw-bayer)".
std::string describe_batch(const ImportBatch& batch);

}  // namespace bs
