// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/sustained_cli.h"

#include <ostream>

#include "common/text_table.h"

namespace bs::cli {

nlohmann::json sustained_json(const sustain::SustainRequirement& r, const std::vector<sustain::SustainVerdict>& v) {
  nlohmann::json list = nlohmann::json::array();
  for (const sustain::SustainVerdict& s : v) {
    nlohmann::json checks = nlohmann::json::array();
    for (const ConstraintCheck& k : s.checks)
      checks.push_back({{"name", k.name},
                        {"unit", k.unit},
                        {"required", k.required},
                        {"actual", k.actual ? nlohmann::json(*k.actual) : nlohmann::json(nullptr)},
                        {"met", k.met},
                        {"margin", k.margin}});
    list.push_back({{"platform", s.platform},
                    {"status", std::string(to_string(s.status))},
                    {"margin", s.margin},
                    {"reason", s.reason},
                    {"record", s.record},
                    {"checks", checks}});
  }
  return {{"requirement", r.text}, {"described", sustain::describe(r)}, {"platforms", list}};
}

void print_sustained(std::ostream& out, const sustain::SustainRequirement& r,
                     const std::vector<sustain::SustainVerdict>& v) {
  out << "\nsustained: " << sustain::describe(r) << "\n";
  TextTable t({"platform", "verdict", "margin / reason", "record"});
  for (const sustain::SustainVerdict& s : v)
    t.add({s.platform, std::string(to_string(s.status)), s.status == RequirementStatus::Pass ? s.margin : s.reason,
           s.record.empty() ? "–" : s.record});
  t.print(out);
  out << "(a platform without a sustained run that answers every term is unknown, never passing; an imported log\n"
         " without a load rate judges throttling only)\n";
}

}  // namespace bs::cli
