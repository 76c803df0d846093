// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli devices: every backend/device the kernels can run on, with its theoretical peak.
#include <iostream>
#include <map>
#include <optional>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "analysis/peaks/ceiling_check.h"
#include "analysis/peaks/device_table.h"
#include "analysis/stats/stats.h"
#include "analysis/stats/units.h"
#include "commands/inventory_grammar.h"
#include "common/args.h"
#include "common/command.h"
#include "common/flag_output.h"
#include "common/signals.h"
#include "kernels/arm_cpu_print.h"
#include "kernels/backends/backend.h"
#include "kernels/bench_ceilings.h"
#include "kernels/ceilings/ceiling_cache.h"
#include "kernels/cpu_args.h"
#include "kernels/measured_set_home.h"
#include "store/home_batch.h"
#include "store/workspace.h"

namespace bs::cli {
namespace {

nlohmann::json ceiling_json(const kernels::Ceiling& c) {
  if (!c.measured()) return {{"how", c.how}, {"mean", nullptr}};
  const Summary w = summarize(c.values), p = summarize(c.per_cpu_second);
  // A device's ceilings are timed on the device: no per-CPU-second figure (null).
  return {{"unit", c.unit},
          {"mean", w.mean},
          {"sd", w.sd},
          {"n", w.n},
          {"per_cpu_second_mean", c.per_cpu_second.empty() ? nlohmann::json() : nlohmann::json(p.mean)},
          {"values", c.values},
          {"how", c.how}};
}

nlohmann::json ceilings_json(const kernels::CeilingSet& s) {
  nlohmann::json j{{"date", s.date},
                   {"isa", s.isa},
                   {"kind", std::string(to_string(s.kind))},
                   {"threads", s.threads},
                   {"clock_hz", s.clock_hz},
                   {"computed_peak_flops", s.computed_peak_flops},
                   {"rotation_mix", ceiling_json(s.rotation_mix)},
                   {"fma", ceiling_json(s.fma)},
                   {"bandwidth", ceiling_json(s.bandwidth)},
                   {"flags", nlohmann::json::array()}};
  if (s.rotation_mix.measured()) {
    const auto cmp = compare_to_ceilings(summarize(s.rotation_mix.values).mean, s.computed_peak_flops, std::nullopt,
                                         "the rotation-mix ceiling");
    j["rotation_mix"]["fraction_of_computed_peak"] =
        cmp.fraction_of_peak ? nlohmann::json(*cmp.fraction_of_peak) : nlohmann::json();
    for (const PlausibilityFlag& f : cmp.flags) j["flags"].push_back({{"code", f.code}, {"reason", f.reason}});
  }
  return j;
}

// The device table itself (resources/devices/devices.json): every entry with its FP32 peak and source.
int print_spec_table(const DeviceTable& table, bool json, std::ostream& out) {
  if (json) {
    nlohmann::json list = nlohmann::json::array();
    for (const DeviceSpec& s : table.devices) {
      nlohmann::json e = spec_json(s);
      e["kind"] = std::string(to_string(s.kind));
      e["aliases"] = s.aliases;
      e["note"] = s.note;
      e["more_urls"] = s.source_more_urls;
      nlohmann::json terms = nlohmann::json::array();
      for (const PeakTerm& t : s.peak_terms)
        terms.push_back({{"units", t.units},
                         {"unit", t.unit},
                         {"flop_per_unit_per_cycle", t.flop_per_unit_per_cycle},
                         {"clock_ghz", t.clock_ghz}});
      e["peak_terms"] = terms;
      e["peak_exempt"] = s.peak_exempt;
      list.push_back(std::move(e));
    }
    out << nlohmann::json{{"format", "benchscope-device-specs"},
                          {"version", 1},
                          {"path", table.path},
                          {"devices", list}}
               .dump(2)
        << '\n';
    return 0;
  }
  out << "device table " << table.path << " (" << table.devices.size()
      << " devices; a value ending in '?' was not confirmed by the entry's sources)\n";
  for (const DeviceSpec& s : table.devices) {
    const auto mark = [&](bool unverified) { return unverified ? "?" : ""; };
    out << s.id << " (" << to_string(s.kind) << "): " << s.name << "\n    FP32 peak "
        << format_si(s.fp32_peak_flops, "FLOPS") << mark(s.peak_unverified()) << " = " << s.derivation;
    if (s.memory_bandwidth_bytes_per_s)
      out << "; memory " << format_si(*s.memory_bandwidth_bytes_per_s, "B/s")
          << mark(s.is_unverified("memory_bandwidth_bytes_per_s"));
    if (s.tdp_w) out << "; TDP " << format_si(*s.tdp_w, "W") << mark(s.is_unverified("tdp_w"));
    out << "\n    source: " << s.source_title << (s.source_url.empty() ? "" : " <" + s.source_url + ">") << '\n';
    for (const std::string& url : s.source_more_urls) out << "    also: <" << url << ">\n";
    if (!s.unverified.empty()) {
      out << "    unverified:";
      for (const std::string& f : s.unverified) out << ' ' << f;
      out << '\n';
    }
    if (!s.peak_exempt.empty()) out << "    peak: " << s.peak_exempt << '\n';
    if (!s.note.empty()) out << "    note: " << s.note << '\n';
  }
  return 0;
}

int run_devices(const std::vector<std::string>& raw, std::ostream& out) {
  const commands::DevicesSettings args = commands::devices_from_words(raw);
  const BundledDeviceTable& specs = bundled_device_table();
  if (args.table) {
    if (!specs.error.empty()) throw std::runtime_error(specs.error);
    return print_spec_table(specs.table, args.json, out);
  }
  if (const auto proc_root = args.proc_root) {
    // Another machine's files (a copy of a robot's /proc, a test fixture): its CPU only, none of this host's backends.
    const auto arm = kernels::detect_arm_cpu(*proc_root, args.sysfs_root.value_or(*proc_root));
    if (!arm)
      throw std::runtime_error(*proc_root + "/proc/cpuinfo: no CPU with a 'CPU implementer' and 'CPU part' (not ARM)");
    if (args.json)
      out << nlohmann::json{{"format", "benchscope-arm-cpu"},
                            {"version", 1},
                            {"proc_root", *proc_root},
                            {"cpu", arm_cpu_json(*arm)}}
                 .dump(2)
          << '\n';
    else
      print_arm_cpu(*arm, out);
    return 0;
  }
  if (args.sysfs_root) throw UsageError("--sysfs-root goes with --proc-root");
  const auto spec_of = [&](const kernels::Backend& b) -> std::optional<DeviceSpec> {
    const DeviceSpec* s = match_device(specs.table, b.device_name, b.kind);
    return s ? std::optional<DeviceSpec>(*s) : std::nullopt;
  };
  kernels::CpuInfo cpu = cpu_from_isa(args.isa);
  const auto backends = kernels::available_backends(cpu);
  // Empirical ceilings of the CPU with its SIMD target and of every device backend (OpenCL, CUDA): measured now
  // when asked, else from the per-host cache.
  std::optional<kernels::CeilingSet> ceilings;
  std::map<std::string, kernels::CeilingSet> device_ceilings;  // by backend id
  std::map<std::string, std::string> device_errors;            // a device whose micro-kernels failed, and why
  const bool measure = args.measure_ceilings;
  if (measure) {
    ceilings = kernels::measure_ceilings(cpu, {}, interrupt_token());
    kernels::store_ceilings(*ceilings);
    for (const auto& b : backends) {
      if (!b.ceiling_kernels) continue;
      try {
        device_ceilings[b.id] = kernels::measure_device_ceilings(b, {}, interrupt_token());
        kernels::store_ceilings(device_ceilings[b.id]);
      } catch (const Cancelled&) {
        throw;
      } catch (const std::exception& e) {
        device_errors[b.id] = e.what();  // a wrong result or a failing device is reported, the others still shown
      }
    }
    // In a workspace the peak table, peaks and the roofline show each run's % of this device's ceiling.
    if (const auto ws_path = args.workspace) {
      // One import per device, as the Kernel Runner stores each device it measures, all in one transaction.
      const std::string where = "benchscope-cli devices --measure-ceilings";
      std::vector<HomeBatch> homes = {measured_set_home(kernels::ceiling_result_set(*ceilings), where)};
      for (const auto& [id, set] : device_ceilings)
        homes.push_back(measured_set_home(kernels::ceiling_result_set(set), where));
      bring_home(*ws_path, homes);
    }
  } else if (args.workspace) {
    throw UsageError("--workspace stores measured ceilings: use it with --measure-ceilings");
  } else {
    ceilings = kernels::cached_ceilings(cpu);
    for (const auto& b : backends)
      if (auto set = kernels::cached_device_ceilings(b)) device_ceilings[b.id] = std::move(*set);
  }
  if (args.json) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& b : backends) {
      nlohmann::json variants = nlohmann::json::array();
      for (auto v : b.variants) variants.push_back(b.variant_label(v));
      nlohmann::json entry{{"backend", b.id},
                           {"label", b.label},
                           {"device", b.device_name},
                           {"kind", std::string(to_string(b.kind))},
                           {"variants", variants},
                           {"theoretical_peak_flops", b.theoretical_peak_flops},
                           {"details", b.details},
                           {"spec", spec_json(spec_of(b))},
                           {"empirical_ceilings", nullptr}};
      if (b.id == "cpu-simd" && ceilings) entry["empirical_ceilings"] = ceilings_json(*ceilings);
      if (const auto it = device_ceilings.find(b.id); it != device_ceilings.end())
        entry["empirical_ceilings"] = ceilings_json(it->second);
      if (const auto it = device_errors.find(b.id); it != device_errors.end()) entry["ceiling_error"] = it->second;
      list.push_back(std::move(entry));
    }
    nlohmann::json doc{{"format", "benchscope-devices"},
                       {"version", 1},
                       {"devices", list},
                       {"unavailable", kernels::unavailable_backends()}};
    if (cpu.arm) doc["arm_cpu"] = arm_cpu_json(*cpu.arm);
    out << doc.dump(2) << '\n';
    return device_errors.empty() ? 0 : 1;
  }
  if (cpu.arm) print_arm_cpu(*cpu.arm, out);
  for (const auto& b : backends) {
    out << b.id << ": " << b.label << " on " << b.device_name << "\n    " << b.details << "\n    variants:";
    for (auto v : b.variants) out << ' ' << b.variant_label(v);
    out << "\n    theoretical peak " << format_si(b.theoretical_peak_flops, "FLOPS") << "\n";
    if (const auto s = spec_of(b))
      out << "    vendor FP32 peak " << format_si(s->fp32_peak_flops, "FLOPS") << " (" << s->name << ": "
          << s->derivation << ")\n";
    if (b.id == "cpu-simd") {
      if (ceilings) {
        out << "    empirical ceilings (" << (args.measure_ceilings ? "measured now" : "cached") << ", "
            << ceilings->date << ", " << ceilings->threads << " threads):\n";
        print_ceilings(*ceilings, out, "      ");
      } else {
        out << "    empirical ceilings: none cached for " << cpu.simd.name << " and " << cpu.threads
            << " threads; devices --measure-ceilings or bench kernels measures them (" << kernels::ceiling_cache_path()
            << ")\n";
      }
    } else if (b.ceiling_kernels) {
      if (const auto it = device_errors.find(b.id); it != device_errors.end()) {
        out << "    empirical ceilings: FAILED: " << it->second << '\n';
      } else if (const auto found = device_ceilings.find(b.id); found != device_ceilings.end()) {
        out << "    empirical ceilings (" << (measure ? "measured now" : "cached") << ", " << found->second.date
            << ", timed on the device):\n";
        print_ceilings(found->second, out, "      ");
      } else {
        out << "    empirical ceilings: none cached for this device; devices --measure-ceilings or bench kernels "
               "measures them ("
            << kernels::ceiling_cache_path() << ")\n";
      }
    }
  }
  for (const std::string& why : kernels::unavailable_backends()) out << "not available: " << why << '\n';
  return device_errors.empty() ? 0 : 1;  // a device micro-kernel whose result was wrong fails the command
}

const CommandRegistrar registrar({
    "devices",
    "list the backends and devices the kernels can run on, with theoretical peaks",
    "usage: benchscope-cli devices [--table] [--json] [--isa avx512|avx2|sse4|generic]\n"
    "         [--measure-ceilings [--workspace W.bsw]] [--proc-root DIR [--sysfs-root DIR]]\n"
    "  Every backend and device (CPU SIMD, CPU scalar, each OpenCL device, each CUDA GPU) with its properties, the\n"
    "  rotation kernel's theoretical peak and the vendor FP32 peak from the device table, then the backends this\n"
    "  build knows but cannot run here and why. --table: the device table (resources/devices/devices.json) with\n"
    "  every entry's FP32 peak, derivation and sources; a value no source confirmed ends in '?'. The CPU SIMD\n"
    "  backend and every OpenCL and CUDA device also show their empirical ceilings (rotation mix, FMA, memory\n"
    "  bandwidth; docs/ceilings.md, docs/gpu-check.md) with when and how they were measured, from the per-host\n"
    "  cache; --measure-ceilings measures them all now (~5 s for the CPU, ~2 s per device) and updates the cache\n"
    "  (--workspace: also stores them there, for peaks, the peak table and the roofline).\n"
    "  --isa: another instruction set this CPU has. On ARM the CPU is named by its core types (/proc/cpuinfo 'CPU\n"
    "  implementer'/'CPU part', the board from /proc/device-tree/model), with NEON lanes, FMA units, clock and FP32\n"
    "  peak per cluster (resources/devices/cpu-cores.json) and their sum. --proc-root DIR: describe the ARM CPU of\n"
    "  DIR/proc/cpuinfo and DIR/proc/device-tree/model (a copy of a robot's files) instead of this machine; clocks\n"
    "  from DIR/sys/devices/system/cpu/cpuN/cpufreq (or --sysfs-root), else from the board's device-table entry.",
    out_only<run_devices>,
});

}  // namespace
}  // namespace bs::cli
