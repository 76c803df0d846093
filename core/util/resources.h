// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where bundled data files (resources/: figure templates, the device table, JSON Schemas) are found at run time,
// the same way for the CLI, the GUI and the tests, from a build tree and from an installed copy.
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

}  // namespace bs
