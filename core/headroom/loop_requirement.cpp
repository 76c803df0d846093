// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/loop_requirement.h"

#include "analysis/platform/requirement_text.h"
#include "analysis/platform/requirement_verdicts.h"
#include "util/text.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace bs::headroom {
namespace {

[[noreturn]] void bad(const std::string& term, const std::string& why) {
  throw std::invalid_argument("loop requirement term '" + term + "': " + why +
                              " (terms: 1kHz | 500Hz, p50|p99|p99.9|p99.99|max<=TIME (ns, us, ms), misses<=PERCENT%, "
                              "max-consecutive-misses<=N, load=PHASE)");
}

double number_with_unit(const std::string& term, const std::string& text,
                        const std::vector<std::pair<std::string, double>>& units) {
  for (const auto& [suffix, scale] : units) {
    if (text.size() <= suffix.size() || text.compare(text.size() - suffix.size(), suffix.size(), suffix) != 0) continue;
    const std::string digits = text.substr(0, text.size() - suffix.size());
    char* end = nullptr;
    const double v = std::strtod(digits.c_str(), &end);
    if (*end != '\0' || !(v >= 0) || !std::isfinite(v)) bad(term, "'" + digits + "' is not a number");
    return v * scale;
  }
  std::string names;
  for (const auto& u : units) names += (names.empty() ? "" : ", ") + u.first;
  bad(term, "'" + text + "' needs a unit (" + names + ")");
}

std::string us_text(double us) { return format_number(us == std::floor(us) ? "%.0f" : "%.1f", us); }

struct Candidate {
  const HeadroomMeasurement* m = nullptr;
  const Phase* phase = nullptr;
  const ThreadLatency* thread = nullptr;
};

}  // namespace

LoopRequirement parse_loop_requirement(const std::string& text) {
  LoopRequirement r;
  r.text = text;
  const std::vector<std::string> terms = comma_terms(text);
  const std::vector<std::pair<std::string, double>> time_units = {{"ns", 1}, {"us", 1e3}, {"ms", 1e6}};
  for (const std::string& term : terms) {
    const std::string t = lower(term);
    if (t.rfind("load=", 0) == 0) {
      r.load = term.substr(5);
      if (r.load.empty()) bad(term, "names no phase");
      continue;
    }
    const auto le = t.find("<=");
    if (le == std::string::npos) {
      if (r.rate_hz > 0) bad(term, "the rate is given twice, or a term lacks '<='");
      r.rate_hz = number_with_unit(term, t, {{"khz", 1e3}, {"hz", 1}});
      if (!(r.rate_hz >= 1 && r.rate_hz <= 100'000)) bad(term, "rate outside 1 Hz .. 100 kHz");
      continue;
    }
    const std::string key = t.substr(0, le), value = t.substr(le + 2);
    const auto time = [&] {
      return static_cast<std::int64_t>(std::llround(number_with_unit(term, value, time_units)));
    };
    if (key == "p50")
      r.p50_ns = time();
    else if (key == "p99")
      r.p99_ns = time();
    else if (key == "p99.9")
      r.p999_ns = time();
    else if (key == "p99.99")
      r.p9999_ns = time();
    else if (key == "max")
      r.max_ns = time();
    else if (key == "misses")
      r.max_miss_percent = number_with_unit(term, value, {{"%", 1}});
    else if (key == "max-consecutive-misses") {
      char* end = nullptr;
      const long long n = std::strtoll(value.c_str(), &end, 10);
      if (value.empty() || *end != '\0' || n < 0) bad(term, "'" + value + "' is not a whole number of cycles");
      r.max_consecutive_misses = static_cast<std::uint64_t>(n);
    } else {
      bad(term, "unknown term '" + key + "'");
    }
  }
  if (r.rate_hz <= 0) bad(text, "no loop rate (e.g. 1kHz)");
  if (!r.p50_ns && !r.p99_ns && !r.p999_ns && !r.p9999_ns && !r.max_ns && !r.max_miss_percent &&
      !r.max_consecutive_misses)
    bad(text, "no limit to check");
  return r;
}

std::string describe(const LoopRequirement& r) {
  std::string s = r.rate_hz >= 1000 ? format_number("%g kHz", r.rate_hz / 1000) : format_number("%g Hz", r.rate_hz);
  const auto lim = [&](const char* name, const std::optional<std::int64_t>& v) {
    if (v) s += std::string(", ") + name + " <= " + us_text(static_cast<double>(*v) / 1000) + " us";
  };
  lim("p50", r.p50_ns);
  lim("p99", r.p99_ns);
  lim("p99.9", r.p999_ns);
  lim("p99.99", r.p9999_ns);
  lim("max", r.max_ns);
  if (r.max_miss_percent) s += format_number(", misses <= %g %%", *r.max_miss_percent);
  if (r.max_consecutive_misses) s += ", max consecutive misses <= " + std::to_string(*r.max_consecutive_misses);
  s += r.load.empty() ? ", in every phase" : ", beside " + r.load;
  return s;
}

std::vector<LoopVerdict> evaluate_loop(const LoopRequirement& r, std::span<const HeadroomMeasurement> measurements,
                                       const std::vector<std::string>& platforms) {
  std::vector<LoopVerdict> out;
  for (const std::string& platform : platforms_to_judge(platforms, measurements)) {
    LoopVerdict v;
    v.platform = platform;
    // The latest application-loop measurement at the rate (within 1 %) that has the phase asked for.
    const HeadroomMeasurement* chosen = nullptr;
    bool other_kind = false, other_rate = false, no_phase = false;
    for (const HeadroomMeasurement& m : measurements) {
      if (m.platform != platform) continue;
      if (m.kind != LatencyKind::ApplicationLoop) {
        other_kind = true;
        continue;
      }
      bool rate_ok = false;
      for (const Phase& p : m.phases)
        for (const ThreadLatency& t : p.threads) rate_ok |= std::abs(t.rate_hz() - r.rate_hz) <= 0.01 * r.rate_hz;
      if (!rate_ok) {
        other_rate = true;
        continue;
      }
      if (!r.load.empty() && !m.phase(r.load)) {
        no_phase = true;
        continue;
      }
      if (!chosen || m.provenance.date > chosen->provenance.date) chosen = &m;
    }
    if (!chosen) {
      v.reason = no_phase     ? "no headroom measurement beside " + r.load
                 : other_rate ? "no headroom measurement at this rate"
                 : other_kind ? "only system wake-up or message latency measured (not an application loop)"
                              : "no headroom measurement";
      out.push_back(std::move(v));
      continue;
    }
    v.realtime = chosen->realtime();
    // Every (phase, thread) at the rate that the requirement covers; each term takes its worst.
    std::vector<Candidate> cands;
    for (const Phase& p : chosen->phases) {
      if (!r.load.empty() && p.name != r.load) continue;
      for (const ThreadLatency& t : p.threads)
        if (std::abs(t.rate_hz() - r.rate_hz) <= 0.01 * r.rate_hz) cands.push_back({chosen, &p, &t});
    }
    v.measurement = chosen->tool + " " + chosen->provenance.date +
                    (r.load.empty() ? ", every phase" : ", phase " + r.load) + (v.realtime ? "" : ", non-real-time");
    bool unknown = false;
    const auto term = [&](const std::string& name, const std::string& unit, double required, const auto& actual_of) {
      ConstraintCheck k{name + (r.load.empty() ? "" : " (" + r.load + ")"), unit, required, std::nullopt, false, 0};
      for (const Candidate& c : cands) {
        const std::optional<double> a = actual_of(c);
        if (!a) {
          k.actual.reset();
          unknown = true;
          break;
        }
        if (!k.actual || *a > *k.actual) k.actual = a;
      }
      if (k.actual) {
        k.margin = required - *k.actual;
        k.met = k.margin >= 0;
      }
      v.checks.push_back(k);
    };
    const auto pct = [&](double q, const std::optional<std::int64_t>& limit, const char* name) {
      if (!limit) return;
      term(name, "us", static_cast<double>(*limit) / 1000, [q](const Candidate& c) -> std::optional<double> {
        const HistogramPercentile p = c.thread->histogram.percentile(q);
        if (p.at_least) return std::nullopt;  // beyond the histogram: not known to meet or miss a finer limit
        return static_cast<double>(p.ns) / 1000;
      });
    };
    pct(50, r.p50_ns, "p50");
    pct(99, r.p99_ns, "p99");
    pct(99.9, r.p999_ns, "p99.9");
    pct(99.99, r.p9999_ns, "p99.99");
    if (r.max_ns)
      term("max", "us", static_cast<double>(*r.max_ns) / 1000, [](const Candidate& c) -> std::optional<double> {
        if (!c.thread->histogram.max_ns) return std::nullopt;
        return static_cast<double>(*c.thread->histogram.max_ns) / 1000;
      });
    if (r.max_miss_percent)
      term("misses", "%", *r.max_miss_percent, [](const Candidate& c) -> std::optional<double> {
        const LatencySummary s = summarize(*c.thread);
        if (!s.misses || !s.misses_exact) return std::nullopt;
        return s.miss_percent();
      });
    if (r.max_consecutive_misses)
      term("max consecutive misses", "cycles", static_cast<double>(*r.max_consecutive_misses),
           [](const Candidate& c) -> std::optional<double> {
             if (!c.thread->misses) return std::nullopt;
             return static_cast<double>(c.thread->misses->longest_run);
           });
    // A phase whose load fell short of its target measured the loop beside less load than asked: neither a pass nor
    // a fail speaks for the load the robot will run (the checks keep their values, to be seen).
    // `cands` holds each phase's threads one after another: a phase is named once, at its first thread.
    std::string not_applied;
    const Phase* named = nullptr;
    for (const Candidate& c : cands)
      if (c.phase != named && load_not_applied(*c.phase)) {
        not_applied += (not_applied.empty() ? "" : "; ") + load_not_applied_text(*c.phase);
        named = c.phase;
      }
    const bool failed =
        std::any_of(v.checks.begin(), v.checks.end(), [](const ConstraintCheck& k) { return k.actual && !k.met; });
    v.status = !not_applied.empty() ? RequirementStatus::Unknown
               : failed             ? RequirementStatus::Fail
               : unknown            ? RequirementStatus::Unknown
                                    : RequirementStatus::Pass;
    if (!not_applied.empty()) {
      v.reason = not_applied;
    } else if (failed) {
      // The term failed by the largest factor names the failure.
      const ConstraintCheck* worst = nullptr;
      double worst_ratio = 0;
      for (const ConstraintCheck& k : v.checks)
        if (k.actual && !k.met) {
          const double ratio = k.required > 0 ? *k.actual / k.required : INFINITY;
          if (!worst || ratio > worst_ratio) worst = &k, worst_ratio = ratio;
        }
      v.reason = worst->name + " " + format_number("%g", -worst->margin) + " " + worst->unit + " over the limit of " +
                 format_number("%g", worst->required) + " " + worst->unit;
      if (std::isfinite(worst_ratio)) v.reason += format_number(" (%.2fx)", worst_ratio);
    } else if (unknown) {
      v.reason =
          "the measurement cannot answer every term (a percentile beyond its histogram, or misses without run "
          "lengths)";
    }
    out.push_back(std::move(v));
  }
  rank_requirement_verdicts(out);
  return out;
}

std::vector<ConstraintCheck> loop_checks(const std::string& platform, std::span<const LoopVerdict> loop) {
  return requirement_checks(platform, loop, "control loop", "no headroom measurement");
}

void apply_loop(std::vector<PlatformVerdict>& verdicts, std::span<const LoopVerdict> loop) {
  add_requirement_checks(verdicts, [&](const std::string& platform) { return loop_checks(platform, loop); });
}

}  // namespace bs::headroom
