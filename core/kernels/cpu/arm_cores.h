// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// ARM CPUs by name: the core types of /proc/cpuinfo ("CPU implementer" / "CPU part", present even where there is no
// "model name"), grouped into clusters (a Jetson TX2 has 2 Denver 2 + 4 Cortex-A57), the board from
// /proc/device-tree/model, and a FP32 peak per cluster from the core table (resources/devices/cpu-cores.json: NEON
// lanes and FMA units per core, each with its source) and each cluster's clock.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/peaks/device_table.h"

namespace bs::kernels {

// One row of the core table.
struct ArmCoreType {
  std::uint32_t implementer = 0;  // MIDR implementer: 0x41 Arm, 0x4e NVIDIA
  std::uint32_t part = 0;         // MIDR part number: 0xd07 Cortex-A57, 0x003 Denver 2, ...
  std::string name;               // "Cortex-A57"
  std::string vendor;             // "Arm", "NVIDIA"
  int fp32_lanes = 4;             // FP32 lanes per NEON vector
  int fma_units = 1;              // 128-bit vector FMAs completed per cycle
  std::string source_title, source_url, note;
  std::vector<std::string> source_more_urls;
  std::vector<std::string> unverified;  // "fp32_lanes", "fma_units": not confirmed by the cited source

  // FP32 FLOP per cycle per core, an FMA counting 2.
  double fp32_flop_per_cycle() const { return fp32_lanes * 2.0 * fma_units; }
};

struct ArmCoreTable {
  std::string path;
  std::vector<ArmCoreType> cores;
};

// Throws std::runtime_error naming `origin`, the entry and the field for malformed input.
ArmCoreTable parse_arm_core_table(std::string_view json_text, const std::string& origin);
ArmCoreTable load_arm_core_table(const std::filesystem::path& path);
// find_resource("devices/cpu-cores.json"), loaded once; throws when it cannot be found or read.
const ArmCoreTable& bundled_arm_core_table();
const ArmCoreType* find_arm_core(const ArmCoreTable& table, std::uint32_t implementer, std::uint32_t part);

// One logical CPU of /proc/cpuinfo.
struct CpuInfoEntry {
  int processor = -1;  // "processor" (-1 when the block has none, e.g. an excerpt)
  std::optional<std::uint32_t> implementer, part;
  std::string model_name;  // "model name" (x86, and ARM kernels before 4.x / Tegra kernels)
};

struct ProcCpuInfo {
  std::vector<CpuInfoEntry> cpus;
  std::string model;     // the trailing "Model" line (Raspberry Pi kernels: the board)
  std::string hardware;  // "Hardware" line
};

// Parses the text of /proc/cpuinfo (x86 or ARM); lines without a "key : value" shape are ignored, a malformed
// implementer/part value throws std::runtime_error naming `origin`, the line and the value.
ProcCpuInfo parse_proc_cpuinfo(std::string_view text, const std::string& origin);

// The contents of /proc/device-tree/model without its trailing NUL(s) and whitespace ("" when absent).
std::string read_device_tree_model(const std::filesystem::path& proc_root);

// A group of CPUs of one core type.
struct ArmCluster {
  std::string core_name;  // "Cortex-A57", or "unknown core (implementer 0x.., part 0x...)"
  std::uint32_t implementer = 0, part = 0;
  std::vector<int> cpus;            // processor numbers (empty entries of an excerpt count as one CPU each)
  int cores = 0;                    // CPUs listed
  std::optional<ArmCoreType> type;  // the core table's row, when known
  double clock_ghz = 0;             // 0 when unknown
  std::string clock_source;         // "cpufreq cpuinfo_max_freq", "device table <id>", "measured", ""
  double fp32_peak_flops = 0;       // cores x fp32_flop_per_cycle x clock (0 when the clock or core is unknown)
};

struct ArmCpu {
  std::string board;                     // /proc/device-tree/model, else the cpuinfo "Model" line
  std::optional<DeviceSpec> board_spec;  // the device table's CPU entry matching the board
  std::vector<ArmCluster> clusters;      // in order of first appearance
  double fp32_peak_flops = 0;            // sum of the clusters' peaks
  bool peak_complete = false;            // every cluster has a known core and clock
  int cores() const;
  // "2x Denver 2 + 4x Cortex-A57"
  std::string summary() const;
};

// Describes the ARM CPU of `info` (nullopt when no CPU has an implementer/part: not ARM). Each cluster's clock is,
// in order: cpufreq's cpuinfo_max_freq under `sysfs_root` for one of its CPUs; the matching board entry's peak term
// for that core type; `measured_clock_hz` when > 0; else unknown (peak 0).
std::optional<ArmCpu> describe_arm_cpu(const ProcCpuInfo& info, std::string_view device_tree_model,
                                       const ArmCoreTable& cores, const DeviceTable* boards,
                                       const std::filesystem::path& sysfs_root, double measured_clock_hz = 0);

// The same from the files under `proc_root` (proc/cpuinfo, proc/device-tree/model) and `sysfs_root`
// (sys/devices/system/cpu/...), with the bundled tables. nullopt when the files describe no ARM CPU; throws
// std::runtime_error when proc/cpuinfo cannot be read or is malformed.
std::optional<ArmCpu> detect_arm_cpu(const std::filesystem::path& proc_root = "/",
                                     const std::filesystem::path& sysfs_root = "/", double measured_clock_hz = 0);

}  // namespace bs::kernels
