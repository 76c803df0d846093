// SPDX-License-Identifier: GPL-3.0-or-later
#include "frames/frame_store.h"

#include <filesystem>
#include <initializer_list>
#include <string_view>

#include <nlohmann/json.hpp>

#include "frames/frame_codec.h"
#include "frames/frame_pnm.h"
#include "frames/frame_raw.h"

namespace bs {
namespace {

// The formats a frame is read again from (raw-bayer aside, which needs the geometry recorded at import). Only
// these formats produce frames, so the lookup stays in this folder, not in the registry of every format above it.
const FileFormat* frame_file_format(std::string_view id) {
  for (const FileFormat* format : {&kPnmFileFormat, &kPngFileFormat, &kTiffFileFormat})
    if (format->id == id) return format;
  return nullptr;
}

}  // namespace

Frame load_frame(const Workspace& ws, const StoredFrame& stored, const CancelToken& cancel,
                 const ImportLimits& limits) {
  Frame out = stored.frame;
  if (stored.frame.storage == FrameStorage::Copy) {
    out.pixels = ws.frame_pixels(stored.id);
    return out;
  }
  const ErrorLocation at{stored.path, 0, 0, {}};
  std::error_code ec;
  if (!std::filesystem::is_regular_file(stored.path, ec))
    throw ImportError(ImportErrorCategory::Io, at,
                      "frame \"" + stored.frame.label +
                          "\" is kept by reference and its file is gone (import it again, or with --copy-frames)");
  if (file_content_hash(stored.path) != stored.content_hash)
    throw ImportError(ImportErrorCategory::InvalidValue, at,
                      "file changed since it was imported (content hash differs); import it again");
  ImportBatch batch;
  if (stored.frame.source_format == "raw-bayer") {
    // The geometry recorded at import, so a sidecar edited later cannot change how the bytes are read.
    const auto j = nlohmann::json::parse(stored.frame.read_options, nullptr, false);
    if (!j.is_object())
      throw ImportError(ImportErrorCategory::Syntax, {ws.path(), 0, 0, "read_options"},
                        "stored raw geometry is damaged");
    RawFrameOptions o;
    o.width = j.value("width", 0);
    o.height = j.value("height", 0);
    o.pattern = j.value("pattern", std::string("BGGR"));
    o.bit_depth = j.value("bit_depth", 8);
    o.big_endian = j.value("endianness", std::string("little")) == "big";
    batch = read_raw_frame(stored.path, o, limits, cancel, ws.path());
  } else {
    const FileFormat* format = frame_file_format(stored.frame.source_format);
    if (!format)
      throw ImportError(ImportErrorCategory::Unsupported, at,
                        "frame format \"" + stored.frame.source_format + "\" is unknown to this build");
    batch = format->parse(stored.path, ParseOptions{}, limits, cancel);
  }
  if (batch.frames.size() != 1 || batch.frames[0].width != out.width || batch.frames[0].height != out.height ||
      batch.frames[0].channels != out.channels)
    throw ImportError(ImportErrorCategory::InvalidValue, at, "file no longer holds the frame recorded at import");
  out.pixels = std::move(batch.frames[0].pixels);
  return out;
}

}  // namespace bs
