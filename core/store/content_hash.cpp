// SPDX-License-Identifier: GPL-3.0-or-later
// 64-bit FNV-1a over a file's bytes: not cryptographic, only to recognise the same file imported twice. It is
// streamed, so a multi-gigabyte power log is hashed in constant memory.
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "store/open_workspaces.h"
#include "store/workspace.h"

namespace bs {
namespace {

constexpr std::uint64_t kFnvOffset = 14695981039346656037ull;
constexpr std::uint64_t kFnvPrime = 1099511628211ull;

std::uint64_t fnv1a(std::uint64_t h, const char* data, std::size_t size) {
  for (std::size_t i = 0; i < size; ++i) {
    h ^= static_cast<unsigned char>(data[i]);
    h *= kFnvPrime;
  }
  return h;
}

std::string hex(std::uint64_t h) {
  char out[17];
  std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(h));
  return out;
}

}  // namespace

std::string content_hash(std::string_view bytes) { return hex(fnv1a(kFnvOffset, bytes.data(), bytes.size())); }

std::string file_content_hash(const std::string& path) {
  refuse_open_workspace(path, "hashing");
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error(path + ": cannot read file to hash it");
  std::uint64_t h = kFnvOffset;
  std::vector<char> buf(std::size_t{1} << 16);
  while (f) {
    f.read(buf.data(), static_cast<std::streamsize>(buf.size()));
    h = fnv1a(h, buf.data(), static_cast<std::size_t>(f.gcount()));
  }
  // eof is the normal end; badbit (or failbit without eof, e.g. reading a directory) is a read error.
  if (f.bad() || !f.eof()) throw std::runtime_error(path + ": read error while hashing the file");
  return hex(h);
}

}  // namespace bs
