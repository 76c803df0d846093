// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/power_line_reader.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <utility>

#include "common/import_error.h"
#include "common/importer.h"

namespace bs {
namespace {

// Big enough that the per-block bookkeeping is noise, small enough to stay in L2 with the parsed columns.
constexpr std::size_t kBlockBytes = std::size_t{1} << 20;

}  // namespace

PowerLineReader::PowerLineReader(std::string_view text, std::string name)
    : path_(std::move(name)), text_(strip_utf8_bom(text)), file_size_(text.size()) {
  consumed_ = text.size() - text_.size();
}

PowerLineReader::PowerLineReader(const std::string& path) : path_(path), eof_(false) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw ImportError(ImportErrorCategory::Io, {path, 0, 0, {}}, "is a folder, not a file");
  const auto size = std::filesystem::file_size(path, ec);
  file_size_ = ec ? 0 : static_cast<std::size_t>(size);
  file_ = std::fopen(path.c_str(), "rb");
  if (!file_)
    throw ImportError(ImportErrorCategory::Io, {path, 0, 0, {}}, std::string("cannot open: ") + std::strerror(errno));
  // One block plus room for the longest allowed line carried over from the previous block.
  buffer_.resize(kBlockBytes + kMaxPowerLogLineBytes);
}

PowerLineReader::~PowerLineReader() {
  if (file_) std::fclose(file_);
}

// Moves the unread tail to the front of the buffer and appends the next block.
bool PowerLineReader::refill() {
  if (eof_) return false;
  const std::size_t carry = text_.size();
  if (carry > kMaxPowerLogLineBytes)
    throw ImportError(ImportErrorCategory::TooLarge, {path_, line_ + 1, 0, {}},
                      "line longer than " + std::to_string(kMaxPowerLogLineBytes) +
                          " bytes (the limit for a log line); not a text log?");
  if (carry > 0) std::memmove(buffer_.data(), text_.data(), carry);
  const std::size_t got = std::fread(buffer_.data() + carry, 1, kBlockBytes, file_);
  if (got < kBlockBytes) {
    if (std::ferror(file_)) throw ImportError(ImportErrorCategory::Io, {path_, line_ + 1, 0, {}}, "read error");
    eof_ = true;
  }
  text_ = std::string_view(buffer_.data(), carry + got);
  if (first_block_) {
    first_block_ = false;
    const std::size_t before = text_.size();
    text_ = strip_utf8_bom(text_);
    consumed_ += before - text_.size();
  }
  return got > 0;
}

std::optional<std::string_view> PowerLineReader::next() {
  for (;;) {
    const std::size_t nl = text_.find('\n');
    if (nl != std::string_view::npos || (eof_ && !text_.empty())) {
      const std::size_t len = nl == std::string_view::npos ? text_.size() : nl;
      if (len > kMaxPowerLogLineBytes)
        throw ImportError(ImportErrorCategory::TooLarge, {path_, line_ + 1, 0, {}},
                          "line longer than " + std::to_string(kMaxPowerLogLineBytes) +
                              " bytes (the limit for a log line); not a text log?");
      std::string_view line = text_.substr(0, len);
      const std::size_t used = nl == std::string_view::npos ? len : len + 1;
      text_.remove_prefix(used);
      consumed_ += used;
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      unterminated_ = nl == std::string_view::npos;
      ++line_;
      return line;
    }
    if (eof_ || !refill()) {
      if (!text_.empty()) continue;  // the last line had no line ending
      return std::nullopt;
    }
  }
}

}  // namespace bs
