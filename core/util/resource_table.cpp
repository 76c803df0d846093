// SPDX-License-Identifier: GPL-3.0-or-later
#include "util/resource_table.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace bs {

void resource_table_fail(const std::string& origin, const std::string& where, const std::string& why) {
  throw std::runtime_error(origin + ": " + where + ": " + why);
}

nlohmann::json resource_table_entries(std::string_view json_text, const std::string& origin, std::string_view format,
                                      const std::string& entries_key) {
  using nlohmann::json;
  json doc;
  try {
    doc = json::parse(json_text);
  } catch (const json::parse_error& e) {
    resource_table_fail(origin, "JSON", e.what());
  }
  if (!doc.is_object() || doc.value("format", "") != format)
    resource_table_fail(origin, "format", "not a " + std::string(format) + " file");
  if (doc.value("version", 0) != 1)
    resource_table_fail(origin, "version", "unsupported (this BenchScope reads version 1)");
  const auto entries = doc.find(entries_key);
  if (entries == doc.end() || !entries->is_array()) resource_table_fail(origin, entries_key, "missing or not an array");
  return std::move(*entries);
}

std::string resource_table_string(const nlohmann::json& entry, const char* key, const std::string& origin,
                                  const std::string& where) {
  const auto it = entry.find(key);
  if (it == entry.end() || !it->is_string() || it->get<std::string>().empty())
    resource_table_fail(origin, where + "." + key, "missing or not a non-empty string");
  return it->get<std::string>();
}

std::vector<std::string> resource_table_strings(const nlohmann::json& entry, const char* key, const std::string& origin,
                                                const std::string& where) {
  std::vector<std::string> out;
  const auto it = entry.find(key);
  if (it == entry.end()) return out;
  if (!it->is_array()) resource_table_fail(origin, where + "." + key, "not an array");
  for (const nlohmann::json& v : *it) {
    if (!v.is_string() || v.get<std::string>().empty())
      resource_table_fail(origin, where + "." + key, "an element is not a non-empty string");
    out.push_back(v.get<std::string>());
  }
  return out;
}

std::string read_resource_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace bs
