// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/kernel_facts.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <system_error>
#include <vector>

namespace bs::headroom {
namespace {

// The first line of a small kernel file, without its line end; nullopt when it cannot be read.
std::optional<std::string> first_line(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  std::string line;
  std::getline(in, line);
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r' || line.back() == ' ')) line.pop_back();
  return line;
}

std::string preemption_model(const std::string& version) {
  // uname -v names the model: "#1 SMP PREEMPT_RT ...", "#1 SMP PREEMPT_DYNAMIC ...", "#1 SMP PREEMPT ...".
  std::istringstream words(version);
  std::string word, found = version.empty() ? "" : "none";
  while (words >> word) {
    if (word == "PREEMPT_RT") return word;
    if (word == "PREEMPT_DYNAMIC" || (word == "PREEMPT" && found == "none")) found = word;
  }
  return found;
}

std::string governors(const std::filesystem::path& cpu_dir) {
  std::map<std::string, int> counts;
  std::error_code ec;
  std::vector<std::filesystem::path> cpus;
  for (const auto& entry : std::filesystem::directory_iterator(cpu_dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.size() > 3 && name.compare(0, 3, "cpu") == 0 &&
        std::all_of(name.begin() + 3, name.end(), [](char c) { return c >= '0' && c <= '9'; }))
      cpus.push_back(entry.path());
  }
  for (const auto& cpu : cpus)
    if (auto g = first_line(cpu / "cpufreq" / "scaling_governor")) ++counts[*g];
  if (counts.empty()) return {};
  if (counts.size() == 1) return counts.begin()->first;
  std::string out;
  for (const auto& [name, n] : counts) out += (out.empty() ? "" : ", ") + name + " x" + std::to_string(n);
  return out;
}

}  // namespace

std::string cmdline_value(const std::string& cmdline, const std::string& key) {
  std::istringstream words(cmdline);
  std::string word, value;
  const std::string prefix = key + "=";
  while (words >> word)
    if (word.compare(0, prefix.size(), prefix) == 0) value = word.substr(prefix.size());
  return value;
}

KernelFacts read_kernel_facts(const std::filesystem::path& root) {
  KernelFacts facts;
  facts.release = first_line(root / "proc/sys/kernel/osrelease").value_or("");
  facts.version = first_line(root / "proc/sys/kernel/version").value_or("");
  facts.preemption = preemption_model(facts.version);
  // /sys/kernel/realtime exists (and reads 1) only on PREEMPT_RT kernels; its absence on a readable sysfs means no.
  if (auto rt = first_line(root / "sys/kernel/realtime"))
    facts.preempt_rt = *rt == "1";
  else if (facts.preemption == "PREEMPT_RT")
    facts.preempt_rt = true;
  else if (std::filesystem::exists(root / "sys/kernel"))
    facts.preempt_rt = false;
  const std::string cmdline = first_line(root / "proc/cmdline").value_or("");
  facts.isolcpus = cmdline_value(cmdline, "isolcpus");
  facts.nohz_full = cmdline_value(cmdline, "nohz_full");
  facts.governor = governors(root / "sys/devices/system/cpu");
  return facts;
}

}  // namespace bs::headroom
