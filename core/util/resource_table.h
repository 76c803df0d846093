// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The bundled data tables (resources/devices/devices.json, cpu-cores.json) share one envelope:
// {"format": "<name>", "version": 1, "<entries>": [...]}. One reader checks it, so every table refuses a wrong file
// with the same words: "<origin>: <field>: <reason>" as std::runtime_error.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace bs {

[[noreturn]] void resource_table_fail(const std::string& origin, const std::string& where, const std::string& why);

// The array under `entries_key` of a version-1 document of `format`; throws naming `origin` otherwise.
nlohmann::json resource_table_entries(std::string_view json_text, const std::string& origin, std::string_view format,
                                      const std::string& entries_key);

// Calls `each(entry, where)` for every entry of the array under `entries_key` (checked as resource_table_entries
// does), `where` naming it for messages ("devices[3]"); an entry that is not an object throws. The one loop every
// table's parser runs, so that they all name their entries alike.
template <class Each>
void for_each_resource_entry(std::string_view json_text, const std::string& origin, std::string_view format,
                             const std::string& entries_key, Each each) {
  const nlohmann::json entries = resource_table_entries(json_text, origin, format, entries_key);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const std::string where = entries_key + "[" + std::to_string(i) + "]";
    if (!entries[i].is_object()) resource_table_fail(origin, where, "not an object");
    each(entries[i], where);
  }
}

// The non-empty string `entry[key]`; throws naming `where.key` when it is missing, not a string or empty.
std::string resource_table_string(const nlohmann::json& entry, const char* key, const std::string& origin,
                                  const std::string& where);

// The non-empty strings of the array `entry[key]` (none when absent); throws naming `where.key` otherwise. The tables'
// lists of more source URLs and of unverified fields.
std::vector<std::string> resource_table_strings(const nlohmann::json& entry, const char* key, const std::string& origin,
                                                const std::string& where);

// The whole file as text; throws "<path>: cannot open".
std::string read_resource_file(const std::filesystem::path& path);

}  // namespace bs
