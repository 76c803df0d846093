// SPDX-License-Identifier: GPL-3.0-or-later
#include "kernels/worker_spec.h"

#include "kernels/rotation/rotation.h"

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
    throw std::invalid_argument("'" + std::string(part) + "': expected a whole number, got '" + std::string(text) +
                                "'");
  if (v < 1) throw std::invalid_argument("'" + std::string(part) + "': numbers must be at least 1");
  return v;
}

std::int64_t worker_count(std::string_view text, std::string_view part) {
  const std::int64_t v = number(text, part);
  if (v > kMaxStatePoints)
    throw std::invalid_argument("'" + std::string(part) + "': more than " + std::to_string(kMaxStatePoints) +
                                " workers (the state would not fit in memory)");
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
      out.push_back(worker_count(range[0], part));
    } else if (range.size() == 3) {
      const std::int64_t start = worker_count(range[0], part), stop = worker_count(range[1], part),
                         step = number(range[2], part);
      if (start > stop) throw std::invalid_argument("'" + std::string(part) + "': start is greater than stop");
      const auto count = static_cast<std::size_t>((stop - start) / step) + 1;
      if (count + out.size() > max_points)
        throw std::invalid_argument("'" + std::string(part) + "': more than " + std::to_string(max_points) + " points");
      // start + i * step <= stop for every i < count: no signed overflow near INT64_MAX.
      for (std::size_t i = 0; i < count; ++i) out.push_back(start + static_cast<std::int64_t>(i) * step);
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
