// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// RAPL energy counters through the kernel's powercap interface (Intel since Sandy Bridge; AMD Zen through the
// same files since Linux 5.8): sys/class/powercap/intel-rapl:N (package-N, psys) and intel-rapl:N:M (core,
// uncore, dram) each hold `name`, `energy_uj` (a counter in microjoules) and `max_energy_range_uj` (where the
// counter wraps back to 0). Since the 2020 "Platypus" side channel (CVE-2020-8694) energy_uj is mode 0400 on
// most distributions: found, but readable by root only, and said so with the fix.
#include <filesystem>
#include <memory>
#include <vector>

#include "sensors/sensor.h"

namespace bs::sensors {

class RaplSensor final : public Sensor {
 public:
  // `zone` is the zone folder; `id_name` the name that makes the id unique ("package-0", "package-0/core").
  RaplSensor(const std::filesystem::path& root, const std::filesystem::path& zone, std::string id_name,
             std::string name, bool top_level);
  std::optional<double> read() override;

 private:
  std::filesystem::path energy_file_;
  long long max_range_uj_ = 0;  // 0: unknown (a counter going down is then a read error, not a wrap)
  long long last_uj_ = -1;
  double total_uj_ = 0;  // since the first read, wraparounds added back
};

// Every RAPL zone under `root`, packages first, sub-zones after their package.
std::vector<std::unique_ptr<Sensor>> find_rapl(const std::filesystem::path& root);

// The counter difference from `last` to `now` for a counter that wraps at `max_range` (both in uJ): a counter
// that went down wrapped once (RAPL's 32-bit register wraps in about a minute on a busy 250 W package, so a
// 100 ms sampler never sees two wraps between reads). max_range 0 (unknown) and now < last: empty.
std::optional<long long> counter_delta(long long last, long long now, long long max_range);

}  // namespace bs::sensors
