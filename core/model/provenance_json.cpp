// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/provenance_json.h"

namespace bs {

nlohmann::json provenance_to_json(const Provenance& p, bool with_source_file) {
  nlohmann::json j = {{"origin", std::string(to_string(p.origin))},
                      {"host", p.host},
                      {"cpu_model", p.cpu_model},
                      {"gpu_model", p.gpu_model},
                      {"os", p.os},
                      {"compiler", p.compiler},
                      {"tool", p.tool},
                      {"git_revision", p.git_revision},
                      {"date", p.date},
                      {"note", p.note}};
  if (with_source_file) j["source_file"] = p.source_file;
  // Written only when set, so that run files without power data keep their exact earlier form.
  if (p.measurement != MeasurementKind::Unknown) j["measurement"] = std::string(to_string(p.measurement));
  if (!p.sensor.empty()) j["sensor"] = p.sensor;
  if (!p.settings.empty()) {
    nlohmann::json settings = nlohmann::json::array();
    for (const auto& [key, value] : p.settings) settings.push_back({key, value});
    j["settings"] = std::move(settings);
  }
  return j;
}

Provenance provenance_from_json(const nlohmann::json& j) {
  Provenance p;
  if (!j.is_object()) return p;
  auto get = [&](const char* key) {
    const auto it = j.find(key);
    return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
  };
  p.origin = data_origin_from_string(get("origin"));
  p.host = get("host");
  p.cpu_model = get("cpu_model");
  p.gpu_model = get("gpu_model");
  p.os = get("os");
  p.compiler = get("compiler");
  p.tool = get("tool");
  p.git_revision = get("git_revision");
  p.date = get("date");
  p.note = get("note");
  p.source_file = get("source_file");
  p.measurement = measurement_kind_from_string(get("measurement"));
  p.sensor = get("sensor");
  if (const auto it = j.find("settings"); it != j.end() && it->is_array())
    for (const auto& kv : *it)
      if (kv.is_array() && kv.size() == 2 && kv[0].is_string() && kv[1].is_string())
        p.settings.emplace_back(kv[0].get<std::string>(), kv[1].get<std::string>());
  return p;
}

}  // namespace bs
