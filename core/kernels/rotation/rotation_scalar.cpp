// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernels/rotation/rotation.h"

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

void check_problem_size(const RotationParams& p, std::int64_t workers) {
  if (workers < 1 || p.dims < 1 || p.iterations < 1)
    throw std::invalid_argument("workers, D and N must all be at least 1 (got W = " + std::to_string(workers) +
                                ", D = " + std::to_string(p.dims) + ", N = " + std::to_string(p.iterations) + ")");
  if (workers > kMaxStatePoints / p.dims)
    throw std::invalid_argument("W = " + std::to_string(workers) + " workers x D = " + std::to_string(p.dims) +
                                " points is more than " + std::to_string(kMaxStatePoints) + " points of state");
}

ScalarRotation::ScalarRotation(const RotationParams& p, std::int64_t workers) : params_(p), workers_(workers) {
  check_problem_size(p, workers);
  xs_.assign(static_cast<std::size_t>(workers * p.dims), 1.0f);  // x0 = (1, 0)
  ys_.assign(xs_.size(), 0.0f);
}

void ScalarRotation::advance(std::int64_t steps) {
  const float c = rotation_cos(), s = rotation_sin();
  const auto dims = static_cast<std::size_t>(params_.dims);
  for (std::size_t w = 0; w < static_cast<std::size_t>(workers_); ++w) {
    float* x = xs_.data() + w * dims;
    float* y = ys_.data() + w * dims;
    for (std::int64_t n = 0; n < steps; ++n)
      for (std::size_t d = 0; d < dims; ++d) {
        const float nx = c * x[d] - s * y[d];
        y[d] = s * x[d] + c * y[d];
        x[d] = nx;
      }
  }
}

void ScalarRotation::outputs(std::span<float> out) const {
  const auto dims = static_cast<std::size_t>(params_.dims);
  for (std::size_t w = 0; w < static_cast<std::size_t>(workers_) && w < out.size(); ++w) {
    float sum = 0;
    for (std::size_t d = 0; d < dims; ++d) sum += xs_[w * dims + d] + ys_[w * dims + d];
    out[w] = sum;
  }
}

void rotate_scalar(const RotationParams& p, std::span<float> outputs) {
  if (outputs.empty()) return;
  ScalarRotation state(p, static_cast<std::int64_t>(outputs.size()));
  state.advance(p.iterations);
  state.outputs(outputs);
}

}  // namespace bs::kernels
