// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/run_label_store.h"

#include <algorithm>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "util/text.h"

namespace bs {
namespace {

constexpr const char* kPrefix = "run-label/";

// What identifies a run's content: its series and its measurement, not its row id.
std::string fingerprint(const FlopsRun& r) {
  std::string s = r.platform + '\x1f' + r.device + '\x1f' + r.backend + '\x1f' + r.kernel + '\x1f' + r.variant +
                  '\x1f' + std::to_string(r.dims) + '\x1f' + std::to_string(r.iterations) + '\x1f' + r.provenance.date +
                  '\x1f' + r.provenance.host + '\x1f' + r.provenance.source_file + '\x1f' +
                  std::to_string(r.samples.size());
  if (!r.samples.empty() && !r.samples.front().seconds.empty())
    s += '\x1f' + std::to_string(r.samples.front().seconds.front()) + '\x1f' +
         std::to_string(r.samples.back().seconds.empty() ? 0.0 : r.samples.back().seconds.back());
  return content_hash(s);
}

std::size_t utf8_chars(const std::string& s) {
  return static_cast<std::size_t>(std::count_if(s.begin(), s.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

}  // namespace

void set_run_label(Workspace& ws, const StoredRun& run, std::string_view label) {
  const std::string text(trim(label));
  if (utf8_chars(text) > kMaxRunLabelChars)
    throw std::invalid_argument("run label longer than " + std::to_string(kMaxRunLabelChars) + " characters");
  if (std::any_of(text.begin(), text.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; }))
    throw std::invalid_argument("run label with a control character (a line break or tab)");
  const auto runs = ws.runs();
  if (std::none_of(runs.begin(), runs.end(), [&](const StoredRun& r) { return r.id == run.id; }))
    throw WorkspaceError(WorkspaceError::Kind::Constraint, "no run with id " + std::to_string(run.id));
  const std::string key = kPrefix + std::to_string(run.id);
  if (text.empty()) {
    ws.remove_setting(key);
    return;
  }
  ws.set_setting(key, nlohmann::json{{"label", text}, {"run", fingerprint(run.run)}}.dump());
}

std::map<std::int64_t, std::string> run_labels(const Workspace& ws, const std::vector<StoredRun>& runs) {
  std::map<std::int64_t, std::string> stored;
  for (const auto& [key, value] : ws.settings(kPrefix)) {
    try {
      stored[std::stoll(key.substr(std::string(kPrefix).size()))] = value;
    } catch (const std::exception&) {
      // a key that is not ours to read: ignored
    }
  }
  std::map<std::int64_t, std::string> out;
  for (const StoredRun& r : runs) {
    const auto it = stored.find(r.id);
    if (it == stored.end()) continue;
    const nlohmann::json j = nlohmann::json::parse(it->second, nullptr, false);
    if (!j.is_object() || !j.contains("label") || !j["label"].is_string() || !j.contains("run") ||
        j["run"] != fingerprint(r.run))
      continue;
    out[r.id] = j["label"].get<std::string>();
  }
  return out;
}

std::vector<std::string> run_labels_in_order(const Workspace& ws) {
  const auto runs = ws.runs();
  const auto labels = run_labels(ws, runs);
  std::vector<std::string> out;
  for (const StoredRun& r : runs) {
    const auto it = labels.find(r.id);
    out.push_back(it == labels.end() ? std::string() : it->second);
  }
  return out;
}

}  // namespace bs
