// SPDX-License-Identifier: GPL-3.0-or-later
#include "kernels/worker_spec.h"

#include <algorithm>
#include <charconv>
#include <stdexcept>
#include <string>

namespace bs::kernels {
namespace {

std::int64_t number(std::string_view text, std::string_view part) {
  std::int64_t v = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec == std::errc::result_out_of_range)
    throw std::invalid_argument("'" + std::string(part) + "': number too large");
  if (ec != std::errc() || ptr != text.data() + text.size() || text.empty())
    throw std::invalid_argument("'" + std::string(part) + "': expected a whole number, got '" + std::string(text) + "'");
  if (v < 1) throw std::invalid_argument("'" + std::string(part) + "': numbers must be at least 1");
  return v;
}

std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (true) {
    const auto pos = s.find(sep, start);
    out.push_back(s.substr(start, pos == std::string_view::npos ? std::string_view::npos : pos - start));
    if (pos == std::string_view::npos) break;
    start = pos + 1;
  }
  return out;
}

}  // namespace

std::vector<std::int64_t> parse_worker_spec(std::string_view spec, std::size_t max_points) {
  if (spec.empty()) throw std::invalid_argument("empty worker list");
  std::vector<std::int64_t> out;
  for (std::string_view part : split(spec, ',')) {
    const auto range = split(part, ':');
    if (range.size() == 1) {
      out.push_back(number(range[0], part));
    } else if (range.size() == 3) {
      const std::int64_t start = number(range[0], part), stop = number(range[1], part), step = number(range[2], part);
      if (start > stop) throw std::invalid_argument("'" + std::string(part) + "': start is greater than stop");
      if (static_cast<std::size_t>((stop - start) / step) + 1 + out.size() > max_points)
        throw std::invalid_argument("'" + std::string(part) + "': more than " + std::to_string(max_points) + " points");
      for (std::int64_t w = start; w <= stop; w += step) out.push_back(w);
    } else {
      throw std::invalid_argument("'" + std::string(part) + "': expected N or START:STOP:STEP");
    }
    if (out.size() > max_points) throw std::invalid_argument("more than " + std::to_string(max_points) + " points");
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<int> parse_dims_list(std::string_view spec) {
  std::vector<int> out;
  for (std::string_view part : split(spec, ',')) {
    const std::int64_t d = number(part, part);
    if (d > 64) throw std::invalid_argument("'" + std::string(part) + "': D must be between 1 and 64");
    out.push_back(static_cast<int>(d));
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace bs::kernels
