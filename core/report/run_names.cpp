// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/run_names.h"

#include <algorithm>
#include <functional>
#include <map>
#include <set>

namespace bs {
namespace {

// "2026-11-26T14:03:12Z" at a precision: 0 day, 1 minute, 2 second; the day is left out when every run of the
// group has the same one ("14:03").
std::string date_at(const std::string& iso, int precision, bool same_day) {
  if (iso.size() < 10) return iso;
  const std::string day = iso.substr(0, 10);
  const std::string time = iso.size() >= 16 ? iso.substr(11, precision >= 2 && iso.size() >= 19 ? 8 : 5) : "";
  if (precision == 0 || time.empty()) return day;
  return same_day ? time : day + " " + time;
}

bool all_distinct(const std::vector<std::string>& names) {
  return std::set<std::string>(names.begin(), names.end()).size() == names.size();
}

}  // namespace

std::vector<std::string> distinct_names(const std::vector<RunIdentity>& runs) {
  std::vector<std::string> names;
  for (const RunIdentity& r : runs) names.push_back(r.label.empty() ? r.base : r.base + " \xE2\x80\x94 " + r.label);
  std::map<std::string, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < names.size(); ++i) groups[names[i]].push_back(i);
  for (const auto& group : groups) {
    // A plain reference, not a structured binding: clang 14 (the sanitizer build) cannot capture bindings in lambdas.
    const std::vector<std::size_t>& members = group.second;
    if (members.size() < 2) continue;
    bool same_day = true;
    for (std::size_t m : members)
      same_day = same_day && runs[m].date.substr(0, 10) == runs[members.front()].date.substr(0, 10);
    std::vector<std::string> added(members.size());
    const auto values_of = [&](const std::function<std::string(const RunIdentity&)>& part) {
      std::vector<std::string> v;
      for (std::size_t m : members) v.push_back(part(runs[m]));
      return v;
    };
    const auto all_same = [](const std::vector<std::string>& v) {
      return std::all_of(v.begin(), v.end(), [&](const std::string& x) { return x == v.front(); });
    };
    const auto add = [&](const std::vector<std::string>& v) {
      for (std::size_t k = 0; k < v.size(); ++k)
        if (!v[k].empty()) added[k] += (added[k].empty() ? "" : ", ") + v[k];
    };
    // The date at the coarsest precision that separates the runs (the day, else the minute, else the second), or
    // the finest if none does; then host, then the detail, each only when it differs.
    std::vector<std::string> date;
    for (int precision = same_day ? 1 : 0; precision <= 2; ++precision) {
      date = values_of([&](const RunIdentity& r) { return date_at(r.date, precision, same_day); });
      if (all_distinct(date)) break;
    }
    if (!all_same(date)) add(date);
    for (const auto& part :
         {std::function<std::string(const RunIdentity&)>([](const RunIdentity& r) { return r.host; }),
          std::function<std::string(const RunIdentity&)>([](const RunIdentity& r) { return r.detail; })}) {
      if (all_distinct(added)) break;
      const auto v = values_of(part);
      if (!all_same(v)) add(v);
    }
    const bool apart = all_distinct(added);
    for (std::size_t k = 0; k < members.size(); ++k) {
      std::string a = added[k];
      if (!apart) a += (a.empty() ? "" : ", ") + std::string("run ") + std::to_string(k + 1);
      names[members[k]] = group.first + (a.empty() ? "" : " (" + a + ")");
    }
  }
  return names;
}

std::vector<std::string> distinguishing_parts(const std::vector<RunIdentity>& runs) {
  const std::vector<std::string> names = distinct_names(runs);
  std::vector<std::string> out;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    std::string rest = names[i].substr(std::min(runs[i].base.size(), names[i].size()));
    const std::string dash = " \xE2\x80\x94 ";
    if (rest.rfind(dash, 0) == 0) rest.erase(0, dash.size());  // " — label (added)" -> "label (added)"
    if (rest.size() >= 3 && rest.rfind(" (", 0) == 0 && rest.back() == ')')
      rest = rest.substr(2, rest.size() - 3);  // " (added)" alone -> "added"
    out.push_back(std::move(rest));
  }
  return out;
}

RunIdentity run_identity(const FlopsRun& run, std::string base, std::string label) {
  return {std::move(base), std::move(label), run.provenance.date, run.provenance.host,
          "N = " + std::to_string(run.iterations)};
}

}  // namespace bs
