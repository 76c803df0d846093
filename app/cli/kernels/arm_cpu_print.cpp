// SPDX-License-Identifier: GPL-3.0-or-later
#include "kernels/arm_cpu_print.h"

#include <cstdio>
#include <string>

#include "analysis/stats/units.h"

namespace bs::cli {
namespace {

std::string hex(std::uint32_t v, int width) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%0*x", width, v);
  return buf;
}

std::string cpu_list(const std::vector<int>& cpus) {
  std::string s;
  for (const int c : cpus) s += (s.empty() ? "" : ",") + std::to_string(c);
  return s.empty() ? "not numbered" : s;
}

}  // namespace

void print_arm_cpu(const kernels::ArmCpu& cpu, std::ostream& out) {
  out << "ARM CPU: " << (cpu.board.empty() ? "board not named (no /proc/device-tree/model)" : cpu.board) << ": "
      << cpu.summary() << " (" << cpu.clusters.size() << (cpu.clusters.size() == 1 ? " cluster, " : " clusters, ")
      << cpu.cores() << (cpu.cores() == 1 ? " core listed" : " cores listed") << ")\n";
  int i = 0;
  for (const kernels::ArmCluster& c : cpu.clusters) {
    out << "    cluster " << ++i << ": " << c.cores << "x " << c.core_name << " (implementer " << hex(c.implementer, 2)
        << ", part " << hex(c.part, 3) << "; CPUs " << cpu_list(c.cpus) << ")\n";
    if (!c.type) {
      out << "        not in the core table (resources/devices/cpu-cores.json): no peak\n";
      continue;
    }
    const kernels::ArmCoreType& t = *c.type;
    const auto mark = [&](const char* field) {
      for (const std::string& f : t.unverified)
        if (f == field) return "?";
      return "";
    };
    char per_core[160];
    std::snprintf(per_core, sizeof per_core,
                  "%d FP32 NEON lanes%s x 2 (FMA) x %d FMA unit%s%s = %.0f FP32 FLOP/cycle/core", t.fp32_lanes,
                  mark("fp32_lanes"), t.fma_units, t.fma_units == 1 ? "" : "s", mark("fma_units"),
                  t.fp32_flop_per_cycle());
    out << "        " << per_core;
    if (c.clock_ghz > 0)
      out << " x " << format_si(c.clock_ghz * 1e9, "Hz") << " (" << c.clock_source << ") x " << c.cores
          << " = FP32 peak " << format_si(c.fp32_peak_flops, "FLOPS") << "\n";
    else
      out << "; clock unknown (no cpufreq, no device-table entry for the board): no peak\n";
    out << "        source: " << t.source_title << (t.source_url.empty() ? "" : " <" + t.source_url + ">") << '\n';
    if (!t.unverified.empty()) {
      out << "        unverified:";
      for (const std::string& f : t.unverified) out << ' ' << f;
      out << '\n';
    }
  }
  if (cpu.clusters.size() > 1 || !cpu.peak_complete)
    out << "    FP32 peak, all clusters: " << format_si(cpu.fp32_peak_flops, "FLOPS")
        << (cpu.peak_complete ? "" : " (incomplete: a cluster's core or clock is unknown)") << '\n';
  if (cpu.board_spec)
    out << "    device table " << cpu.board_spec->id << ": " << cpu.board_spec->name << ", FP32 peak "
        << format_si(cpu.board_spec->fp32_peak_flops, "FLOPS") << " = " << cpu.board_spec->derivation << '\n';
  else if (!cpu.board.empty())
    out << "    device table: no CPU entry matches \"" << cpu.board << "\"\n";
}

nlohmann::json arm_cpu_json(const kernels::ArmCpu& cpu) {
  nlohmann::json clusters = nlohmann::json::array();
  for (const kernels::ArmCluster& c : cpu.clusters) {
    nlohmann::json j{{"core", c.core_name},
                     {"implementer", hex(c.implementer, 2)},
                     {"part", hex(c.part, 3)},
                     {"cores", c.cores},
                     {"cpus", c.cpus},
                     {"clock_hz", c.clock_ghz > 0 ? nlohmann::json(c.clock_ghz * 1e9) : nlohmann::json()},
                     {"clock_source", c.clock_source},
                     {"fp32_peak_flops", c.fp32_peak_flops > 0 ? nlohmann::json(c.fp32_peak_flops) : nlohmann::json()}};
    if (c.type)
      j["core_type"] = {{"vendor", c.type->vendor},
                        {"fp32_lanes", c.type->fp32_lanes},
                        {"fma_units", c.type->fma_units},
                        {"fp32_flop_per_cycle", c.type->fp32_flop_per_cycle()},
                        {"source", c.type->source_title},
                        {"url", c.type->source_url},
                        {"more_urls", c.type->source_more_urls},
                        {"unverified", c.type->unverified}};
    clusters.push_back(std::move(j));
  }
  return {{"board", cpu.board},
          {"summary", cpu.summary()},
          {"cores", cpu.cores()},
          {"clusters", clusters},
          {"fp32_peak_flops", cpu.fp32_peak_flops},
          {"peak_complete", cpu.peak_complete},
          {"device_table_entry", cpu.board_spec ? nlohmann::json(cpu.board_spec->id) : nlohmann::json()}};
}

}  // namespace bs::cli
