// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/power/power_time.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace bs {
namespace {

// Reads exactly `digits` decimal digits at `pos`.
bool fixed_int(std::string_view s, std::size_t& pos, std::size_t digits, int& out) noexcept {
  if (pos + digits > s.size()) return false;
  out = 0;
  for (std::size_t i = 0; i < digits; ++i) {
    const char c = s[pos + i];
    if (c < '0' || c > '9') return false;
    out = out * 10 + (c - '0');
  }
  pos += digits;
  return true;
}

bool expect(std::string_view s, std::size_t& pos, char c) noexcept {
  if (pos >= s.size() || s[pos] != c) return false;
  ++pos;
  return true;
}

unsigned days_in_month(int year, unsigned month) noexcept {
  static constexpr unsigned days[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  return month == 2 && leap ? 29 : days[month - 1];
}

// "HH:MM:SS[.fff]" -> seconds of the day.
std::optional<double> time_of_day(std::string_view s, std::size_t& pos) noexcept {
  int h = 0, m = 0, sec = 0;
  if (!fixed_int(s, pos, 2, h) || !expect(s, pos, ':') || !fixed_int(s, pos, 2, m) || !expect(s, pos, ':') ||
      !fixed_int(s, pos, 2, sec))
    return std::nullopt;
  if (h > 23 || m > 59 || sec > 60) return std::nullopt;  // 60: a leap second
  double frac = 0;
  if (pos < s.size() && (s[pos] == '.' || s[pos] == ',')) {
    ++pos;
    double scale = 0.1;
    const std::size_t start = pos;
    while (pos < s.size() && s[pos] >= '0' && s[pos] <= '9') {
      frac += (s[pos] - '0') * scale;
      scale /= 10;
      ++pos;
    }
    if (pos == start) return std::nullopt;
  }
  return h * 3600.0 + m * 60.0 + sec + frac;
}

}  // namespace

long long days_from_civil(int year, unsigned month, unsigned day) noexcept {
  // Howard Hinnant's algorithm: shift the year to start in March so the leap day is the last day of the year.
  const long long y = static_cast<long long>(year) - (month <= 2 ? 1 : 0);
  const long long era = (y >= 0 ? y : y - 399) / 400;
  const long long yoe = y - era * 400;
  const long long doy = (153 * (month + (month > 2 ? -3 : 9)) + 2) / 5 + day - 1;
  const long long doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + doe - 719468;
}

namespace {

// "HH:MM:SS[.fff][Z|+hh[:mm]]" from `pos` to the end of `s`, on the date `days` -> seconds since the epoch.
std::optional<double> time_and_zone(std::string_view s, std::size_t pos, long long days, bool* has_offset) noexcept {
  const auto tod = time_of_day(s, pos);
  if (!tod) return std::nullopt;
  double offset_s = 0;
  bool zone = false;
  if (pos < s.size()) {
    if (s[pos] == 'Z' && pos + 1 == s.size()) {
      ++pos;
      zone = true;
    } else if (s[pos] == '+' || s[pos] == '-') {
      const double sign = s[pos] == '-' ? -1 : 1;
      ++pos;
      int oh = 0, om = 0;
      if (!fixed_int(s, pos, 2, oh)) return std::nullopt;
      if (pos < s.size() && s[pos] == ':') ++pos;
      if (!fixed_int(s, pos, 2, om) || oh > 14 || om > 59) return std::nullopt;
      offset_s = sign * (oh * 3600.0 + om * 60.0);
      zone = true;
    }
    if (pos != s.size()) return std::nullopt;
  }
  if (has_offset) *has_offset = zone;
  return static_cast<double>(days) * 86400.0 + *tod - offset_s;
}

bool valid_date(int y, int mo, int d) noexcept {
  return mo >= 1 && mo <= 12 && d >= 1 && static_cast<unsigned>(d) <= days_in_month(y, static_cast<unsigned>(mo));
}

}  // namespace

std::optional<double> parse_iso8601(std::string_view s) noexcept {
  std::size_t pos = 0;
  int y = 0, mo = 0, d = 0;
  if (!fixed_int(s, pos, 4, y) || !expect(s, pos, '-') || !fixed_int(s, pos, 2, mo) || !expect(s, pos, '-') ||
      !fixed_int(s, pos, 2, d))
    return std::nullopt;
  if (!valid_date(y, mo, d)) return std::nullopt;
  if (pos >= s.size() || (s[pos] != 'T' && s[pos] != ' ')) return std::nullopt;
  ++pos;
  return time_and_zone(s, pos, days_from_civil(y, static_cast<unsigned>(mo), static_cast<unsigned>(d)), nullptr);
}

std::optional<double> parse_date_time(std::string_view s, bool* has_offset) noexcept {
  std::size_t pos = 0;
  int y = 0, mo = 0, d = 0;
  if (s.size() >= 10 && (s[4] == '-' || s[4] == '/')) {
    // Year first: "2026-11-22" (ISO) or "2026/11/22" (nvidia-smi).
    const char sep = s[4];
    if (!fixed_int(s, pos, 4, y) || !expect(s, pos, sep) || !fixed_int(s, pos, 2, mo) || !expect(s, pos, sep) ||
        !fixed_int(s, pos, 2, d))
      return std::nullopt;
  } else if (s.size() >= 10 && s[2] == '-' && s[5] == '-') {
    // Month first with dashes: "11-22-2026" (US order, as tegrastats prints it). "11/22/2026" is not read: with
    // slashes it is as often day first, and a silently swapped day and month would shift the log by months.
    if (!fixed_int(s, pos, 2, mo) || !expect(s, pos, '-') || !fixed_int(s, pos, 2, d) || !expect(s, pos, '-') ||
        !fixed_int(s, pos, 4, y))
      return std::nullopt;
  } else {
    return std::nullopt;
  }
  if (!valid_date(y, mo, d)) return std::nullopt;
  if (pos >= s.size() || (s[pos] != 'T' && s[pos] != ' ')) return std::nullopt;
  ++pos;
  return time_and_zone(s, pos, days_from_civil(y, static_cast<unsigned>(mo), static_cast<unsigned>(d)), has_offset);
}

std::optional<double> parse_month_day_year(std::string_view date, std::string_view time) noexcept {
  std::size_t pos = 0;
  int mo = 0, d = 0, y = 0;
  if (!fixed_int(date, pos, 2, mo) || !expect(date, pos, '-') || !fixed_int(date, pos, 2, d) ||
      !expect(date, pos, '-') || !fixed_int(date, pos, 4, y) || pos != date.size())
    return std::nullopt;
  if (mo < 1 || mo > 12 || d < 1 || static_cast<unsigned>(d) > days_in_month(y, static_cast<unsigned>(mo)))
    return std::nullopt;
  std::size_t tpos = 0;
  const auto tod = time_of_day(time, tpos);
  if (!tod || tpos != time.size()) return std::nullopt;
  return static_cast<double>(days_from_civil(y, static_cast<unsigned>(mo), static_cast<unsigned>(d))) * 86400.0 + *tod;
}

std::string format_iso8601(double epoch_s) {
  const double whole = std::floor(epoch_s);
  long long days = static_cast<long long>(std::floor(whole / 86400.0));
  long long sod = static_cast<long long>(whole) - days * 86400;
  // Inverse of days_from_civil (same algorithm, run backwards).
  const long long z = days + 719468;
  const long long era = (z >= 0 ? z : z - 146096) / 146097;
  const long long doe = z - era * 146097;
  const long long yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const long long doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const long long mp = (5 * doy + 2) / 153;
  const long long day = doy - (153 * mp + 2) / 5 + 1;
  const long long month = mp < 10 ? mp + 3 : mp - 9;
  const long long year = yoe + era * 400 + (month <= 2 ? 1 : 0);
  char buf[128];
  const int ms = static_cast<int>(std::lround((epoch_s - whole) * 1000));
  if (ms > 0 && ms < 1000)
    std::snprintf(buf, sizeof buf, "%04lld-%02lld-%02lldT%02lld:%02lld:%02lld.%03d", year, month, day, sod / 3600,
                  sod / 60 % 60, sod % 60, ms);
  else
    std::snprintf(buf, sizeof buf, "%04lld-%02lld-%02lldT%02lld:%02lld:%02lld", year, month, day, sod / 3600,
                  sod / 60 % 60, sod % 60);
  return buf;
}

}  // namespace bs
