// SPDX-License-Identifier: GPL-3.0-or-later
// What every format reads its file with: the head, the whole file within a limit, the text checks. Which format
// reads a file (the registry and its sniffing) is services/workspace/registry.cpp, above the format folders.
#include "common/importer.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "store/open_workspaces.h"

namespace bs {
namespace {

[[noreturn]] void io_error(const std::string& path, const std::string& what) {
  throw ImportError(ImportErrorCategory::Io, {path, 0, 0, {}}, what);
}

std::ifstream open_or_throw(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) io_error(path, "is a folder, not a file");
  // Reading the workspace this process has open, and closing that descriptor, would drop its SQLite locks.
  if (is_open_workspace(path))
    io_error(path, "is the workspace open here, not a file to import (reading it would drop its locks)");
  std::ifstream f(path, std::ios::binary);
  if (!f) io_error(path, std::string("cannot open: ") + std::strerror(errno));
  return f;
}

}  // namespace

std::string read_head(const std::string& path, std::size_t max_bytes) {
  std::ifstream f = open_or_throw(path);
  std::string head(max_bytes, '\0');
  f.read(head.data(), static_cast<std::streamsize>(max_bytes));
  head.resize(static_cast<std::size_t>(f.gcount()));
  if (f.bad()) io_error(path, "read error");
  return head;
}

std::string read_whole_file(const std::string& path, std::size_t max_bytes) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) io_error(path, "cannot read size: " + ec.message());
  // Checked before allocating: the size comes from the file system, never from the file's own claims.
  if (size > max_bytes)
    throw ImportError(ImportErrorCategory::TooLarge, {path, 0, 0, {}},
                      "file is " + std::to_string(size) + " bytes; the limit for this format is " +
                          std::to_string(max_bytes) + " bytes");
  std::ifstream f = open_or_throw(path);
  std::string text(static_cast<std::size_t>(size), '\0');
  f.read(text.data(), static_cast<std::streamsize>(size));
  text.resize(static_cast<std::size_t>(f.gcount()));
  if (f.bad()) io_error(path, "read error");
  return text;
}

std::string_view strip_utf8_bom(std::string_view text) {
  constexpr std::string_view kBom = "\xEF\xBB\xBF";
  if (text.starts_with(kBom)) text.remove_prefix(kBom.size());
  return text;
}

namespace {

// Counts bytes that cannot be text: C0 controls other than tab, LF, CR, FF, and bytes that do not form UTF-8.
// Decoding stops short of the end of `head`, which may cut a multi-byte character in two.
std::size_t count_non_text(std::string_view head) {
  std::size_t bad = 0;
  std::size_t i = 0;
  while (i < head.size()) {
    const auto b = static_cast<unsigned char>(head[i]);
    if (b < 0x80) {
      if (b < 0x20 && b != '\t' && b != '\n' && b != '\r' && b != '\f') ++bad;
      if (b == 0x7F) ++bad;
      ++i;
      continue;
    }
    const std::size_t len = b >= 0xF0 && b <= 0xF4 ? 4 : b >= 0xE0 ? 3 : b >= 0xC2 && b <= 0xDF ? 2 : 0;
    if (len == 0) {
      ++bad;
      ++i;
      continue;
    }
    if (i + len > head.size()) break;  // cut at the end of the head
    bool ok = true;
    for (std::size_t k = 1; k < len; ++k) ok = ok && (static_cast<unsigned char>(head[i + k]) & 0xC0) == 0x80;
    if (!ok) {
      ++bad;
      ++i;
      continue;
    }
    i += len;
  }
  return bad;
}

// UTF-16 text without a byte-order mark has a NUL in every other byte (ASCII characters); UTF-32 in three of four.
std::string_view wide_encoding(std::string_view head) {
  if (head.size() < 8) return {};
  std::size_t nul_at[4] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < head.size(); ++i)
    if (head[i] == '\0') ++nul_at[i % 4];
  const std::size_t per_slot = head.size() / 4;
  auto mostly = [&](std::size_t slot) { return nul_at[slot] * 10 >= per_slot * 9; };
  auto rarely = [&](std::size_t slot) { return nul_at[slot] * 10 <= per_slot; };
  const int nul_slots = mostly(0) + mostly(1) + mostly(2) + mostly(3);
  const int text_slots = rarely(0) + rarely(1) + rarely(2) + rarely(3);
  if (nul_slots == 3 && text_slots == 1) return "UTF-32";
  if (nul_slots == 2 && text_slots == 2 && mostly(0) == mostly(2) && mostly(1) == mostly(3)) return "UTF-16";
  return {};
}

}  // namespace

void check_text(std::string_view head, const std::string& path) {
  const ErrorLocation at{path, 0, 0, {}};
  // Byte-order marks first: UTF-32 LE starts with the UTF-16 LE mark, so test the longer ones first.
  constexpr std::string_view utf32_le("\xFF\xFE\0\0", 4);
  constexpr std::string_view utf32_be("\0\0\xFE\xFF", 4);
  if (head.starts_with(utf32_le) || head.starts_with(utf32_be))
    throw ImportError(ImportErrorCategory::Encoding, at, "file is UTF-32 (byte-order mark); save it as UTF-8");
  if (head.starts_with("\xFF\xFE") || head.starts_with("\xFE\xFF"))
    throw ImportError(ImportErrorCategory::Encoding, at, "file is UTF-16 (byte-order mark); save it as UTF-8");
  const std::string_view body = strip_utf8_bom(head);
  if (body.find_first_not_of(" \t\r\n\f\v") == std::string_view::npos)
    throw ImportError(ImportErrorCategory::Empty, at,
                      head.empty() ? "file is empty (0 bytes)" : "file holds only whitespace");
  const std::size_t nul = body.find('\0');
  if (nul != std::string_view::npos) {
    if (const std::string_view wide = wide_encoding(body); !wide.empty())
      throw ImportError(ImportErrorCategory::Encoding, at,
                        "file looks like " + std::string(wide) + " without a byte-order mark; save it as UTF-8");
    throw ImportError(ImportErrorCategory::Binary, at,
                      "file is binary (NUL byte at offset " + std::to_string(nul + (head.size() - body.size())) +
                          "), not a text format");
  }
  // Text in another 8-bit encoding (a stray Latin-1 "µ") still imports; a file mostly made of non-text does not.
  const std::size_t bad = count_non_text(body);
  if (bad * 10 > body.size())
    throw ImportError(ImportErrorCategory::Binary, at,
                      "file is not text (" + std::to_string(bad) + " of the first " + std::to_string(body.size()) +
                          " bytes are control codes or invalid UTF-8)");
}

}  // namespace bs
