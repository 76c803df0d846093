// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The paper's benchmark kernel (Biddulph et al. 2018, eq. 1): every worker rotates D 2D points, all starting at
// x0 = (1, 0), by R(2 rad) N times and stores out = sum over its points of (x + y).
// Our reading of the paper's final "out_n = <x_n,0, x_n,1>": the sum of the point's two components, summed over the
// D points. An inner product of the two scalars x_n,0 and x_n,1 would be one multiply, but the paper counts this
// term as (2D - 1) flops per worker, which is exactly the additions that sum 2D values. It leaves those out of the
// FLOPS count, and so do we. After n steps a point is (cos 2n, sin 2n), so every output has the closed form
// D * (cos 2N + sin 2N), which is what every backend's outputs are checked against.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace bs::kernels {

struct RotationParams {
  int dims = 4;                     // D
  std::int64_t iterations = 40000;  // N
};

// cos(2) and sin(2) as the float constants every backend uses.
float rotation_cos();
float rotation_sin();

// The exact value every output should approach, and the float tolerance we accept: rounding in a float rotation
// grows about linearly with N (measured 7.7e-4 at N = 40,000); 1.2e-7 per step per point plus 1e-5 covers it.
double closed_form_output(const RotationParams& p);
double output_tolerance(const RotationParams& p);

// Checks every output against the closed form; returns the index of the first bad one, or -1.
std::int64_t first_wrong_output(std::span<const float> outputs, const RotationParams& p);

// Every backend holds W * D points of state (x and y floats); above this many (2 GiB) a request is refused before
// anything is allocated. The paper's largest point is 1,024,000 workers x 4 = 4.1e6 points.
constexpr std::int64_t kMaxStatePoints = std::int64_t{1} << 28;

// Throws std::invalid_argument naming the problem when W, D or N is below 1 or W * D exceeds kMaxStatePoints.
void check_problem_size(const RotationParams& p, std::int64_t workers);

// Scalar reference with the paper's exact semantics: every worker rotates its own D points (plain floats, no
// vectors, one thread), stepping them together; advance() can be called in chunks so a long run stays cancellable.
class ScalarRotation {
 public:
  ScalarRotation(const RotationParams& p, std::int64_t workers);
  void advance(std::int64_t steps);
  void outputs(std::span<float> out) const;  // one per worker: sum over its D points of (x + y)

 private:
  RotationParams params_;
  std::int64_t workers_;
  std::vector<float> xs_, ys_;  // worker-major: worker w's points at [w * D, (w + 1) * D)
};

// All N steps at once: outputs.size() workers.
void rotate_scalar(const RotationParams& p, std::span<float> outputs);

}  // namespace bs::kernels
