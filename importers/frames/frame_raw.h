// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Raw Bayer captures: row-major samples with no header, 1 byte each (8-bit) or 2 bytes each (10/12/14/16-bit
// values in the low bits of a 16-bit word, little or big endian). The geometry comes from the JSON sidecar next to
// the file (capture.raw -> capture.json, or capture.raw.json), read by model/raw_sidecar.h with the rules and
// schema there (resources/schema/benchscope-raw-v1.schema.json); this importer also requires its "pattern". For a
// file without a sidecar the geometry comes from RawFrameOptions given by the caller (import --raw-geometry).
#include <string>

#include "common/format_importer.h"
#include "model/raw_sidecar.h"

namespace bs {

struct RawFrameOptions {
  int width = 0;
  int height = 0;
  std::string pattern = "BGGR";  // "" for a grey (non-mosaic) raw image
  int bit_depth = 8;             // 1..16; above 8 two bytes per sample
  bool big_endian = false;
  bool synthetic = false;
  std::string lens_json;  // lens + view JSON, when known
};

// Reads a sidecar; every error names the sidecar file and the JSON field.
RawFrameOptions read_raw_sidecar(const std::string& sidecar_path, const ImportLimits& limits = {});

// Reads a raw file with the geometry in `options`; the file size must be exactly width x height x bytes per sample.
// `geometry_source` names where the geometry came from for error messages (the sidecar path or "--raw-geometry").
ImportBatch read_raw_frame(const std::string& path, const RawFrameOptions& options, const ImportLimits& limits = {},
                           const CancelToken& cancel = CancelToken{}, const std::string& geometry_source = {});

// "WxH[:PATTERN[:BITS[:le|be]]]", e.g. "1280x1024:BGGR:12:le"; PATTERN "grey" for no mosaic. Throws
// std::invalid_argument with the reason.
RawFrameOptions parse_raw_geometry(const std::string& text);

// True for a .raw file with no sidecar next to it: it can only be read with a geometry from the user.
bool raw_without_sidecar(const std::string& path);

extern const FileFormat kRawBayerFileFormat;

}  // namespace bs
