// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli sensors: every power sensor of this computer, readable or why not.
#include <nlohmann/json.hpp>
#include <ostream>

#include "commands/inventory_grammar.h"
#include "common/args.h"
#include "common/command.h"
#include "common/text_table.h"
#include "sensors/discovery.h"
#include "sensors/sysfs_file.h"

namespace bs::cli {
namespace {

int sensors_command(const std::vector<std::string>& raw, std::ostream& out, std::ostream&) {
  const commands::SensorsSettings args = commands::sensors_from_words(raw);
  const std::string root = args.sysfs_root.value_or("/");
  const sensors::SensorSet set = sensors::find_sensors({root, sensors::default_nvml_library()});
  if (args.json) {
    nlohmann::json j = {{"sysfs_root", root}, {"sensors", nlohmann::json::array()}, {"notes", set.notes}};
    for (const auto& s : set.sensors) {
      const sensors::SensorInfo& i = s->info();
      j["sensors"].push_back({{"id", i.id},
                              {"kind", std::string(to_string(i.kind))},
                              {"label", i.label},
                              {"device", i.device},
                              {"source", i.source},
                              {"quantity", i.quantity == sensors::SensorQuantity::Energy ? "energy" : "power"},
                              {"unit", i.unit},
                              {"board_total", i.board_total},
                              {"readable", i.readable},
                              {"reason", i.reason}});
    }
    out << j.dump(2) << '\n';
    return 0;
  }
  if (set.sensors.empty()) {
    const auto at = [&](const char* sys) { return sensors::under_root(root, sys).string(); };
    out << "no power sensors found (looked for RAPL in " << at("/sys/class/powercap") << ", INA3221 in "
        << at("/sys/bus/i2c/drivers/ina3221") << "{,x}, hwmon in " << at("/sys/class/hwmon") << ")\n";
    for (const auto& n : set.notes) out << n << '\n';
    return 0;
  }
  TextTable table({"id", "kind", "rail/label", "device", "unit", "total", "status"});
  std::string reasons;  // below the table, so one long reason does not stretch every row
  for (const auto& s : set.sensors) {
    const sensors::SensorInfo& i = s->info();
    table.add({i.id, std::string(to_string(i.kind)), i.label, i.device, i.unit, i.board_total ? "yes" : "",
               i.readable ? "readable" : "NOT READABLE (below)"});
    if (!i.readable) reasons += i.id + ": " + i.reason + "\n";
  }
  table.print(out);
  out << reasons;
  for (const auto& n : set.notes) out << n << '\n';
  return 0;
}

const CommandRegistrar registrar({
    "sensors",
    "list this computer's power sensors (RAPL, Jetson INA3221, hwmon, NVML) and whether they can be read",
    "usage: benchscope-cli sensors [--sysfs-root DIR] [--json]\n"
    "  RAPL (sys/class/powercap/intel-rapl:*), Jetson INA3221 (JetPack 5+ hwmon and JetPack 4 ina3221x), hwmon\n"
    "  power*/energy* files and NVIDIA GPUs through NVML (libnvidia-ml.so.1, loaded if present). Each with its id\n"
    "  (for --sensor / --power), kind, rail, unit, whether it is the board's or package's total, and readable or\n"
    "  why not. --sysfs-root reads another tree (a container's bind mount of the host's /sys, a test fixture).\n"
    "  Exit 0 also when there are none (\"no power sensors found\"). BENCHSCOPE_NVML_LIBRARY=none skips NVML.",
    [](const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
      try {
        return sensors_command(args, out, err);
      } catch (const UsageError& e) {
        err << "benchscope-cli: error: " << e.what() << "\n(see benchscope-cli help sensors)\n";
        return 2;
      }
    },
});

}  // namespace
}  // namespace bs::cli
