// SPDX-License-Identifier: GPL-3.0-or-later
#include "sustain/sustain_requirement.h"

#include "analysis/platform/requirement_text.h"
#include "analysis/platform/requirement_verdicts.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "sustain/sustain_analysis.h"
#include "util/text.h"

namespace bs::sustain {
namespace {

[[noreturn]] void bad(const std::string& term, const std::string& why) {
  throw std::invalid_argument("sustained requirement term '" + term + "': " + why +
                              " (terms: stability>=PERCENT%, minutes>=N, throttle=none, sustained>=RATE)");
}

// A number > 0 followed by nothing or by `suffix` (when given); returns the number and what followed it.
std::pair<double, std::string> number_then(const std::string& term, const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || !std::isfinite(v) || !(v > 0)) bad(term, "'" + text + "' is not a number > 0");
  return {v, std::string(end)};
}

double minutes_of(const SustainRun& run) { return run.t_s.empty() ? 0.0 : run.t_s.back() / 60; }

// One record judged against the requirement, before the record for the platform is chosen.
struct Judged {
  RequirementStatus status = RequirementStatus::Unknown;
  std::vector<ConstraintCheck> checks;
  std::vector<std::string> margins, fails, unknowns;
};

Judged judge(const SustainRequirement& r, const SustainRun& run) {
  Judged j;
  const SustainAnalysis a = analyse(run);
  const double minutes = minutes_of(run);
  const bool short_run = r.min_minutes && minutes < *r.min_minutes;
  const std::string no_rate = run.rate.empty() ? "no load rate in the record (an imported log)" : "no interval rate";
  if (r.min_minutes) {
    const double need = *r.min_minutes;
    j.checks.push_back({"run length", "min", need, minutes, !short_run, minutes - need});
    j.margins.push_back("run " + format_number("%.1f", minutes) + " min " + (short_run ? "< " : ">= ") +
                        format_number("%g", need) + " min");
    if (short_run)
      j.unknowns.push_back("run lasted " + format_number("%.1f", minutes) + " min < " + format_number("%g", need) +
                           " min required: cannot say");
  }
  if (r.min_stability_percent) {
    const double need = *r.min_stability_percent;
    if (!a.stability_percent) {
      j.unknowns.push_back(no_rate + ": stability cannot be judged");
    } else {
      // Worst / best over a longer run can only be lower: a short run's failure is a failure.
      const double s = *a.stability_percent, margin = s - need;
      j.checks.push_back({"stability", "% of best", need, s, margin >= 0, margin});
      const std::string text = "stability " + format_number("%.1f", s) + " % " + (margin >= 0 ? ">= " : "< ") +
                               format_number("%g", need) + " %, " + format_number("%.1f", std::abs(margin)) +
                               " points " + (margin >= 0 ? "to spare" : "short");
      j.margins.push_back(text);
      if (margin < 0) j.fails.push_back(text);
    }
  }
  if (r.no_throttle) {
    const Throttle& t = a.throttle;
    if (!t.known) {
      std::string why = t.unknown_reason;
      if (why.rfind("unknown: ", 0) == 0) why.erase(0, 9);
      j.unknowns.push_back("throttling unknown: " + why);
    } else {
      // Throttling seen stays seen however long the run goes on.
      j.checks.push_back({"throttling", "s throttled", 0, t.throttled_s, !t.detected, -t.throttled_s});
      if (t.detected) {
        std::string text = "throttled from " + format_number("%.1f", t.onset_s.value_or(0)) + " s";
        if (!t.what.empty()) text += " (" + t.what.front() + ")";
        j.margins.push_back(text);
        j.fails.push_back(text);
      } else {
        j.margins.push_back("no throttling");
      }
    }
  }
  if (r.min_sustained_rate) {
    const double need = *r.min_sustained_rate;
    if (!a.has_rate || a.sustained.n == 0) {
      j.unknowns.push_back(no_rate + ": the sustained rate cannot be judged");
    } else if (!short_run) {  // the last third of a short run says nothing of the last third of a long one
      const double s = a.sustained.mean, margin = s - need;
      const std::string unit = run.rate_unit;
      j.checks.push_back({"sustained rate", unit, need, s, margin >= 0, margin});
      const std::string text = "sustained rate " + format_number("%.1f", s) + " " + unit +
                               (margin >= 0 ? " >= " : " < ") + format_number("%g", need) + " " + unit + ", " +
                               format_number("%.1f", std::abs(margin)) + " " + unit +
                               (margin >= 0 ? " to spare" : " short");
      j.margins.push_back(text);
      if (margin < 0) j.fails.push_back(text);
    }
  }
  j.status = !j.fails.empty()      ? RequirementStatus::Fail
             : !j.unknowns.empty() ? RequirementStatus::Unknown
                                   : RequirementStatus::Pass;
  return j;
}

std::string record_text(const SustainRun& run) {
  std::string s = run.label.empty() ? std::string("unnamed record") : run.label;
  if (!run.provenance.date.empty()) s += ", " + run.provenance.date;
  s += ", " + format_number("%.1f", minutes_of(run)) + " min";
  if (run.rate_unit.empty() || run.rate.empty()) s += ", no load rate";
  return s;
}

}  // namespace

SustainRequirement parse_sustain_requirement(const std::string& text) {
  SustainRequirement r;
  r.text = text;
  const std::vector<std::string> terms = comma_terms(text);
  if (terms.empty()) bad(text, "no term to check");
  for (const std::string& term : terms) {
    const std::string t = lower(term);
    const auto ge = t.find(">=");
    if (ge == std::string::npos) {
      if (t == "throttle=none") {
        if (r.no_throttle) bad(term, "given twice");
        r.no_throttle = true;
        continue;
      }
      if (t.rfind("throttle=", 0) == 0) bad(term, "only throttle=none is accepted");
      bad(term, "a term is KEY>=VALUE or throttle=none");
    }
    const std::string key = t.substr(0, ge), value = t.substr(ge + 2);
    const auto once = [&](const auto& field) {
      if (field) bad(term, "'" + key + "' is given twice");
    };
    if (key == "stability") {
      once(r.min_stability_percent);
      const auto [v, rest] = number_then(term, value);
      if (!rest.empty() && rest != "%") bad(term, "'" + rest + "' is not a percent sign");
      if (v > 100) bad(term, "stability is at most 100 %");
      r.min_stability_percent = v;
    } else if (key == "minutes") {
      once(r.min_minutes);
      const auto [v, rest] = number_then(term, value);
      if (!rest.empty() && rest != "min") bad(term, "'" + rest + "' is not minutes (min)");
      r.min_minutes = v;
    } else if (key == "sustained") {
      once(r.min_sustained_rate);
      const auto [v, rest] = number_then(term, value);
      // The rate is in the judged record's own unit: a unit here would suggest a conversion that does not happen.
      if (!rest.empty()) bad(term, "'" + rest + "' follows the rate; it is a number in the record's own unit");
      r.min_sustained_rate = v;
    } else {
      bad(term, "unknown term '" + key + "'");
    }
  }
  return r;
}

std::string describe(const SustainRequirement& r) {
  std::vector<std::string> parts;
  if (r.min_stability_percent) parts.push_back("stability >= " + format_number("%g", *r.min_stability_percent) + " %");
  if (r.min_minutes) parts.push_back("at least " + format_number("%g", *r.min_minutes) + " min");
  if (r.no_throttle) parts.push_back("no throttling");
  if (r.min_sustained_rate) parts.push_back("sustained rate >= " + format_number("%g", *r.min_sustained_rate));
  return join(parts, ", ");
}

std::vector<SustainVerdict> evaluate_sustain(const SustainRequirement& r, std::span<const SustainRun> runs,
                                             const std::vector<std::string>& platforms) {
  std::vector<SustainVerdict> out;
  for (const std::string& platform : platforms_to_judge(platforms, runs)) {
    SustainVerdict v;
    v.platform = platform;
    // The longest record that answers every term, else the newest (the later one in the list on equal dates).
    const SustainRun* chosen = nullptr;
    std::optional<Judged> judged;
    const SustainRun* newest = nullptr;
    for (const SustainRun& run : runs) {
      if (run.platform != platform) continue;
      if (!newest || run.provenance.date >= newest->provenance.date) newest = &run;
      Judged j = judge(r, run);
      if (j.status == RequirementStatus::Unknown) continue;
      if (!chosen || minutes_of(run) > minutes_of(*chosen)) {
        chosen = &run;
        judged = std::move(j);
      }
    }
    if (!chosen && newest) {
      chosen = newest;
      judged = judge(r, *newest);
    }
    if (!chosen) {
      v.reason = "no sustained run of this platform";
      out.push_back(std::move(v));
      continue;
    }
    v.status = judged->status;
    v.checks = std::move(judged->checks);
    v.margin = join(judged->margins, "; ");
    v.reason = v.status == RequirementStatus::Fail      ? join(judged->fails, "; ")
               : v.status == RequirementStatus::Unknown ? join(judged->unknowns, "; ")
                                                        : std::string();
    v.record = record_text(*chosen);
    out.push_back(std::move(v));
  }
  rank_requirement_verdicts(out);
  return out;
}

std::vector<ConstraintCheck> sustain_checks(const std::string& platform, std::span<const SustainVerdict> verdicts) {
  return requirement_checks(platform, verdicts, "sustained", "no sustained run of this platform");
}

void apply_sustain(std::vector<PlatformVerdict>& verdicts, std::span<const SustainVerdict> sustain) {
  add_requirement_checks(verdicts, [&](const std::string& platform) { return sustain_checks(platform, sustain); });
}

}  // namespace bs::sustain
