// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/log_platform.h"

#include <algorithm>
#include <cctype>

namespace bs {
namespace {

bool same_ignoring_case(const std::string& a, const std::string& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

std::string spelled_as_known(const std::string& name, const std::vector<std::string>& known) {
  for (const std::string& k : known)
    if (same_ignoring_case(k, name)) return k;
  return name;
}

}  // namespace

bool blank_platform(const std::string& name) { return name.find_first_not_of(" \t\r\n") == std::string::npos; }

LogPlatformGuess infer_log_platform(const PowerTrace& trace, const std::vector<std::string>& known) {
  if (!blank_platform(trace.platform)) return {trace.platform, "named in the file"};
  return infer_platform(trace.provenance, trace.label.empty() ? std::string("power log") : trace.label, known);
}

LogPlatformGuess infer_platform(const Provenance& provenance, const std::string& label,
                                const std::vector<std::string>& known) {
  // Settings a logger writes about the machine it measured, most specific first.
  for (const char* key : {"platform", "board", "machine", "hostname", "host", "device"})
    for (const auto& [k, v] : provenance.settings)
      if (same_ignoring_case(k, key) && !blank_platform(v))
        return {spelled_as_known(v, known), "the file's \"" + k + "\" setting"};
  if (!blank_platform(provenance.host)) return {spelled_as_known(provenance.host, known), "the file's host name"};
  std::vector<std::string> distinct;
  for (const std::string& k : known)
    if (!blank_platform(k) && std::find(distinct.begin(), distinct.end(), k) == distinct.end()) distinct.push_back(k);
  if (distinct.size() == 1) return {distinct.front(), "the workspace's only platform"};
  return {"unassigned: " + label, "nothing in the file or the workspace names it"};
}

}  // namespace bs
