// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/power/borrowed_voltage.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/power/power.h"
#include "analysis/power/power_time.h"

namespace bs {

bool borrow_voltage(PowerTrace& target, const PowerTrace& source, const std::string& channel) {
  const PowerChannel* v = nullptr;
  for (const PowerChannel& c : source.channels)
    if (c.name == channel && c.quantity == PowerQuantity::Voltage && c.values.size() == source.time_s.size()) v = &c;
  if (!v || source.time_s.empty()) return false;
  // Seconds to add to a target time to get the source's time of the same moment.
  double shift = 0;
  const auto t0 = parse_date_time(target.start_time), s0 = parse_date_time(source.start_time);
  if (t0 && s0) shift = *t0 - *s0;
  const std::vector<double>& st = source.time_s;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  PowerChannel out{channel + " from " + source.label, PowerQuantity::Voltage, {}};
  out.values.reserve(target.time_s.size());
  for (const double t : target.time_s) {
    const double s = t + shift;
    if (!(s >= st.front() && s <= st.back())) {
      out.values.push_back(nan);
      continue;
    }
    const auto hi = std::lower_bound(st.begin(), st.end(), s);
    const std::size_t k = static_cast<std::size_t>(hi - st.begin());
    if (*hi == s || k == 0) {
      out.values.push_back(v->values[k]);
      continue;
    }
    const double a = v->values[k - 1], b = v->values[k];
    const double span = st[k] - st[k - 1];
    // A missing neighbour (NaN) stays missing: interpolation never invents a reading.
    out.values.push_back(span > 0 ? a + (b - a) * (s - st[k - 1]) / span : b);
  }
  // The borrowed channel is the log's voltage; any earlier borrowed one is replaced.
  std::erase_if(target.channels, [](const PowerChannel& c) {
    return c.quantity == PowerQuantity::Voltage && c.name.find(" from ") != std::string::npos;
  });
  target.channels.push_back(std::move(out));
  return true;
}

std::optional<std::string> why_no_power(const PowerTrace& trace) {
  if (!main_channel(trace, PowerQuantity::Current) && !main_channel(trace, PowerQuantity::Power))
    return std::string("no current or power channel");
  // What power_series() needs, checked without computing it (a log may hold 100 million samples).
  if (main_channel(trace, PowerQuantity::Power) || main_channel(trace, PowerQuantity::Voltage) ||
      trace.supply_voltage_v)
    return std::nullopt;
  return std::string(
      "current only: no voltage channel and no supply voltage (right-click the log in the workspace tree > "
      "Supply voltage…)");
}

}  // namespace bs
