// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/stats/units.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "util/text.h"

namespace bs {
namespace {

// std::to_chars, not printf: the GUI runs under the user's locale (Qt calls setlocale), and "5,25 TFLOPS" from a
// German desktop would differ from the CLI and from exported tables.
}  // namespace

int si_exponent(double value) noexcept {
  const double a = std::fabs(value);
  if (a == 0.0 || !std::isfinite(a)) return 0;
  int e = static_cast<int>(std::floor(std::log10(a) / 3.0)) * 3;
  if (e < -12) e = -12;
  if (e > 18) e = 18;
  return e;
}

std::string_view si_prefix(int exponent) noexcept {
  switch (exponent) {
    case -12:
      return "p";
    case -9:
      return "n";
    case -6:
      return "\xC2\xB5";  // micro sign, UTF-8
    case -3:
      return "m";
    case 3:
      return "k";
    case 6:
      return "M";
    case 9:
      return "G";
    case 12:
      return "T";
    case 15:
      return "P";
    case 18:
      return "E";
    default:
      return "";
  }
}

std::string format_si(double value, std::string_view unit, int decimals) {
  if (!std::isfinite(value)) return std::string(std::isnan(value) ? "NaN " : (value > 0 ? "inf " : "-inf ")) += unit;
  int e = si_exponent(value);
  std::string out = fixed(value / std::pow(10.0, e), decimals);
  // 999.999e9 rounds to "1000.00" at two decimals: move to the next prefix so the mantissa stays below 1000.
  double shown = 0;
  std::from_chars(out.data(), out.data() + out.size(), shown);
  if (e < 18 && std::fabs(shown) >= 1000.0) {
    e += 3;
    out = fixed(value / std::pow(10.0, e), decimals);
  }
  out += ' ';
  out += si_prefix(e);
  out += unit;
  return out;
}

std::string format_mean_sd(double mean, double sd, std::size_t n, std::string_view unit, int decimals) {
  std::string out = fixed(mean, decimals) + " \xC2\xB1 " + fixed(sd, decimals);
  if (!unit.empty()) (out += ' ') += unit;
  out += " (n = " + std::to_string(n) + ")";
  return out;
}

}  // namespace bs
