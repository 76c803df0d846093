// SPDX-License-Identifier: GPL-3.0-or-later
#include "mlperf/loose_files.h"

#include <algorithm>
#include <cctype>
#include <map>

#include "util/text.h"

namespace bs::mlperf_loose {
namespace fs = std::filesystem;
namespace {

constexpr std::string_view kLogSummary = "mlperf_log_summary";
constexpr std::size_t kHeadBytes = 64 * 1024;  // enough for a system or measurements JSON, a summary's banner

bool separator(char c) { return c == '_' || c == '-' || c == '.' || c == ' '; }

std::string head_of(const fs::path& p) {
  try {
    return read_head(p.string(), kHeadBytes);
  } catch (const ImportError&) {
    return {};  // unreadable: not paired, and the import of the file itself says why
  }
}

// The prefix without its trailing separators: what a run's other files start with ("Orin_resnet50_SS").
std::string stem_of(std::string_view prefix) {
  while (!prefix.empty() && separator(prefix.back())) prefix.remove_suffix(1);
  return std::string(prefix);
}

enum class Role { None, Detail, Spl, Measurements };

// The role a file plays by the part of its name after a run's stem ("_detail.txt", "-mlperf_log_detail.txt",
// "_spl.txt", or a measurements JSON by its fields).
Role role_of(std::string_view rest, const fs::path& file) {
  while (!rest.empty() && separator(rest.front())) rest.remove_prefix(1);
  const std::string r = lower(rest);
  if (r.find("summary") != std::string::npos) return Role::None;
  if (r.starts_with("mlperf_log_detail") || r.starts_with("detail")) return Role::Detail;
  if (r.starts_with("spl") || r.starts_with("mlperf_log_spl")) return Role::Spl;
  if (file.extension() == ".json" && description_kind(head_of(file)) == "measurements description")
    return Role::Measurements;
  return Role::None;
}

struct Folder {
  std::vector<fs::path> files;
  std::vector<std::pair<fs::path, std::string>> summaries;  // each LoadGen summary and its stem
};

Folder list(const fs::path& dir) {
  Folder f;
  std::error_code ec;
  for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.empty() || name[0] == '.' || !it->is_regular_file(ec)) continue;
    f.files.push_back(it->path());
  }
  std::sort(f.files.begin(), f.files.end());
  for (const fs::path& p : f.files)
    if (const auto prefix = run_prefix(p.filename().string());
        prefix && head_of(p).find("MLPerf Results Summary") != std::string::npos)
      f.summaries.emplace_back(p, stem_of(*prefix));
  return f;
}

// The summary of `folder` whose stem is the longest one `name` starts with (then a separator); nullptr when none,
// or when two summaries with that stem claim it.
const fs::path* owner(const Folder& folder, std::string_view name) {
  const fs::path* best = nullptr;
  std::size_t best_len = 0;
  bool tie = false;
  for (const auto& [summary, stem] : folder.summaries) {
    if (stem.empty() || !name.starts_with(stem) || name.size() == stem.size() || !separator(name[stem.size()]))
      continue;
    if (!best || stem.size() > best_len) {
      best = &summary;
      best_len = stem.size();
      tie = false;
    } else if (stem.size() == best_len) {
      tie = true;
    }
  }
  return tie ? nullptr : best;
}

std::string role_name(Role r) {
  return r == Role::Detail ? "detail log" : r == Role::Spl ? "power log (spl)" : "measurements JSON";
}

// The JSON files in `folder` and in its `sub` folder whose head says they are a `kind` ("system description",
// "measurements description"): a submission keeps them beside the summary or in systems/ and measurements/.
std::vector<fs::path> descriptions_in(const fs::path& folder, const char* sub, std::string_view kind) {
  std::vector<fs::path> found;
  for (const fs::path& dir : {folder, folder / sub}) {
    std::error_code ec;
    for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec))
      if (it->path().extension() == ".json" && description_kind(head_of(it->path())) == kind)
        found.push_back(it->path());
  }
  return found;
}

// The one system description for a summary: the only one beside it (or in systems/), or among several the one whose
// name ("Orin_TRT_MaxQ.system.json" -> "Orin_TRT_MaxQ") the summary's name contains, the longest such.
void pair_system(const fs::path& folder, const std::string& summary_name, LooseFiles& out) {
  std::vector<fs::path> found = descriptions_in(folder, "systems", "system description");
  std::sort(found.begin(), found.end());
  const auto system_of = [](const fs::path& p) {
    std::string s = p.stem().string();
    if (lower(s).ends_with(".system")) s.resize(s.size() - 7);
    return s;
  };
  const fs::path* chosen = found.size() == 1 ? &found.front() : nullptr;
  for (const fs::path& f : found)
    if (found.size() > 1 && summary_name.find(system_of(f)) != std::string::npos &&
        (!chosen || system_of(f).size() > system_of(*chosen).size()))
      chosen = &f;
  if (chosen) {
    out.system = chosen->string();
  } else if (found.size() > 1) {
    out.system_note = std::to_string(found.size()) + " system descriptions beside it, none named by it";
  }
}

}  // namespace

std::optional<std::string> run_prefix(std::string_view name) {
  std::size_t at = name.find(kLogSummary);
  if (at == std::string_view::npos) at = lower(name).rfind("summary");
  if (at == std::string_view::npos) return std::nullopt;
  return std::string(name.substr(0, at));
}

std::string description_kind(std::string_view text) {
  const auto has = [&](std::string_view k) { return text.find(k) != std::string_view::npos; };
  if (!text.empty() && has("\"system_name\"") && has("\"submitter\"") && has("\"host_processor_model_name\""))
    return "system description";
  if (has("\"weight_data_types\"") && has("\"input_data_types\"")) return "measurements description";
  return {};
}

LooseFiles loose_files_of(const fs::path& summary, const ImportLimits& /*limits*/) {
  LooseFiles out;
  const std::string name = summary.filename().string();
  const auto prefix = run_prefix(name);
  if (!prefix) return out;
  const fs::path dir = summary.parent_path();
  const Folder folder = list(dir);
  // 1. The summary's own name with its role word for "summary": "X_detail.txt", "X-mlperf_log_detail.txt".
  const bool log_name = name.find(kLogSummary) != std::string::npos;
  const std::string suffix = name.substr(prefix->size() + (log_name ? kLogSummary.size() : 7));
  const auto exact = [&](std::initializer_list<std::string_view> words) -> std::string {
    for (std::string_view w : words)
      if (std::error_code ec; fs::is_regular_file(dir / (*prefix + std::string(w) + suffix), ec))
        return (dir / (*prefix + std::string(w) + suffix)).string();
    return {};
  };
  out.detail = log_name ? exact({"mlperf_log_detail"}) : exact({"detail", "mlperf_log_detail"});
  out.spl = exact({"spl"});
  // 2. Else what starts with its stem and names its role, claimed by no longer stem of another summary.
  const std::string stem = stem_of(*prefix);
  std::map<Role, std::vector<fs::path>> by_role;
  if (!stem.empty())
    for (const fs::path& f : folder.files) {
      const std::string n = f.filename().string();
      if (f == summary || !n.starts_with(stem)) continue;
      const fs::path* o = owner(folder, n);
      if (!o || *o != summary) continue;
      if (const Role r = role_of(std::string_view(n).substr(stem.size()), f); r != Role::None) by_role[r].push_back(f);
    }
  const auto take = [&](Role r, std::string& path) {
    if (!path.empty()) return;
    const auto it = by_role.find(r);
    if (it == by_role.end()) return;
    if (it->second.size() == 1) {
      path = it->second.front().string();
      return;
    }
    std::string names;
    for (const fs::path& p : it->second) names += (names.empty() ? "" : ", ") + p.filename().string();
    std::string& note = r == Role::Measurements ? out.measurements_note : out.pairing_note;
    note += (note.empty() ? "" : "; ") + std::to_string(it->second.size()) + " files could be its " + role_name(r) +
            " (" + names + "): none taken";
  };
  take(Role::Detail, out.detail);
  take(Role::Spl, out.spl);
  take(Role::Measurements, out.measurements);
  // 3. A measurements JSON names no network ("Orin_TRT_MaxQ_SingleStream.json" for every one): without the prefix it
  // is the summary's only when the two are alone in the folder.
  if (out.measurements.empty()) {
    const std::vector<fs::path> all = descriptions_in(dir, "measurements", "measurements description");
    if (all.size() == 1 && folder.summaries.size() == 1) {
      out.measurements = all.front().string();
    } else if (!all.empty() && out.measurements_note.empty()) {
      out.measurements_note = std::to_string(all.size()) + " measurements description(s) beside it, none named " +
                              (stem.empty() ? std::string("for it") : "with its prefix '" + *prefix + "'");
    }
  }
  pair_system(dir, name, out);
  return out;
}

}  // namespace bs::mlperf_loose
