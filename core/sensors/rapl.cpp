// SPDX-License-Identifier: GPL-3.0-or-later
#include "sensors/rapl.h"

#include "sensors/sysfs_file.h"

namespace bs::sensors {

std::optional<long long> counter_delta(long long last, long long now, long long max_range) {
  if (now >= last) return now - last;
  if (max_range <= 0 || last > max_range) return std::nullopt;
  // The counter ran from `last` up to max_range, wrapped to 0, and went on to `now`.
  return (max_range - last) + now;
}

RaplSensor::RaplSensor(const std::filesystem::path& root, const std::filesystem::path& zone, std::string id_name,
                       std::string name, bool top_level)
    : energy_file_(zone / "energy_uj") {
  info_.id = "rapl:" + id_name;
  info_.kind = SensorKind::Rapl;
  info_.label = name;
  info_.device = zone.filename().string();
  info_.source = "/" + std::filesystem::relative(energy_file_, root).string();
  info_.quantity = SensorQuantity::Energy;
  info_.unit = "uJ";
  // The package (or psys, the whole SoC platform) is the total; core/uncore/dram are parts of a package.
  info_.board_total = top_level;
  int err = 0;
  if (const auto max = read_sysfs_integer(zone / "max_energy_range_uj", &err)) max_range_uj_ = *max;
  if (read_sysfs_integer(energy_file_, &err)) {
    info_.readable = true;
  } else if (err == EACCES || err == EPERM) {
    info_.reason =
        "energy_uj is readable by root only (kernels since 2020, CVE-2020-8694): run as root, or "
        "`sudo chmod o+r /sys/class/powercap/intel-rapl:*/energy_uj /sys/class/powercap/intel-rapl:*:*/energy_uj` "
        "(until reboot; a udev rule makes it permanent)";
  } else {
    info_.reason = "energy_uj: " + describe_error(err);
  }
}

std::optional<double> RaplSensor::read() {
  const auto now = read_sysfs_integer(energy_file_);
  if (!now) return std::nullopt;
  if (last_uj_ >= 0) {
    const auto delta = counter_delta(last_uj_, *now, max_range_uj_);
    if (!delta) {
      last_uj_ = *now;  // a counter reset we cannot size: start again from here, this reading is lost
      return std::nullopt;
    }
    total_uj_ += static_cast<double>(*delta);
  }
  last_uj_ = *now;
  return total_uj_ * 1e-6;
}

std::vector<std::unique_ptr<Sensor>> find_rapl(const std::filesystem::path& root) {
  std::vector<std::unique_ptr<Sensor>> out;
  const auto base = under_root(root, "/sys/class/powercap");
  // "intel-rapl" alone is the control type, not a zone; "intel-rapl:0" a package, "intel-rapl:0:1" its sub-zone.
  for (const auto& zone : entries_with_prefix(base, "intel-rapl:")) {
    const std::string dir = zone.filename().string();
    const bool top = dir.find(':') == dir.rfind(':');
    if (!top) continue;
    const FileRead name = read_sysfs(zone / "name");
    const std::string zone_name = name.ok() && !name.text.empty() ? name.text : dir;
    out.push_back(std::make_unique<RaplSensor>(root, zone, zone_name, zone_name, true));
    for (const auto& sub : entries_with_prefix(base, dir + ":")) {
      const FileRead sub_name = read_sysfs(sub / "name");
      const std::string n = sub_name.ok() && !sub_name.text.empty() ? sub_name.text : sub.filename().string();
      out.push_back(std::make_unique<RaplSensor>(root, sub, zone_name + "/" + n, zone_name + " " + n, false));
    }
  }
  return out;
}

}  // namespace bs::sensors
