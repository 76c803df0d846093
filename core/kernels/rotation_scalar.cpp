// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>
#include <vector>

#include "kernels/rotation.h"

namespace bs::kernels {

float rotation_cos() { return static_cast<float>(std::cos(2.0)); }
float rotation_sin() { return static_cast<float>(std::sin(2.0)); }

double closed_form_output(const RotationParams& p) {
  const double a = 2.0 * static_cast<double>(p.iterations);
  return p.dims * (std::cos(a) + std::sin(a));
}

double output_tolerance(const RotationParams& p) {
  return p.dims * (1e-5 + 1.2e-7 * static_cast<double>(p.iterations));
}

std::int64_t first_wrong_output(std::span<const float> outputs, const RotationParams& p) {
  const double expected = closed_form_output(p);
  const double tol = output_tolerance(p);
  for (std::size_t i = 0; i < outputs.size(); ++i)
    if (!(std::abs(outputs[i] - expected) <= tol)) return static_cast<std::int64_t>(i);
  return -1;
}

void rotate_scalar(const RotationParams& p, std::span<float> outputs) {
  const float c = rotation_cos(), s = rotation_sin();
  std::vector<float> x(static_cast<std::size_t>(p.dims)), y(static_cast<std::size_t>(p.dims));
  for (float& out : outputs) {
    for (int d = 0; d < p.dims; ++d) {
      x[static_cast<std::size_t>(d)] = 1.0f;
      y[static_cast<std::size_t>(d)] = 0.0f;
    }
    for (std::int64_t n = 0; n < p.iterations; ++n)
      for (std::size_t d = 0; d < x.size(); ++d) {
        const float nx = c * x[d] - s * y[d];
        y[d] = s * x[d] + c * y[d];
        x[d] = nx;
      }
    float sum = 0;
    for (std::size_t d = 0; d < x.size(); ++d) sum += x[d] + y[d];
    out = sum;
  }
}

}  // namespace bs::kernels
