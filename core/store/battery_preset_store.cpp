// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/battery_preset_store.h"

#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace bs {
namespace {

constexpr const char* kPrefix = "battery-preset/";

void check(const BatterySetup& s) {
  const BatteryPack& p = s.pack;
  const auto bad = [&](const std::string& what) {
    throw std::invalid_argument("battery preset '" + p.name + "': " + what);
  };
  if (p.name.empty()) throw std::invalid_argument("battery preset: empty name");
  if (p.cells_series < 1 || p.cells_series > 100) bad("cells_series must be 1..100");
  if (!(p.capacity_ah > 0 && p.capacity_ah < 1e4)) bad("capacity must be > 0 Ah");
  if (!(p.nominal_cell_v > 0 && p.nominal_cell_v < 10)) bad("nominal cell voltage must be in (0, 10) V");
  if (!(p.internal_resistance_ohm >= 0 && p.internal_resistance_ohm < 100)) bad("internal resistance must be >= 0");
  if (!(p.cutoff_cell_v >= 0 && p.cutoff_cell_v < 4.2)) bad("cut-off cell voltage must be in [0, 4.2) V");
  if (!(s.depth_of_discharge > 0 && s.depth_of_discharge <= 1)) bad("depth of discharge must be in (0, 1]");
  if (!(s.extra_load_w >= 0 && std::isfinite(s.extra_load_w))) bad("extra load must be >= 0 W");
  if (!s.mission.empty()) parse_mission(s.mission);  // throws std::invalid_argument with the reason
}

}  // namespace

std::vector<BatterySetup> builtin_battery_setups() {
  std::vector<BatterySetup> out;
  for (const BatteryPack& p : battery_presets()) out.push_back({p, 1.0, 0, BatteryModel::ConstantPower, {}, false});
  return out;
}

std::string battery_setup_to_json(const BatterySetup& s) {
  const BatteryPack& p = s.pack;
  nlohmann::json j{{"name", p.name},
                   {"description", p.description},
                   {"cells_series", p.cells_series},
                   {"capacity_ah", p.capacity_ah},
                   {"nominal_cell_v", p.nominal_cell_v},
                   {"internal_resistance_ohm", p.internal_resistance_ohm},
                   {"cutoff_cell_v", p.cutoff_cell_v},
                   {"depth_of_discharge", s.depth_of_discharge},
                   {"extra_load_w", s.extra_load_w},
                   {"model", std::string(to_string(s.model))},
                   {"mission", s.mission}};
  // A custom open-circuit curve is kept; an empty one means the typical LiPo curve.
  if (!p.ocv.empty()) {
    j["ocv"] = nlohmann::json::array();
    for (const OcvPoint& o : p.ocv) j["ocv"].push_back({o.soc, o.volts_per_cell});
  }
  return j.dump();
}

BatterySetup battery_setup_from_json(std::string_view text) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw std::invalid_argument("battery preset: not a JSON object");
  BatterySetup s;
  const auto number = [&](const char* key, double fallback) {
    if (!j.contains(key)) return fallback;
    if (!j[key].is_number())
      throw std::invalid_argument(std::string("battery preset: field '") + key + "' is not a number");
    return j[key].get<double>();
  };
  const auto text_field = [&](const char* key) {
    if (!j.contains(key)) return std::string();
    if (!j[key].is_string())
      throw std::invalid_argument(std::string("battery preset: field '") + key + "' is not a string");
    return j[key].get<std::string>();
  };
  s.pack.name = text_field("name");
  s.pack.description = text_field("description");
  const double cells = number("cells_series", 4);
  if (cells != std::floor(cells) || cells < 1 || cells > 100)
    throw std::invalid_argument("battery preset: field 'cells_series' must be a whole number 1..100");
  s.pack.cells_series = static_cast<int>(cells);
  s.pack.capacity_ah = number("capacity_ah", 0);
  s.pack.nominal_cell_v = number("nominal_cell_v", 3.7);
  s.pack.internal_resistance_ohm = number("internal_resistance_ohm", 0.04);
  s.pack.cutoff_cell_v = number("cutoff_cell_v", 3.3);
  s.depth_of_discharge = number("depth_of_discharge", 1.0);
  s.extra_load_w = number("extra_load_w", 0);
  const std::string model = text_field("model");
  if (model == "lipo")
    s.model = BatteryModel::Lipo;
  else if (model.empty() || model == "constant-power")
    s.model = BatteryModel::ConstantPower;
  else
    throw std::invalid_argument("battery preset: field 'model' must be constant-power or lipo");
  s.mission = text_field("mission");
  if (j.contains("ocv")) {
    if (!j["ocv"].is_array()) throw std::invalid_argument("battery preset: field 'ocv' is not an array");
    for (const auto& pt : j["ocv"]) {
      if (!pt.is_array() || pt.size() != 2 || !pt[0].is_number() || !pt[1].is_number())
        throw std::invalid_argument("battery preset: field 'ocv' needs [soc, volts] pairs");
      s.pack.ocv.push_back({pt[0].get<double>(), pt[1].get<double>()});
    }
  }
  check(s);
  return s;
}

void save_battery_setup(Workspace& ws, const BatterySetup& setup) {
  check(setup);
  ws.set_setting(kPrefix + setup.pack.name, battery_setup_to_json(setup));
}

void remove_battery_setup(Workspace& ws, std::string_view name) { ws.remove_setting(kPrefix + std::string(name)); }

std::vector<BatterySetup> workspace_battery_setups(const Workspace& ws, std::vector<std::string>* errors) {
  std::vector<BatterySetup> out;
  for (const auto& [key, value] : ws.settings(kPrefix)) {
    try {
      BatterySetup s = battery_setup_from_json(value);
      s.pack.name = key.substr(std::string_view(kPrefix).size());  // the key is the name
      s.from_workspace = true;
      out.push_back(std::move(s));
    } catch (const std::invalid_argument& e) {
      if (errors) errors->push_back(ws.path() + ": setting '" + key + "': " + e.what());
    }
  }
  return out;
}

std::vector<BatterySetup> all_battery_setups(const Workspace* ws, std::vector<std::string>* errors) {
  std::vector<BatterySetup> out = builtin_battery_setups();
  if (!ws) return out;
  for (BatterySetup& s : workspace_battery_setups(*ws, errors)) {
    bool replaced = false;
    for (BatterySetup& b : out)
      if (b.pack.name == s.pack.name) b = s, replaced = true;
    if (!replaced) out.push_back(std::move(s));
  }
  return out;
}

std::optional<BatterySetup> find_battery_setup(const Workspace* ws, std::string_view name) {
  for (BatterySetup& s : all_battery_setups(ws))
    if (s.pack.name == name) return s;
  return std::nullopt;
}

std::optional<BatterySetup> battery_tab_setup(const Workspace& ws) {
  constexpr const char* kKey = "battery-tab/current";  // widgets/power/battery_view.cpp writes it
  for (const auto& [key, json] : ws.settings(kKey)) {
    if (key != kKey) continue;
    try {
      return battery_setup_from_json(json);
    } catch (const std::exception&) {
      return std::nullopt;  // the Battery tab says why when it opens the workspace
    }
  }
  return std::nullopt;
}

}  // namespace bs
