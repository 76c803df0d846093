// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The JSON sidecar that gives a raw Bayer file its geometry (capture.raw -> capture.json), one module for everyone
// who reads or writes it: `benchscope-cli synth-frame` writes it, the frame importer (importers/frames/frame_raw.cpp)
// and the pipeline's frame reader (core/vision/frames/frame_file.cpp) read it. Its JSON Schema is
// resources/schema/benchscope-raw-v1.schema.json:
//   {"format": "benchscope-raw", "version": 1, "width": 1280, "height": 1024, "pattern": "BGGR",
//    "bit_depth": 8, "endianness": "little", "synthetic": true, "truth": "capture-truth.png", "lens": {...}}
// Rules (the same for every reader): width, height and bit_depth are required integers (1 to 2^30; 1 to 16 bits,
// two bytes per sample above 8); format and version are optional, but when present must be "benchscope-raw" and
// at most 1; endianness ("little" | "big") is required above 8 bits, where the byte order is otherwise a guess;
// pattern is one of BGGR, RGGB, GRBG, GBRG in any case. Other members are ignored, so later versions can add some.
// What a reader adds on top: the importer requires a pattern (it stores how to demosaic), the pipeline falls back
// to its --pattern; each applies its own size limits (ImportLimits) and checks the raw file's size.
#include <optional>
#include <stdexcept>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace bs {

struct RawSidecar {
  int width = 0;
  int height = 0;
  std::optional<std::string> pattern;  // upper case; absent when the sidecar names none
  int bit_depth = 8;
  bool big_endian = false;
  bool synthetic = false;  // rendered (synth-frame), not captured
  std::string lens_json;   // the "lens" object (lens + view), serialised; empty when absent
  std::string truth;       // the ground-truth image synth-frame wrote beside it; empty when absent
};

// A sidecar that breaks the rules: which member (a JSON pointer such as "/bit_depth") and why.
class RawSidecarError : public std::runtime_error {
 public:
  enum class Kind { Missing, WrongType, Invalid, Unsupported };
  RawSidecarError(Kind kind, std::string pointer, const std::string& reason)
      : std::runtime_error(pointer + ": " + reason), kind_(kind), pointer_(std::move(pointer)), reason_(reason) {}
  Kind kind() const noexcept { return kind_; }
  const std::string& pointer() const noexcept { return pointer_; }
  const std::string& reason() const noexcept { return reason_; }

 private:
  Kind kind_;
  std::string pointer_;
  std::string reason_;
};

// Reads a parsed sidecar document; throws RawSidecarError.
RawSidecar raw_sidecar_from_json(const nlohmann::json& doc);
// The document for `s`, with format and version, as synth-frame writes it (raw_sidecar_from_json reads it back).
nlohmann::json raw_sidecar_to_json(const RawSidecar& s);

// Where the sidecar of a raw file is written and looked for first: same folder and stem, extension .json.
std::string raw_sidecar_path(const std::string& raw_path);
// The sidecar that exists for `raw_path`: capture.json, else capture.raw.json; nullopt when there is neither.
std::optional<std::string> find_raw_sidecar(const std::string& raw_path);

}  // namespace bs
