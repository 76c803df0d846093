// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <string_view>

namespace bs {

// Formats with an SI prefix chosen so the mantissa is in [1, 1000): format_si(5.25e12, "FLOPS", 2) ->
// "5.25 TFLOPS". Zero, NaN and infinities are printed plainly with the unit.
std::string format_si(double value, std::string_view unit, int decimals = 2);

// The prefix exponent (multiple of 3, clamped to [-12, 18]) format_si would choose for `value`.
int si_exponent(double value) noexcept;
// "k", "M", "G", "T", ... for an exponent from si_exponent(); "" for 0.
std::string_view si_prefix(int exponent) noexcept;

// "6.21 ± 0.99 ms (n = 200)": mean ± SD with the count, as BenchScope shows every repeated measurement.
std::string format_mean_sd(double mean, double sd, std::size_t n, std::string_view unit, int decimals = 2);

}  // namespace bs
