// SPDX-License-Identifier: GPL-3.0-or-later
#include "kernels/ceilings/ceiling_cache.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "util/host_clock.h"

namespace bs::kernels {
namespace {

using json = nlohmann::json;
constexpr const char* kFormat = "benchscope-ceilings-cache";

json ceiling_json(const Ceiling& c) {
  return {{"unit", c.unit}, {"values", c.values}, {"per_cpu_second", c.per_cpu_second}, {"how", c.how}};
}

Ceiling ceiling_from(const json& j) {
  Ceiling c;
  c.unit = j.at("unit").get<std::string>();
  c.values = j.at("values").get<std::vector<double>>();
  c.per_cpu_second = j.at("per_cpu_second").get<std::vector<double>>();
  c.how = j.at("how").get<std::string>();
  return c;
}

bool same_key(const CeilingSet& a, const CeilingSet& b) {
  return a.host == b.host && a.cpu_model == b.cpu_model && a.isa == b.isa && a.threads == b.threads;
}

}  // namespace

std::string ceiling_cache_path() {
  namespace fs = std::filesystem;
  if (const char* d = std::getenv("BENCHSCOPE_CACHE_DIR"); d && *d) return (fs::path(d) / "ceilings.json").string();
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x)
    return (fs::path(x) / "benchscope" / "ceilings.json").string();
  const char* home = std::getenv("HOME");
  return (fs::path(home && *home ? home : ".") / ".cache" / "benchscope" / "ceilings.json").string();
}

std::vector<CeilingSet> load_ceiling_cache(const std::string& path) {
  std::ifstream f(path);
  if (!f) return {};
  json doc;
  try {
    doc = json::parse(f);
  } catch (const json::exception& e) {
    throw std::runtime_error(path + ": not JSON (" + e.what() + ")");
  }
  if (!doc.is_object() || doc.value("format", "") != kFormat)
    throw std::runtime_error(path + ": field \"format\" is not \"" + kFormat + "\"");
  std::vector<CeilingSet> out;
  const json& entries = doc.contains("entries") ? doc["entries"] : json::array();
  for (std::size_t i = 0; i < entries.size(); ++i) {
    try {
      const json& e = entries[i];
      CeilingSet s;
      s.host = e.at("host").get<std::string>();
      s.cpu_model = e.at("cpu_model").get<std::string>();
      s.backend = e.at("backend").get<std::string>();
      s.isa = e.at("isa").get<std::string>();
      s.threads = e.at("threads").get<int>();
      s.clock_hz = e.at("clock_hz").get<double>();
      s.computed_peak_flops = e.at("computed_peak_flops").get<double>();
      s.date = e.at("date").get<std::string>();
      s.rotation_mix = ceiling_from(e.at("rotation_mix"));
      s.fma = ceiling_from(e.at("fma"));
      s.bandwidth = ceiling_from(e.at("bandwidth"));
      // "kind" came with the device ceilings; entries written before it are the CPU's.
      const std::string kind = e.value("kind", std::string("cpu"));
      if (kind != "cpu" && kind != "gpu" && kind != "other")
        throw std::runtime_error("field \"kind\" is \"" + kind + "\", not cpu, gpu or other");
      s.kind = device_kind_from_string(kind);
      out.push_back(std::move(s));
    } catch (const std::exception& e) {
      throw std::runtime_error(path + ": entries[" + std::to_string(i) + "]: " + e.what());
    }
  }
  return out;
}

std::optional<CeilingSet> cached_ceilings(const CpuInfo& cpu, const std::string& path) {
  CeilingSet key;
  key.host = host_name();
  key.cpu_model = cpu.model;
  key.isa = isa_id(cpu.simd.isa);
  key.threads = cpu.threads;
  try {
    for (CeilingSet& s : load_ceiling_cache(path))
      if (same_key(s, key)) return std::move(s);
  } catch (const std::runtime_error&) {
    // A damaged cache is as good as none: the next measurement rewrites it.
  }
  return std::nullopt;
}

std::optional<CeilingSet> cached_device_ceilings(const Backend& backend, const std::string& path) {
  if (!backend.ceiling_kernels) return std::nullopt;
  CeilingSet key;
  key.host = host_name();
  key.cpu_model = backend.device_name;
  key.isa = device_ceiling_family(backend);
  key.threads = 0;
  try {
    for (CeilingSet& s : load_ceiling_cache(path))
      if (same_key(s, key)) return std::move(s);
  } catch (const std::runtime_error&) {
    // as cached_ceilings: a damaged cache is as good as none
  }
  return std::nullopt;
}

void store_ceilings(const CeilingSet& set, const std::string& path) {
  std::vector<CeilingSet> all;
  try {
    all = load_ceiling_cache(path);
  } catch (const std::runtime_error&) {
    all.clear();  // replaced by a readable file below
  }
  std::erase_if(all, [&](const CeilingSet& s) { return same_key(s, set); });
  all.push_back(set);
  json entries = json::array();
  for (const CeilingSet& s : all)
    entries.push_back({{"host", s.host},
                       {"cpu_model", s.cpu_model},
                       {"backend", s.backend},
                       {"isa", s.isa},
                       {"threads", s.threads},
                       {"clock_hz", s.clock_hz},
                       {"computed_peak_flops", s.computed_peak_flops},
                       {"kind", std::string(to_string(s.kind))},
                       {"date", s.date},
                       {"rotation_mix", ceiling_json(s.rotation_mix)},
                       {"fma", ceiling_json(s.fma)},
                       {"bandwidth", ceiling_json(s.bandwidth)}});
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::trunc);
    if (!f) throw std::runtime_error(path + ": cannot write the ceilings cache");
    f << json{{"format", kFormat}, {"version", 1}, {"entries", entries}}.dump(2) << '\n';
    if (!f) throw std::runtime_error(path + ": cannot write the ceilings cache");
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw std::runtime_error(path + ": cannot replace the ceilings cache (" + ec.message() + ")");
}

}  // namespace bs::kernels
