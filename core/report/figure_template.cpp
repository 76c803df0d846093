// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/figure_template.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace bs {

bool FigureTemplate::selects(const FlopsRun& run) const {
  if (device_kind && run.device_kind != *device_kind) return false;
  if (!platforms.empty() && std::find(platforms.begin(), platforms.end(), run.platform) == platforms.end())
    return false;
  if (!dims.empty() && std::find(dims.begin(), dims.end(), run.dims) == dims.end()) return false;
  return true;
}

std::vector<FigureTemplate> parse_figure_templates(const std::string& text, const std::string& name) {
  const auto doc = nlohmann::json::parse(text, nullptr, false);
  if (doc.is_discarded()) throw std::runtime_error(name + ": not valid JSON");
  if (!doc.is_object() || doc.value("format", "") != "benchscope-figures")
    throw std::runtime_error(name + ": /format must be \"benchscope-figures\"");
  if (doc.value("version", 0) != 1) throw std::runtime_error(name + ": /version must be 1");
  if (!doc.contains("figures") || !doc["figures"].is_array())
    throw std::runtime_error(name + ": /figures must be an array");
  std::vector<FigureTemplate> out;
  for (std::size_t i = 0; i < doc["figures"].size(); ++i) {
    const auto& f = doc["figures"][i];
    const std::string where = name + ": /figures/" + std::to_string(i);
    try {
      FigureTemplate t;
      t.id = f.at("id").get<std::string>();
      t.kind = f.at("kind").get<std::string>();
      if (t.kind != "flops" && t.kind != "current" && t.kind != "triptych" && t.kind != "inference" &&
          t.kind != "headroom")
        throw std::runtime_error("/kind must be flops, current, triptych, inference or headroom");
      if (t.id.empty() || t.id.find_first_of("/\\.") != std::string::npos)
        throw std::runtime_error("/id must be a plain file stem");
      t.title = f.value("title", "");
      if (f.contains("device_kind")) {
        const std::string k = f["device_kind"].get<std::string>();
        if (k != "gpu" && k != "cpu") throw std::runtime_error("/device_kind must be gpu or cpu");
        t.device_kind = k == "gpu" ? DeviceKind::Gpu : DeviceKind::Cpu;
      }
      t.platforms = f.value("platforms", std::vector<std::string>{});
      t.dims = f.value("dims", std::vector<int>{});
      t.x_label = f.value("x_label", "");
      t.y_label = f.value("y_label", "");
      t.y_scale = f.value("y_scale", 1.0);
      if (!(t.y_scale > 0)) throw std::runtime_error("/y_scale must be > 0");
      t.log_x = f.value("log_x", false);
      t.log_y = f.value("log_y", false);
      t.optional = f.value("optional", false);
      out.push_back(std::move(t));
    } catch (const nlohmann::json::exception& e) {
      throw std::runtime_error(where + ": " + e.what());
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(where + e.what());
    }
  }
  return out;
}

std::vector<FigureTemplate> load_figure_templates(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error(path + ": cannot read the figure template");
  std::stringstream ss;
  ss << f.rdbuf();
  return parse_figure_templates(ss.str(), path);
}

std::optional<double> preset_width_mm(const std::string& preset) {
  if (preset == "lncs") return 122.0;
  if (preset == "lncs-half") return 58.0;
  if (preset == "ieee") return 88.9;
  if (preset == "ieee-double") return 181.0;
  return std::nullopt;
}

}  // namespace bs
