// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Small sysfs text files: read whole (they are a few bytes), parsed as one integer or one trimmed line. Errors
// keep errno so callers can tell "root only" (EACCES) from "not there" (ENOENT).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace bs::sensors {

struct FileRead {
  std::string text;  // trimmed of trailing whitespace
  int error = 0;     // errno of the failed open/read; 0 on success
  bool ok() const { return error == 0; }
};

FileRead read_sysfs(const std::filesystem::path& file);
// A decimal integer file ("123456\n"); empty on an error or junk, `error` set to errno (EINVAL for junk).
std::optional<long long> read_sysfs_integer(const std::filesystem::path& file, int* error = nullptr);
// `root` + an absolute-looking sysfs path ("/sys/class/powercap"): joined so that root "/" gives the path itself.
std::filesystem::path under_root(const std::filesystem::path& root, std::string_view sys_path);
// Entries of `dir` whose name starts with `prefix`, sorted by name with numbers compared as numbers
// (hwmon2 before hwmon10). Missing folder: empty.
std::vector<std::filesystem::path> entries_with_prefix(const std::filesystem::path& dir, std::string_view prefix);
// Why a file could not be read, in words: "permission denied (readable by root only)", strerror otherwise.
std::string describe_error(int error);

}  // namespace bs::sensors
