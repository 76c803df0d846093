// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli synth-power: a long current log as a bench meter writes it, to measure import and view at scale
// (issue #19: a 4 kS/s meter over 7 hours is 100 million samples) without shipping gigabytes of data.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <string>

#include "common/args.h"
#include "common/command.h"
#include "common/signals.h"

namespace bs::cli {
namespace {

// The load pattern of a robot computer on a bench: idle stretches, benchmark bursts and short spikes, with
// meter noise. Deterministic for a given seed, so two runs write byte-identical files.
class SyntheticLoad {
 public:
  explicit SyntheticLoad(unsigned seed) : rng_(seed) {}
  double next_amps(double t) {
    // 60 s cycle: 20 s idle (0.60 A), 30 s load (2.4 A with a slow 0.2 A ripple), 10 s cool-down (0.9 A).
    const double phase = std::fmod(t, 60.0);
    double a = phase < 20 ? 0.60 : phase < 50 ? 2.4 + 0.2 * std::sin(2 * M_PI * t / 7.0) : 0.90;
    if (spike_left_ > 0) {
      --spike_left_;
      a += 1.5;
    } else if (uniform_(rng_) < 1e-4) {
      spike_left_ = 40;  // a 10 ms spike at 4 kS/s
    }
    return a + noise_(rng_);
  }

 private:
  std::mt19937_64 rng_;
  std::normal_distribution<double> noise_{0.0, 0.02};
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
  int spike_left_ = 0;
};

void put_fixed(std::string& line, double v, int digits) {
  char buf[48];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, digits);
  line.append(buf, r.ptr);
}

int run_synth_power(const std::vector<std::string>& raw_args, std::ostream& out) {
  const ParsedArgs args = parse_args(raw_args, {}, {"--out", "--samples", "--rate", "--seed", "--platform"});
  const auto path = args.value("--out");
  if (!path) throw UsageError("--out FILE.csv is required");
  const double samples_d = args.number("--samples", 1e6);
  const double rate = args.number("--rate", 4000);
  if (!(samples_d >= 2 && samples_d <= 1e10) || samples_d != std::floor(samples_d))
    throw UsageError("--samples must be a whole number from 2 to 1e10");
  if (!(rate > 0 && rate <= 1e7)) throw UsageError("--rate must be above 0 and at most 1e7 samples per second");
  const auto samples = static_cast<std::uint64_t>(samples_d);
  const auto seed = static_cast<unsigned>(args.number("--seed", 1));
  const std::string platform = args.value("--platform").value_or("Synthetic bench");

  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path->c_str(), "wb"), &std::fclose);
  if (!f) throw std::runtime_error(*path + ": cannot create file");
  std::string block;
  block += "# platform: " + platform + "\n# supply_voltage_V: 16\n# meter: benchscope-cli synth-power (synthetic)\n";
  block += "time_s,current_A\n";
  // Time to 0.1 us: a 4 kS/s sample period (250 us) is exact, and at 7 h the text still resolves it.
  const int time_digits = rate <= 1e5 ? 7 : 9;
  SyntheticLoad load(seed);
  const CancelToken& cancel = interrupt_token();
  for (std::uint64_t i = 0; i < samples; ++i) {
    const double t = static_cast<double>(i) / rate;
    put_fixed(block, t, time_digits);
    block += ',';
    put_fixed(block, load.next_amps(t), 5);
    block += '\n';
    if (block.size() > (1u << 20)) {
      if (std::fwrite(block.data(), 1, block.size(), f.get()) != block.size())
        throw std::runtime_error(*path + ": write failed (disk full?)");
      block.clear();
      cancel.throw_if_cancelled();
    }
  }
  if (std::fwrite(block.data(), 1, block.size(), f.get()) != block.size() || std::fflush(f.get()) != 0)
    throw std::runtime_error(*path + ": write failed (disk full?)");
  out << "wrote " << *path << ": " << samples << " samples at " << rate << " S/s ("
      << static_cast<double>(samples) / rate / 3600.0 << " h), synthetic current in A, supply 16 V\n";
  return 0;
}

const CommandRegistrar registrar({
    "synth-power",
    "write a synthetic current log (CSV) of N samples, to measure import and viewing at scale",
    "usage: benchscope-cli synth-power --out FILE.csv [--samples N] [--rate S_PER_S] [--seed N] [--platform NAME]\n"
    "  Writes a meter-style CSV (time_s,current_A; '# platform' and '# supply_voltage_V: 16' comments) of N samples\n"
    "  (default 1e6) at the given rate (default 4000 S/s): a 60 s cycle of idle (0.6 A), load (2.4 A) and\n"
    "  cool-down (0.9 A) with 10 ms spikes and 20 mA Gaussian noise. The same seed (default 1) gives the same bytes.\n"
    "  The data is synthetic and says so in a '# meter' comment.",
    out_only<run_synth_power>,
});

}  // namespace
}  // namespace bs::cli
