// SPDX-License-Identifier: GPL-3.0-or-later
#include "kernels/cpu/arm_cores.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "util/resource_table.h"
#include "util/resources.h"
#include "util/text.h"

namespace bs::kernels {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& origin, const std::string& where, const std::string& why) {
  resource_table_fail(origin, where, why);
}

// "0x4e", "0xd07": MIDR fields are at most 12 bits (part) or 8 bits (implementer); anything else is not a
// cpuinfo we understand.
std::optional<std::uint32_t> parse_hex(std::string_view v, std::uint32_t max) {
  if (v.size() < 3 || v.size() > 10 || v[0] != '0' || (v[1] != 'x' && v[1] != 'X')) return std::nullopt;
  std::uint32_t out = 0;
  for (const char c : v.substr(2)) {
    int d = -1;
    if (c >= '0' && c <= '9') d = c - '0';
    if (c >= 'a' && c <= 'f') d = c - 'a' + 10;
    if (c >= 'A' && c <= 'F') d = c - 'A' + 10;
    if (d < 0) return std::nullopt;
    out = out * 16 + static_cast<std::uint32_t>(d);
    if (out > max) return std::nullopt;
  }
  return out;
}

std::string hex(std::uint32_t v, int width) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%0*x", width, v);
  return buf;
}

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return {};
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::uint32_t table_hex(const json& e, const char* key, std::uint32_t max, const std::string& origin,
                        const std::string& where) {
  const auto it = e.find(key);
  if (it == e.end() || !it->is_string()) fail(origin, where + "." + key, "missing or not a string like \"0x41\"");
  const auto v = parse_hex(it->get<std::string>(), max);
  if (!v) fail(origin, where + "." + key, "not a hexadecimal MIDR field: " + it->get<std::string>());
  return *v;
}

int table_count(const json& e, const char* key, const std::string& origin, const std::string& where) {
  const auto it = e.find(key);
  if (it == e.end() || !it->is_number_integer() || it->get<int>() < 1 || it->get<int>() > 64)
    fail(origin, where + "." + key, "missing or not an integer in 1..64");
  return it->get<int>();
}

// cpufreq's highest frequency of `cpu` in GHz (the file holds kHz), 0 when absent or not a sane number.
double cpufreq_max_ghz(const std::filesystem::path& sysfs_root, int cpu) {
  if (cpu < 0) return 0;
  const std::string text(bs::trim(
      read_file(sysfs_root / "sys/devices/system/cpu" / ("cpu" + std::to_string(cpu)) / "cpufreq/cpuinfo_max_freq")));
  if (text.empty() || text.size() > 9 ||
      !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return 0;
  const double khz = std::stod(text);
  return khz >= 1e4 && khz <= 1e7 ? khz / 1e6 : 0;  // 10 MHz .. 10 GHz
}

// Whether the words of `core` (e.g. "Cortex-A57") appear in a peak term's unit ("Cortex-A57 cores").
bool unit_names_core(const std::string& unit, const std::string& core) {
  const auto hay = device_name_tokens(unit);
  const auto needle = device_name_tokens(core);
  return !needle.empty() && std::search(hay.begin(), hay.end(), needle.begin(), needle.end()) != hay.end();
}

}  // namespace

ArmCoreTable parse_arm_core_table(std::string_view json_text, const std::string& origin) {
  ArmCoreTable table;
  table.path = origin;
  for_each_resource_entry(
      json_text, origin, "benchscope-cpu-cores", "cores", [&](const json& e, const std::string& where) {
        ArmCoreType c;
        c.implementer = table_hex(e, "implementer", 0xff, origin, where);
        c.part = table_hex(e, "part", 0xfff, origin, where);
        c.name = resource_table_string(e, "name", origin, where);
        c.vendor = e.value("vendor", "");
        c.fp32_lanes = table_count(e, "fp32_lanes", origin, where);
        c.fma_units = table_count(e, "fma_units", origin, where);
        const auto src = e.find("source");
        if (src == e.end() || !src->is_object() || !src->contains("title") || !(*src)["title"].is_string())
          fail(origin, where + ".source", "missing: every core names its source (title, url)");
        c.source_title = (*src)["title"].get<std::string>();
        c.source_url = src->value("url", "");
        c.source_more_urls = resource_table_strings(*src, "more", origin, where + ".source");
        c.unverified = resource_table_strings(e, "unverified", origin, where);
        for (const std::string& f : c.unverified)
          if (f != "fp32_lanes" && f != "fma_units") fail(origin, where + ".unverified", "unknown field " + f);
        c.note = e.value("note", "");
        if (find_arm_core(table, c.implementer, c.part))
          fail(origin, where, "duplicate core " + hex(c.implementer, 2) + "/" + hex(c.part, 3));
        table.cores.push_back(std::move(c));
      });
  return table;
}

ArmCoreTable load_arm_core_table(const std::filesystem::path& path) {
  return parse_arm_core_table(read_resource_file(path), path.string());
}

const ArmCoreTable& bundled_arm_core_table() {
  static const ArmCoreTable table = load_arm_core_table(find_resource("devices/cpu-cores.json"));
  return table;
}

const ArmCoreType* find_arm_core(const ArmCoreTable& table, std::uint32_t implementer, std::uint32_t part) {
  for (const ArmCoreType& c : table.cores)
    if (c.implementer == implementer && c.part == part) return &c;
  return nullptr;
}

ProcCpuInfo parse_proc_cpuinfo(std::string_view text, const std::string& origin) {
  ProcCpuInfo out;
  bool in_block = false;  // a block has started and has not yet been closed by a blank line
  std::size_t line_no = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    const auto colon = line.find(':');
    if (colon == std::string_view::npos) {
      if (bs::trim(line).empty()) in_block = false;  // blocks are separated by blank lines
      if (end == text.size()) break;
      continue;
    }
    const std::string key(bs::trim(line.substr(0, colon)));
    const std::string value(bs::trim(line.substr(colon + 1)));
    const auto start_block = [&] {
      out.cpus.emplace_back();
      in_block = true;
    };
    if (key == "processor") {
      start_block();
      const bool digits = !value.empty() && value.size() <= 5 &&
                          std::all_of(value.begin(), value.end(), [](char c) { return c >= '0' && c <= '9'; });
      out.cpus.back().processor = digits ? std::stoi(value) : -1;
    } else if (key == "CPU implementer" || key == "CPU part") {
      const bool impl = key == "CPU implementer";
      const auto v = parse_hex(value, impl ? 0xff : 0xfff);
      if (!v)
        fail(origin, "line " + std::to_string(line_no),
             key + " \"" + value + "\" is not a hexadecimal " + (impl ? "8" : "12") + "-bit value");
      if (!in_block) start_block();  // an excerpt without "processor" lines
      auto& slot = impl ? out.cpus.back().implementer : out.cpus.back().part;
      if (slot) start_block();  // a second implementer/part without a blank line: a new CPU
      (impl ? out.cpus.back().implementer : out.cpus.back().part) = *v;
    } else if (key == "model name") {
      if (!in_block) start_block();
      out.cpus.back().model_name = value;
    } else if (key == "Model") {
      out.model = value;
    } else if (key == "Hardware") {
      out.hardware = value;
    }
    if (end == text.size()) break;
  }
  return out;
}

std::string read_device_tree_model(const std::filesystem::path& proc_root) {
  std::string s = read_file(proc_root / "proc/device-tree/model");
  while (!s.empty() && (s.back() == '\0' || s.back() == '\n' || s.back() == ' ')) s.pop_back();
  if (s.size() > 256 || s.find('\0') != std::string::npos) return {};  // not a device-tree string property
  return s;
}

int ArmCpu::cores() const {
  int n = 0;
  for (const ArmCluster& c : clusters) n += c.cores;
  return n;
}

std::string ArmCpu::summary() const {
  std::string s;
  for (const ArmCluster& c : clusters) s += (s.empty() ? "" : " + ") + std::to_string(c.cores) + "x " + c.core_name;
  return s;
}

std::optional<ArmCpu> describe_arm_cpu(const ProcCpuInfo& info, std::string_view device_tree_model,
                                       const ArmCoreTable& cores, const DeviceTable* boards,
                                       const std::filesystem::path& sysfs_root, double measured_clock_hz) {
  ArmCpu cpu;
  for (const CpuInfoEntry& e : info.cpus) {
    if (!e.implementer || !e.part) continue;
    auto it = std::find_if(cpu.clusters.begin(), cpu.clusters.end(),
                           [&](const ArmCluster& c) { return c.implementer == *e.implementer && c.part == *e.part; });
    if (it == cpu.clusters.end()) {
      ArmCluster c;
      c.implementer = *e.implementer;
      c.part = *e.part;
      if (const ArmCoreType* t = find_arm_core(cores, c.implementer, c.part)) {
        c.type = *t;
        c.core_name = t->name;
      } else {
        c.core_name = "unknown core (implementer " + hex(c.implementer, 2) + ", part " + hex(c.part, 3) + ")";
      }
      cpu.clusters.push_back(std::move(c));
      it = cpu.clusters.end() - 1;
    }
    ++it->cores;
    if (e.processor >= 0) it->cpus.push_back(e.processor);
  }
  if (cpu.clusters.empty()) return std::nullopt;

  cpu.board = device_tree_model.empty() ? info.model : std::string(device_tree_model);
  if (boards && !cpu.board.empty())
    if (const DeviceSpec* s = match_device(*boards, cpu.board, DeviceKind::Cpu)) cpu.board_spec = *s;

  cpu.peak_complete = true;
  for (ArmCluster& c : cpu.clusters) {
    for (const int n : c.cpus) {
      if (const double ghz = cpufreq_max_ghz(sysfs_root, n); ghz > 0) {
        c.clock_ghz = ghz;
        c.clock_source = "cpufreq cpuinfo_max_freq of cpu" + std::to_string(n);
        break;
      }
    }
    if (c.clock_ghz == 0 && cpu.board_spec) {
      for (const PeakTerm& t : cpu.board_spec->peak_terms)
        if (unit_names_core(t.unit, c.core_name)) {
          c.clock_ghz = t.clock_ghz;
          c.clock_source = "device table " + cpu.board_spec->id;
          break;
        }
    }
    if (c.clock_ghz == 0 && measured_clock_hz > 0) {
      c.clock_ghz = measured_clock_hz / 1e9;
      c.clock_source = "measured";
    }
    if (c.type && c.clock_ghz > 0) {
      c.fp32_peak_flops = c.cores * c.type->fp32_flop_per_cycle() * c.clock_ghz * 1e9;
      cpu.fp32_peak_flops += c.fp32_peak_flops;
    } else {
      cpu.peak_complete = false;
    }
  }
  return cpu;
}

std::optional<ArmCpu> detect_arm_cpu(const std::filesystem::path& proc_root, const std::filesystem::path& sysfs_root,
                                     double measured_clock_hz) {
  const std::filesystem::path path = proc_root / "proc/cpuinfo";
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  // /proc/cpuinfo of a 256-core machine is ~300 KB; more than 4 MB is not a cpuinfo.
  std::string text(4u << 20, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  const ProcCpuInfo info = parse_proc_cpuinfo(text, path.string());
  // Not ARM (x86 has no implementer/part lines): no need for the tables.
  if (std::none_of(info.cpus.begin(), info.cpus.end(), [](const CpuInfoEntry& e) { return e.implementer && e.part; }))
    return std::nullopt;
  const BundledDeviceTable& boards = bundled_device_table();
  return describe_arm_cpu(info, read_device_tree_model(proc_root), bundled_arm_core_table(),
                          boards.error.empty() ? &boards.table : nullptr, sysfs_root, measured_clock_hz);
}

}  // namespace bs::kernels
