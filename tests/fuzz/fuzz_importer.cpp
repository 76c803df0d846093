// SPDX-License-Identifier: GPL-3.0-or-later
#include "fuzz_importer.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string_view>

#include <unistd.h>

#include "analysis/peaks/foreign_sweeps.h"
#include "common/importer.h"
#include "frames/frame_raw.h"
#include "workspace/registry.h"

namespace bs::fuzz {
namespace {

// Importers read files (they stream large logs), so each input goes through a file in /dev/shm when it exists:
// the same code path as a real import, without disk traffic.
const std::string& scratch_path() {
  static const std::string path = [] {
    const char* dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
    return std::string(dir) + "/benchscope-fuzz-" + importer_id() + "-" + std::to_string(getpid());
  }();
  return path;
}

// Limits small enough that a fuzz input cannot make a legitimate but slow multi-second parse, large enough that
// every limit check is itself exercised.
ImportLimits fuzz_limits() {
  ImportLimits l;
  l.max_json_bytes = 1 << 20;
  l.max_samples = 100'000;
  l.max_json_values = 200'000;
  return l;
}

[[noreturn]] void finding(const char* what) {
  std::fprintf(stderr, "benchscope fuzz (%s): %s\n", importer_id(), what);
  std::abort();
}

}  // namespace

void run_one(const std::uint8_t* data, std::size_t size) {
  {
    std::ofstream f(scratch_path(), std::ios::binary | std::ios::trunc);
    f.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!f) finding("cannot write the scratch file");
  }
  const std::string_view id = importer_id();
  const CancelToken cancel;
  try {
    // What every load does after an import: derive the FLOPS sweeps inside result sets (benchmark names parsed).
    const auto derive = [](const ImportBatch& b) {
      for (const ResultSet& s : b.result_sets) (void)foreign_sweeps(s);
    };
    if (id == "any") {
      derive(import_file(scratch_path(), cancel, fuzz_limits()));
    } else if (id == "raw-bayer") {
      // A raw frame is two files: the input is "<sidecar JSON>\0<raw samples>" (no NUL: all sidecar, no samples).
      // Input that does not start with '{' is "<geometry>\0<raw samples>" instead: a .raw without a sidecar and
      // the geometry the user types (benchscope-cli import --raw-geometry WxH:PATTERN:BITS:le, the GUI's dialog).
      const std::string_view all(reinterpret_cast<const char*>(data), size);
      const std::size_t split = std::min(all.find('\0'), all.size());
      const std::string raw = scratch_path() + ".raw", sidecar = scratch_path() + ".json";
      const std::string_view head = all.substr(0, split);
      const std::string_view samples = split < all.size() ? all.substr(split + 1) : std::string_view();
      std::ofstream(raw, std::ios::binary | std::ios::trunc)
          .write(samples.data(), static_cast<std::streamsize>(samples.size()));
      if (!head.empty() && head.front() != '{') {
        std::remove(sidecar.c_str());
        std::optional<RawFrameOptions> geometry;
        try {
          geometry = parse_raw_geometry(std::string(head));
        } catch (const std::invalid_argument&) {
          // A geometry the CLI refuses as a usage error; the .raw is then read without one (no sidecar: an error).
        }
        (void)import_file_with_raw_geometry(raw, geometry, cancel, "--raw-geometry");
        return;
      }
      std::ofstream(sidecar, std::ios::binary | std::ios::trunc)
          .write(head.data(), static_cast<std::streamsize>(split));
      const Importer* imp = find_importer(id);
      if (!imp || imp->sniff({}, raw) != 100) finding("raw-bayer does not claim a .raw with a sidecar");
      (void)imp->parse(raw, ParseOptions{}, fuzz_limits(), cancel);
    } else {
      const Importer* imp = find_importer(id);
      if (!imp) finding("unknown importer id");
      const std::string_view text(reinterpret_cast<const char*>(data), size);
      (void)imp->sniff(text.substr(0, 64 * 1024), scratch_path());
      // As import_file does before any text importer runs; binary formats (frames) skip the text check.
      if (!imp->binary()) check_text(text.substr(0, 64 * 1024), scratch_path());
      derive(imp->parse(scratch_path(), ParseOptions{}, fuzz_limits(), cancel));
    }
  } catch (const ImportError&) {
    // The expected way to reject a bad file.
  } catch (const std::exception& e) {
    std::fprintf(stderr, "unexpected exception: %s\n", e.what());
    finding("an importer threw something other than ImportError");
  }
}

}  // namespace bs::fuzz
