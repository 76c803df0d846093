// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Checks and helpers shared by the frame importers (raw Bayer, PGM/PPM, PNG/TIFF). Every size a file claims is
// checked against ImportLimits and against the file's real size before a single pixel buffer is allocated.
#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>

#include "common/import_error.h"
#include "common/importer.h"
#include "model/frame.h"

namespace bs::frames {

// Throws ImportError(TooLarge / InvalidValue) naming `file` and `field` when width x height (x channels) is not a
// sensible image under `limits`. Call before allocating.
void check_dimensions(const std::string& file, const std::string& field, std::int64_t width, std::int64_t height,
                      const ImportLimits& limits);

// "BGGR", "RGGB", "GRBG", "GBRG" (any case) -> upper case; throws InvalidValue naming file and field otherwise.
std::string check_pattern(const std::string& file, const std::string& field, std::string_view pattern);

// Size of `path` from the file system (never from the file's own claims); throws Io.
std::uint64_t file_size(const std::string& path);

// `path` opened for reading bytes; throws Io naming it when it cannot be opened. The frame readers open their file
// after checking its size, and report a file that cannot be opened alike.
std::ifstream open_binary(const std::string& path);

// The file's stem ("capture" for /a/capture.raw): the frame's default label.
std::string stem_of(const std::string& path);

// Rejects samples above the largest value `bit_depth` bits can hold (a wrong bit depth or byte order shows up
// this way), naming the first offender's byte offset, row and column.
void check_sample_range(const std::string& file, const Frame& frame, std::uint64_t data_offset);

// A frame whose fields other than the pixels are filled in from the arguments.
Frame make_frame(const std::string& path, std::string_view format, int width, int height, int channels, int bit_depth,
                 std::string pattern);

}  // namespace bs::frames
