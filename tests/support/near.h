// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Whether two figures agree to a relative tolerance (of the larger one): a figure a test computes by hand and the
// one the code computes differ in the last bits, never in what they say.
#include <algorithm>
#include <cmath>

namespace bs::test {

inline bool near(double a, double b, double relative = 1e-9) {
  return std::abs(a - b) <= relative * std::max(std::abs(a), std::abs(b));
}

}  // namespace bs::test
