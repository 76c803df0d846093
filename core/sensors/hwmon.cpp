// SPDX-License-Identifier: GPL-3.0-or-later
#include "sensors/hwmon.h"

#include <algorithm>
#include <regex>

#include "sensors/sysfs_file.h"

namespace bs::sensors {
namespace {

class HwmonSensor final : public Sensor {
 public:
  HwmonSensor(const std::filesystem::path& root, const std::filesystem::path& file, const std::string& hwmon,
              const std::string& chip, const std::string& attr, const std::string& label, bool energy)
      : file_(file) {
    info_.id = "hwmon:" + hwmon + ":" + attr;
    info_.kind = SensorKind::Hwmon;
    info_.label = label.empty() ? attr : label;
    info_.device = chip.empty() ? hwmon : hwmon + " (" + chip + ")";
    info_.source = "/" + std::filesystem::relative(file, root).string();
    info_.quantity = energy ? SensorQuantity::Energy : SensorQuantity::Power;
    info_.unit = energy ? "uJ" : "uW";
    int err = 0;
    if (read_sysfs_integer(file_, &err))
      info_.readable = true;
    else
      info_.reason = describe_error(err);
  }
  std::optional<double> read() override {
    const auto v = read_sysfs_integer(file_);
    if (!v) return std::nullopt;
    if (info_.quantity == SensorQuantity::Power) return static_cast<double>(*v) * 1e-6;
    // hwmon energy counters are 64-bit and do not wrap in practice; one going down was reset (driver reload):
    // go on from the new value instead of subtracting across the reset.
    if (last_ >= 0 && *v >= last_) total_ += *v - last_;
    last_ = *v;
    return static_cast<double>(total_) * 1e-6;
  }

 private:
  std::filesystem::path file_;
  long long last_ = -1, total_ = 0;
};

}  // namespace

std::vector<std::unique_ptr<Sensor>> find_hwmon(const std::filesystem::path& root) {
  std::vector<std::unique_ptr<Sensor>> out;
  static const std::regex attr_re(R"((power|energy)(\d+)_(input|average))");
  for (const auto& dir : entries_with_prefix(under_root(root, "/sys/class/hwmon"), "hwmon")) {
    const std::string hwmon = dir.filename().string();
    const FileRead chip = read_sysfs(dir / "name");
    // The INA3221 on a Jetson is also a hwmon device; find_ina3221 reads it with its rail names.
    if (chip.ok() && chip.text == "ina3221") continue;
    std::vector<std::filesystem::path> files;
    for (const auto& f : entries_with_prefix(dir, "")) {
      std::smatch m;
      const std::string name = f.filename().string();
      if (!std::regex_match(name, m, attr_re)) continue;
      files.push_back(f);
    }
    for (const auto& f : files) {
      const std::string name = f.filename().string();
      std::smatch m;
      std::regex_match(name, m, attr_re);
      const std::string attr = m[1].str() + m[2].str();  // "power1"
      // power1_average and power1_input of one channel: keep the instantaneous one.
      if (m[3] == "average" &&
          std::any_of(files.begin(), files.end(), [&](const auto& g) { return g.filename() == attr + "_input"; }))
        continue;
      const FileRead label = read_sysfs(dir / (attr + "_label"));
      const std::string id_attr = m[3] == "average" ? attr + "_average" : attr;
      out.push_back(std::make_unique<HwmonSensor>(root, f, hwmon, chip.ok() ? chip.text : std::string(), id_attr,
                                                  label.ok() ? label.text : std::string(), m[1] == "energy"));
    }
  }
  return out;
}

}  // namespace bs::sensors
