// SPDX-License-Identifier: GPL-3.0-or-later
#include "sensors/discovery.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "sensors/hwmon.h"
#include "sensors/ina3221.h"
#include "sensors/nvml.h"
#include "sensors/rapl.h"

namespace bs::sensors {
namespace {

// The packages of a multi-socket machine as one counter: the sum of their energies is the total, and each
// package stays its own channel beside it.
class EnergySum final : public Sensor {
 public:
  explicit EnergySum(std::vector<Sensor*> parts) : parts_(std::move(parts)) {
    info_.id = "rapl:packages";
    info_.kind = SensorKind::Rapl;
    info_.label = "packages";
    info_.device = "sum of " + std::to_string(parts_.size()) + " RAPL packages";
    for (const Sensor* p : parts_) info_.source += (info_.source.empty() ? "" : " + ") + p->info().source;
    info_.quantity = SensorQuantity::Energy;
    info_.unit = "uJ";
    info_.readable = true;
    info_.board_total = true;
  }
  // The parts return joules since their own first read (wraps added back), so their sum is the total's; a part
  // that is also recorded as its own channel is simply read twice per sample.
  std::optional<double> read() override {
    double sum = 0;
    for (Sensor* p : parts_) {
      const auto v = p->read();
      if (!v) return std::nullopt;
      sum += *v;
    }
    return sum;
  }

 private:
  std::vector<Sensor*> parts_;
};

void append(std::vector<std::unique_ptr<Sensor>>& to, std::vector<std::unique_ptr<Sensor>> from) {
  for (auto& s : from) to.push_back(std::move(s));
}

std::unique_ptr<Sensor> take(SensorSet& set, Sensor* which) {
  for (auto& s : set.sensors)
    if (s.get() == which) {
      auto out = std::move(s);
      std::erase(set.sensors, nullptr);
      return out;
    }
  return nullptr;
}

std::string ids_of(const SensorSet& set) {
  std::string ids;
  for (const auto& s : set.sensors) ids += (ids.empty() ? "" : ", ") + s->info().id;
  return ids.empty() ? "none" : ids;
}

}  // namespace

std::string default_nvml_library() {
  if (const char* env = std::getenv("BENCHSCOPE_NVML_LIBRARY")) {
    const std::string v = env;
    return v == "none" ? std::string() : v;
  }
  return "libnvidia-ml.so.1";
}

SensorSet find_sensors(const DiscoveryOptions& options) {
  SensorSet set;
  append(set.sensors, find_rapl(options.root));
  append(set.sensors, find_ina3221(options.root));
  append(set.sensors, find_hwmon(options.root));
  if (!options.nvml_library.empty()) {
    NvmlProbe nvml = find_nvml(options.nvml_library);
    append(set.sensors, std::move(nvml.sensors));
    if (!nvml.problem.empty()) set.notes.push_back("NVML: " + nvml.problem);
  }
  return set;
}

Selection select_sensors(SensorSet& set, const std::string& spec) {
  Selection sel;
  if (spec != "auto") {
    std::size_t start = 0;
    while (start <= spec.size()) {
      const auto comma = spec.find(',', start);
      const std::string id = spec.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      start = comma == std::string::npos ? spec.size() + 1 : comma + 1;
      if (id.empty()) continue;
      const auto it =
          std::find_if(set.sensors.begin(), set.sensors.end(), [&](const auto& s) { return s && s->info().id == id; });
      if (it == set.sensors.end())
        throw std::invalid_argument("no sensor '" + id + "' (sensors here: " + ids_of(set) + ")");
      if (!(*it)->info().readable)
        throw std::invalid_argument("sensor '" + id + "' cannot be read: " + (*it)->info().reason);
      sel.sensors.push_back(take(set, it->get()));
    }
    if (sel.sensors.empty()) throw std::invalid_argument("--sensor: no sensor id given");
    sel.note = "sensor " + sel.sensors.front()->info().id + " as given";
    return sel;
  }
  const auto readable = [](const std::unique_ptr<Sensor>& s, SensorKind kind) {
    return s && s->info().readable && s->info().kind == kind;
  };
  // 1. A Jetson's input rail, with the other rails of its board beside it (never added to it).
  for (auto& s : set.sensors) {
    if (!readable(s, SensorKind::Ina3221) || !s->info().board_total) continue;
    sel.sensors.push_back(take(set, s.get()));
    for (auto& r : set.sensors)
      if (readable(r, SensorKind::Ina3221)) sel.sensors.push_back(std::move(r));
    std::erase(set.sensors, nullptr);
    sel.note =
        "INA3221 input rail " + sel.sensors.front()->info().label + " (the board's total; other rails beside it)";
    return sel;
  }
  // 2. RAPL: psys (the whole SoC platform) when there is one, else the package(s); sub-zones beside it.
  std::vector<Sensor*> packages;
  Sensor* psys = nullptr;
  for (auto& s : set.sensors) {
    if (!readable(s, SensorKind::Rapl) || !s->info().board_total) continue;
    if (s->info().label == "psys")
      psys = s.get();
    else
      packages.push_back(s.get());
  }
  if (psys || !packages.empty()) {
    if (psys) {
      sel.sensors.push_back(take(set, psys));
      sel.note = "RAPL psys (the platform's total as the processor sees it)";
    } else if (packages.size() == 1) {
      sel.sensors.push_back(take(set, packages.front()));
      sel.note = "RAPL " + sel.sensors.front()->info().label + " (the processor package; not the rest of the board)";
    } else {
      // A sum sensor reading the package counters through their own objects, which are recorded too.
      std::vector<Sensor*> parts = packages;
      sel.sensors.push_back(std::make_unique<EnergySum>(parts));
      for (Sensor* p : packages) sel.sensors.push_back(take(set, p));
      sel.note = "sum of " + std::to_string(packages.size()) + " RAPL packages (not the rest of the board)";
    }
    for (auto& r : set.sensors)
      if (readable(r, SensorKind::Rapl)) sel.sensors.push_back(std::move(r));
    std::erase(set.sensors, nullptr);
    return sel;
  }
  // 3. A GPU board through NVML, 4. any hwmon power or energy file.
  for (SensorKind kind : {SensorKind::Nvml, SensorKind::Hwmon})
    for (auto& s : set.sensors)
      if (readable(s, kind)) {
        sel.sensors.push_back(take(set, s.get()));
        sel.note = std::string(to_string(kind)) + " " + sel.sensors.front()->info().label +
                   " (no board or package total on this machine; this sensor only)";
        return sel;
      }
  std::string why;
  for (const auto& s : set.sensors)
    if (!s->info().readable) why += "\n  " + s->info().id + ": " + s->info().reason;
  throw std::invalid_argument(set.sensors.empty() ? "no power sensors found" : "no readable power sensor:" + why);
}

std::string_view to_string(SensorKind kind) {
  switch (kind) {
    case SensorKind::Rapl:
      return "rapl";
    case SensorKind::Ina3221:
      return "ina3221";
    case SensorKind::Hwmon:
      return "hwmon";
    case SensorKind::Nvml:
      return "nvml";
  }
  return "unknown";
}

}  // namespace bs::sensors
