// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/lens/points_json.h"

#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace bs::vision {

template <class T>
std::vector<cv::Point_<T>> points_from_json(const nlohmann::json& j, const std::string& at, bool finite) {
  if (!j.is_array()) throw std::invalid_argument(at + ": expected an array of [x, y] points");
  std::vector<cv::Point_<T>> out;
  for (std::size_t k = 0; k < j.size(); ++k) {
    const auto& p = j[k];
    if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
      throw std::invalid_argument(at + "/" + std::to_string(k) + ": expected [x, y] numbers");
    const T x = p[0].get<T>(), y = p[1].get<T>();
    if (finite && (!std::isfinite(x) || !std::isfinite(y)))
      throw std::invalid_argument(at + "/" + std::to_string(k) + ": coordinates must be finite");
    out.emplace_back(x, y);
  }
  return out;
}

template std::vector<cv::Point_<float>> points_from_json(const nlohmann::json&, const std::string&, bool);
template std::vector<cv::Point_<double>> points_from_json(const nlohmann::json&, const std::string&, bool);

}  // namespace bs::vision
