// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/headroom_print.h"

#include <ostream>

#include "common/text_table.h"
#include "headroom/headroom_table.h"

namespace bs::cli {

std::string kernel_line(const headroom::KernelFacts& k) {
  const std::string rt = !k.preempt_rt ? "PREEMPT_RT unknown" : *k.preempt_rt ? "PREEMPT_RT" : "not PREEMPT_RT";
  return "kernel " + (k.release.empty() ? std::string("unknown") : k.release) + " (" +
         (k.preemption.empty() || k.preemption == "PREEMPT_RT" ? rt : k.preemption + ", " + rt) + "), governor " +
         (k.governor.empty() ? "unknown" : k.governor) + ", isolcpus " + (k.isolcpus.empty() ? "none" : k.isolcpus) +
         ", nohz_full " + (k.nohz_full.empty() ? "none" : k.nohz_full);
}

void print_headroom(std::ostream& out, const headroom::HeadroomMeasurement& m, const std::string& source) {
  if (!m.realtime()) {
    bool policy_known = false;
    for (const headroom::Phase& p : m.phases)
      for (const headroom::ThreadLatency& t : p.threads) policy_known |= !t.policy.empty();
    if (policy_known)
      out << "NON-REAL-TIME: " << (m.tool == "benchscope probe" ? "the probe" : "the measured loop")
          << " did not run under SCHED_FIFO/RR; not comparable with real-time results\n";
    else
      out << "POLICY UNKNOWN: " << m.tool << "'s file does not say whether the loop ran under SCHED_FIFO/RR; not "
          << "comparable with real-time results until it is known\n";
  }
  out << m.platform << ": " << headroom::to_string(m.kind) << " (" << m.tool << "), " << kernel_line(m.kernel)
      << "\n\n";
  const ExportTable t = headroom::headroom_table(m, source);
  TextTable table(t.header);
  for (const auto& row : t.rows) table.add(row);
  table.print(out);
  if (!t.notes.empty()) out << "\n";
  for (const std::string& n : t.notes) out << n << "\n";
  for (const headroom::Phase& p : m.phases)
    if (p.probe_cpu_s_per_s) {
      out << "probe CPU time: " << format_number("%.4f", *p.probe_cpu_s_per_s) << " s per s (phase " << p.name << ")\n";
    }
}

}  // namespace bs::cli
