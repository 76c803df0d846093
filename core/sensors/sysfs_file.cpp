// SPDX-License-Identifier: GPL-3.0-or-later
#include "sensors/sysfs_file.h"

#include <fcntl.h>
#include <unistd.h>
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>

namespace bs::sensors {

FileRead read_sysfs(const std::filesystem::path& file) {
  FileRead out;
  // open/read rather than iostreams: one syscall each, errno kept, and a sysfs attribute is at most a page.
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    out.error = errno;
    return out;
  }
  char buf[4096];
  const ssize_t n = ::read(fd, buf, sizeof buf);
  out.error = n < 0 ? errno : 0;
  ::close(fd);
  if (n > 0) out.text.assign(buf, static_cast<std::size_t>(n));
  while (!out.text.empty() && (out.text.back() == '\n' || out.text.back() == ' ' || out.text.back() == '\r' ||
                               out.text.back() == '\t' || out.text.back() == '\0'))
    out.text.pop_back();
  return out;
}

std::optional<long long> read_sysfs_integer(const std::filesystem::path& file, int* error) {
  const FileRead r = read_sysfs(file);
  if (!r.ok()) {
    if (error) *error = r.error;
    return std::nullopt;
  }
  std::string_view t = r.text;
  while (!t.empty() && t.front() == ' ') t.remove_prefix(1);
  long long v = 0;
  const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc() || ptr != t.data() + t.size() || t.empty()) {
    if (error) *error = EINVAL;
    return std::nullopt;
  }
  if (error) *error = 0;
  return v;
}

std::filesystem::path under_root(const std::filesystem::path& root, std::string_view sys_path) {
  while (!sys_path.empty() && sys_path.front() == '/') sys_path.remove_prefix(1);
  return root / std::filesystem::path(sys_path);
}

namespace {

// "hwmon10" after "hwmon2", "intel-rapl:1:0" after "intel-rapl:0:1": runs of digits compare by value.
bool natural_less(const std::string& a, const std::string& b) {
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    const bool da = a[i] >= '0' && a[i] <= '9', db = b[j] >= '0' && b[j] <= '9';
    if (da && db) {
      std::size_t ie = i, je = j;
      while (ie < a.size() && a[ie] >= '0' && a[ie] <= '9') ++ie;
      while (je < b.size() && b[je] >= '0' && b[je] <= '9') ++je;
      const std::string_view na(a.data() + i, ie - i), nb(b.data() + j, je - j);
      if (na.size() != nb.size()) return na.size() < nb.size();
      if (na != nb) return na < nb;
      i = ie;
      j = je;
      continue;
    }
    if (a[i] != b[j]) return a[i] < b[j];
    ++i;
    ++j;
  }
  return a.size() - i < b.size() - j;
}

}  // namespace

std::vector<std::filesystem::path> entries_with_prefix(const std::filesystem::path& dir, std::string_view prefix) {
  std::vector<std::filesystem::path> out;
  std::error_code ec;
  std::filesystem::directory_iterator it(dir, ec), end;
  for (; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.starts_with(prefix)) out.push_back(it->path());
  }
  std::sort(out.begin(), out.end(),
            [](const auto& a, const auto& b) { return natural_less(a.filename().string(), b.filename().string()); });
  return out;
}

std::string describe_error(int error) {
  if (error == EACCES || error == EPERM) return "permission denied (readable by root only)";
  if (error == EINVAL) return "not a number";
  return std::strerror(error);
}

}  // namespace bs::sensors
