// SPDX-License-Identifier: GPL-3.0-or-later
#include "util/resources.h"

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <system_error>

// Set for this file alone by core/CMakeLists.txt (so the absolute path does not spoil ccache hits of the others).
#ifndef BENCHSCOPE_SOURCE_RESOURCES
#define BENCHSCOPE_SOURCE_RESOURCES ""
#endif
#ifndef BENCHSCOPE_INSTALL_RESOURCES
#define BENCHSCOPE_INSTALL_RESOURCES "share/benchscope/resources"
#endif
#ifndef BENCHSCOPE_CONFIGURED_PUBLIC_DATA
#define BENCHSCOPE_CONFIGURED_PUBLIC_DATA ""
#endif

namespace bs {
namespace fs = std::filesystem;

namespace {

// The running executable's directory; empty where /proc is not mounted (then only the other places are tried).
fs::path executable_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec || exe.empty()) return {};
  return exe.parent_path();
}

void add_if_dir(std::vector<fs::path>& dirs, const fs::path& dir) {
  std::error_code ec;
  if (dir.empty() || !fs::is_directory(dir, ec)) return;
  const fs::path canonical = fs::weakly_canonical(dir, ec);
  const fs::path& d = ec ? dir : canonical;
  for (const fs::path& seen : dirs)
    if (seen == d) return;
  dirs.push_back(d);
}

}  // namespace

std::vector<fs::path> resource_search_dirs() {
  std::vector<fs::path> dirs;
  if (const char* env = std::getenv("BENCHSCOPE_RESOURCE_DIR"); env && *env) add_if_dir(dirs, fs::path(env));
  if (const fs::path exe = executable_dir(); !exe.empty())
    add_if_dir(dirs, exe.parent_path() / BENCHSCOPE_INSTALL_RESOURCES);
  add_if_dir(dirs, fs::path(BENCHSCOPE_SOURCE_RESOURCES));
  return dirs;
}

fs::path find_resource(std::string_view relative) {
  const std::vector<fs::path> dirs = resource_search_dirs();
  std::error_code ec;
  for (const fs::path& dir : dirs) {
    fs::path candidate = dir / fs::path(relative);
    if (fs::is_regular_file(candidate, ec)) return candidate;
  }
  std::string tried;
  for (const fs::path& dir : dirs) tried += (tried.empty() ? "" : ", ") + dir.string();
  throw std::runtime_error("resource " + std::string(relative) + " not found (searched: " +
                           (tried.empty() ? std::string("no resource directory exists") : tried) +
                           "; set BENCHSCOPE_RESOURCE_DIR to the resources/ folder)");
}

fs::path public_data_dir() {
  if (const char* env = std::getenv("BENCHSCOPE_PUBLIC_DATA_DIR"); env && *env) return fs::path(env);
  return fs::path(BENCHSCOPE_CONFIGURED_PUBLIC_DATA);
}

}  // namespace bs
