// SPDX-License-Identifier: GPL-3.0-or-later
#include "kernels/measured_set_home.h"

#include <nlohmann/json.hpp>

#include "model/provenance_json.h"
#include "store/workspace.h"
#include "util/home_name.h"

namespace bs {
namespace {

// The set as JSON, only for its hash: no file format writes result sets, and date + note alone (the GUI's old
// recipe) tells two measurements apart only by their second and settings, not by what they measured.
nlohmann::json hashed_json(const ResultSet& set) {
  nlohmann::json measurements = nlohmann::json::array();
  for (const Measurement& m : set.measurements)
    measurements.push_back({{"name", m.name}, {"metric", m.metric}, {"unit", m.unit}, {"values", m.values}});
  return {{"platform", set.platform},
          {"device", set.device},
          {"device_kind", std::string(to_string(set.device_kind))},
          {"backend", set.backend},
          {"source_format", set.source_format},
          {"provenance", provenance_to_json(set.provenance, true)},
          {"measurements", measurements}};
}

}  // namespace

HomeBatch measured_set_home(const ResultSet& set, const std::string& where) {
  HomeBatch out;
  out.batch.source_path = home_name(where, set.platform, set.provenance.date);
  out.batch.format = set.source_format;
  out.batch.result_sets = {set};
  out.content_hash = content_hash(hashed_json(set).dump());
  return out;
}

}  // namespace bs
