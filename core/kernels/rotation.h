// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The paper's benchmark kernel (Biddulph et al. 2018, eq. 1): every worker rotates D 2D points, all starting at
// x0 = (1, 0), by R(2 rad) N times and stores out = sum over its points of (x + y) (the paper's final
// "<x_n,0, x_n,1>" term, (2D - 1) additions, which it leaves out of the FLOPS count). After n steps a point is
// (cos 2n, sin 2n), so every output has the closed form D * (cos 2N + sin 2N).
#include <cstdint>
#include <span>
#include <string>

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

// Scalar reference with the paper's exact semantics: one worker at a time, its D points one after another.
void rotate_scalar(const RotationParams& p, std::span<float> outputs);

}  // namespace bs::kernels
