// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// PNG and TIFF frames, decoded by OpenCV's imgcodecs (8- and 16-bit, grey or colour; alpha is dropped). Before
// OpenCV sees the file, its structure is checked here: the PNG chunk chain (every chunk inside the file, IHDR
// first, IEND present) or the TIFF header, first IFD and strip/tile extents, so a truncated file or a header
// claiming a giant image is refused with the file, the offset and the reason, before any pixel buffer exists.
// A grey image is taken as a BGGR Bayer mosaic (how raw captures are saved); PNG's sBIT chunk gives the
// significant bits of a 16-bit capture (10 or 12).
#include "common/importer.h"

namespace bs {

class PngImporter final : public Importer {
 public:
  std::string_view id() const override { return "png"; }
  std::string_view description() const override { return "PNG image"; }
  int sniff(std::string_view head, std::string_view path) const override;
  bool usual_extension(std::string_view path) const override;
  bool binary() const override { return true; }
  ImportBatch parse(const std::string& path, const ParseOptions& options, const ImportLimits& limits,
                    const CancelToken& cancel) const override;
};

class TiffImporter final : public Importer {
 public:
  std::string_view id() const override { return "tiff"; }
  std::string_view description() const override { return "TIFF image"; }
  int sniff(std::string_view head, std::string_view path) const override;
  bool usual_extension(std::string_view path) const override;
  bool binary() const override { return true; }
  ImportBatch parse(const std::string& path, const ParseOptions& options, const ImportLimits& limits,
                    const CancelToken& cancel) const override;
};

}  // namespace bs
