// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Lines of a text log, read in fixed-size blocks so a log of any length is parsed in one pass with bounded
// memory. Line endings LF or CRLF; a UTF-8 byte-order mark at the start is dropped
// (strip_utf8_bom). Used by the power importers.
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bs {

// The longest line a power log may have: anything longer is not a log line, and the streaming reader's buffer
// never grows beyond it.
inline constexpr std::size_t kMaxPowerLogLineBytes = std::size_t{1} << 20;

class PowerLineReader {
 public:
  // Lines of text already in memory (tests, sniffing); `name` is the file name errors carry.
  PowerLineReader(std::string_view text, std::string name);
  // Lines of a file, read block by block. Throws ImportError Io when it cannot be opened.
  explicit PowerLineReader(const std::string& path);
  ~PowerLineReader();
  PowerLineReader(const PowerLineReader&) = delete;
  PowerLineReader& operator=(const PowerLineReader&) = delete;

  // The next line without its line ending, valid until the next call; empty optional at the end.
  // Throws ImportError TooLarge for a line longer than kMaxPowerLogLineBytes, Io on a read error.
  std::optional<std::string_view> next();
  std::size_t line_number() const { return line_; }
  const std::string& name() const {
    return path_;
  }  // the file named in errors and warnings  // 1-based number of the line last returned
  // The line last returned ended the file without a line ending: a logger killed mid-write leaves such a line.
  bool last_line_unterminated() const { return unterminated_; }
  std::size_t bytes_consumed() const { return consumed_; }
  std::size_t file_size() const { return file_size_; }  // total bytes (file system size for files)

 private:
  bool refill();
  std::string path_;
  std::FILE* file_ = nullptr;
  std::vector<char> buffer_;
  std::string_view text_;  // the unread part of the current block (or of the in-memory text)
  bool eof_ = true;
  bool first_block_ = true;
  bool unterminated_ = false;
  std::size_t line_ = 0, consumed_ = 0, file_size_ = 0;
};

}  // namespace bs
