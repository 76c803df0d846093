// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/power_args.h"

#include "analysis/power/sweep_energy.h"

#include <cstdio>
#include <ostream>

#include "analysis/power/phase_energy.h"
#include "common/events_option.h"

namespace bs::cli {

std::unique_ptr<sensors::PowerRecorder> make_recorder(const std::string& spec, const std::string& root,
                                                      double interval_ms, std::ostream& err, bool quiet,
                                                      remote::EventWriter* events) {
  if (!(interval_ms >= 1 && interval_ms <= 60000)) throw UsageError("the sample interval must be 1..60000 ms");
  sensors::SensorSet set = sensors::find_sensors({root, sensors::default_nvml_library()});
  sensors::Selection sel;
  try {
    sel = sensors::select_sensors(set, spec);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("power sensors: ") + e.what());
  }
  if (!quiet) {
    err << "benchscope-cli: recording power from " << sel.note << ": ";
    for (std::size_t i = 0; i < sel.sensors.size(); ++i) err << (i ? ", " : "") << sel.sensors[i]->info().id;
    err << ", every " << interval_ms << " ms\n";
  }
  auto rec = std::make_unique<sensors::PowerRecorder>(
      std::move(sel), std::chrono::microseconds(static_cast<long long>(interval_ms * 1000)));
  if (events) stream_power(*rec, *events);
  rec->start();
  return rec;
}

std::unique_ptr<sensors::PowerRecorder> start_power(const ParsedArgs& args, std::ostream& err, bool quiet,
                                                    remote::EventWriter* events) {
  return start_power(commands::read_power(args), err, quiet, events);
}

std::unique_ptr<sensors::PowerRecorder> start_power(const commands::PowerWords& power, std::ostream& err, bool quiet,
                                                    remote::EventWriter* events) {
  if (power.sensor == "none") return nullptr;
  return make_recorder(power.sensor, power.sysfs_root.value_or("/"), power.interval_ms.value_or(100), err, quiet,
                       events);
}

void print_phase_energies(std::ostream& out, const PowerTrace& trace) {
  out << "power: " << to_string(trace.provenance.measurement) << ": " << trace.provenance.sensor << ", "
      << trace.time_s.size() << " samples\n";
  char line[256];
  for (const PhaseEnergy& e : phase_energies(trace)) {
    std::snprintf(line, sizeof line, "  %-28s %10.4f J over %8.3f s, mean %8.4f W (%zu samples)%s\n", e.name.c_str(),
                  e.energy_j, e.end_s - e.start_s, e.mean_power_w, e.samples, short_point_mark(e.samples).c_str());
    out << line;
  }
}

void print_energy_per_item(std::ostream& out, const PowerTrace& trace,
                           const std::vector<std::pair<std::string, std::size_t>>& groups, const std::string& item) {
  const auto energies = phase_energies(trace);
  out << "energy per " << item << " (" << to_string(trace.provenance.measurement) << ": " << trace.provenance.sensor
      << "):\n";
  char line[256];
  for (const auto& [group, items] : groups) {
    double joules = 0, seconds = 0;
    for (const PhaseEnergy& e : energies)
      if (e.name.starts_with(group)) joules += e.energy_j, seconds += e.end_s - e.start_s;
    if (items == 0 || seconds <= 0) continue;
    std::snprintf(line, sizeof line, "  %-58s %9.4f J per %s (%zu, mean %.3f W)\n", group.c_str(),
                  joules / static_cast<double>(items), item.c_str(), items, joules / seconds);
    out << line;
  }
}

std::string power_csv_beside(const std::string& out_path) {
  std::string base = out_path;
  if (base.size() > 5 && base.ends_with(".json")) base.resize(base.size() - 5);
  return base + ".power.csv";
}

}  // namespace bs::cli
