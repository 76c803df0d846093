// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where bundled data files (resources/: figure templates, the device table, JSON Schemas) are found at run time,
// the same way for the CLI, the GUI and the tests, from a build tree and from an installed copy.
#include <exception>
#include <filesystem>
#include <string_view>
#include <vector>

namespace bs {

// The directories searched, in order: $BENCHSCOPE_RESOURCE_DIR when set; <executable's dir>/../share/benchscope/
// resources (what `cmake --install` lays out); the source tree's resources/ this binary was configured from (a
// build directory, which never copies them). Only directories that exist are listed.
std::vector<std::filesystem::path> resource_search_dirs();

// The first existing <dir>/<relative> of resource_search_dirs(), e.g. find_resource("devices/devices.json").
// Throws std::runtime_error naming the file and every directory tried when none has it.
std::filesystem::path find_resource(std::string_view relative);

// A bundled file loaded once into a struct holding its value and an `error` (BundledLibrary, BundledDeviceTable): when
// `load` throws, the value stays empty and `error` says why, so that callers can say what they could not check
// instead of failing or staying silent.
template <class Bundled, class Value, class Load>
Bundled load_bundled(Value Bundled::*value, Load load) {
  Bundled b;
  try {
    b.*value = load();
  } catch (const std::exception& e) {
    b.error = e.what();
  }
  return b;
}

// The shared folder of third-party files (real outputs other people published, e.g. the library's kept sources
// under resources/library/sources/), which is never bundled with BenchScope (docs/third-party-data.md):
// $BENCHSCOPE_PUBLIC_DATA_DIR when set, else the folder this build was configured with (the CMake cache variable of
// that name). The folder may not exist: an installed copy has no third-party files unless a user points here.
std::filesystem::path public_data_dir();

}  // namespace bs
