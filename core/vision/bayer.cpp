// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/bayer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

namespace bs::vision {
namespace {

// Top-left 2x2 cell of each pattern, row-major: colour index at (0,0), (0,1), (1,0), (1,1).
constexpr int kCells[4][4] = {{0, 1, 1, 2}, {2, 1, 1, 0}, {1, 2, 0, 1}, {1, 0, 2, 1}};

int reflect(int i, int n) {
  if (i < 0) return -i;
  if (i >= n) return 2 * n - 2 - i;
  return i;
}

// OpenCV names its Bayer codes after the pixels in the second row, second and third columns ("BayerRG" = R, G
// there), so a BGGR sensor (row 1: G R G R) is COLOR_BayerRG2BGR; the test checks this against ground truth.
int opencv_code(BayerPattern p, DemosaicMethod m) {
  static const int bilinear[4] = {cv::COLOR_BayerRG2BGR, cv::COLOR_BayerBG2BGR, cv::COLOR_BayerGB2BGR, cv::COLOR_BayerGR2BGR};
  static const int ea[4] = {cv::COLOR_BayerRG2BGR_EA, cv::COLOR_BayerBG2BGR_EA, cv::COLOR_BayerGB2BGR_EA, cv::COLOR_BayerGR2BGR_EA};
  static const int vng[4] = {cv::COLOR_BayerRG2BGR_VNG, cv::COLOR_BayerBG2BGR_VNG, cv::COLOR_BayerGB2BGR_VNG, cv::COLOR_BayerGR2BGR_VNG};
  const int i = static_cast<int>(p);
  return m == DemosaicMethod::OpenCvEdgeAware ? ea[i] : m == DemosaicMethod::OpenCvVng ? vng[i] : bilinear[i];
}

// Our demosaic of the pixel at (r, c) in integers; `at(dr, dc)` reads the mosaic at (r + dr, c + dc). The
// arithmetic is the textbook one scaled to integers, rounded half up and clamped:
//  bilinear  a measured channel is copied; a missing one is the mean of its 2 or 4 nearest samples;
//  MHC       Malvar, He, Cutler (2004), eq. (and Fig. 2): bilinear estimate plus a scaled Laplacian of the
//            measured channel, i.e. their 5x5 kernels, whose weights are multiples of 1/16.
template <class T, class At>
inline void demosaic_pixel(At at, int here, int row_colour, bool mhc, int maxv, T* dst) {
  const int v = at(0, 0);
  const int e = at(0, 1), w = at(0, -1), n = at(-1, 0), s = at(1, 0);
  int ch[3];
  ch[here] = v;
  if (!mhc) {
    if (here == 1) {
      ch[row_colour] = (w + e + 1) >> 1;
      ch[2 - row_colour] = (n + s + 1) >> 1;
    } else {
      ch[1] = (n + s + w + e + 2) >> 2;
      ch[2 - here] = (at(-1, -1) + at(-1, 1) + at(1, -1) + at(1, 1) + 2) >> 2;
    }
  } else {
    const int n2 = at(-2, 0) + at(2, 0), w2 = at(0, -2) + at(0, 2);
    if (here == 1) {
      const int d = at(-1, -1) + at(-1, 1) + at(1, -1) + at(1, 1);
      // Colour in the same row: (10 v + 8 (E + W) - 2 diagonals - 2 (W2 + E2) + (N2 + S2)) / 16; the column
      // colour is the same kernel turned by 90 degrees.
      ch[row_colour] = (10 * v + 8 * (w + e) - 2 * d - 2 * w2 + n2 + 8) >> 4;
      ch[2 - row_colour] = (10 * v + 8 * (n + s) - 2 * d - 2 * n2 + w2 + 8) >> 4;
    } else {
      const int d = at(-1, -1) + at(-1, 1) + at(1, -1) + at(1, 1);
      ch[1] = (4 * v + 2 * (n + s + w + e) - n2 - w2 + 4) >> 3;
      ch[2 - here] = (12 * v + 4 * d - 3 * (n2 + w2) + 8) >> 4;
    }
  }
  for (int k = 0; k < 3; ++k) dst[k] = static_cast<T>(std::clamp(ch[k], 0, maxv));
}

template <class T>
void demosaic_ours(const cv::Mat& raw, BayerPattern p, bool mhc, cv::Mat& out) {
  const int rows = raw.rows, cols = raw.cols;
  const int maxv = std::numeric_limits<T>::max();
  // Stripes of rows on OpenCV's pool, as the fused path (fused.cpp says why not OpenMP).
  cv::parallel_for_(cv::Range(0, rows), [&](const cv::Range& range) {
  for (int r = range.start; r < range.end; ++r) {
    // Rows r-2 .. r+2 with the top and bottom reflected, so only the left and right edges need the slow reader.
    const T* row[5];
    for (int k = 0; k < 5; ++k) row[k] = raw.ptr<T>(reflect(r - 2 + k, rows));
    T* dst = out.ptr<T>(r);
    const auto edge = [&](int c) {
      const auto at = [&](int dr, int dc) { return static_cast<int>(row[2 + dr][reflect(c + dc, cols)]); };
      demosaic_pixel<T>(at, bayer_channel(p, r, c), bayer_channel(p, r, c + 1), mhc, maxv, dst + 3 * c);
    };
    const int margin = std::min(2, cols);
    for (int c = 0; c < margin; ++c) edge(c);
    // The two site kinds of this row alternate: even and odd columns each get a branch-free inner loop.
    for (int parity = 0; parity < 2; ++parity) {
      const int here = bayer_channel(p, r, parity), row_colour = bayer_channel(p, r, parity + 1);
      for (int c = 2 + parity; c < cols - 2; c += 2) {
        const auto at = [&](int dr, int dc) { return static_cast<int>(row[2 + dr][c + dc]); };
        demosaic_pixel<T>(at, here, row_colour, mhc, maxv, dst + 3 * c);
      }
    }
    for (int c = std::max(margin, cols - 2); c < cols; ++c) edge(c);
  }
  }, std::max(1.0, rows / 16.0));
}

}  // namespace

std::string_view to_string(BayerPattern p) {
  static const char* names[] = {"BGGR", "RGGB", "GRBG", "GBRG"};
  return names[static_cast<int>(p)];
}

BayerPattern bayer_pattern_from_string(std::string_view s) {
  for (int i = 0; i < 4; ++i)
    if (to_string(static_cast<BayerPattern>(i)) == s) return static_cast<BayerPattern>(i);
  throw std::invalid_argument("unknown Bayer pattern '" + std::string(s) + "' (expected BGGR, RGGB, GRBG or GBRG)");
}

std::string_view to_string(DemosaicMethod m) {
  static const char* names[] = {"bilinear", "mhc", "opencv", "opencv-ea", "opencv-vng"};
  return names[static_cast<int>(m)];
}

DemosaicMethod demosaic_method_from_string(std::string_view s) {
  for (int i = 0; i < 5; ++i)
    if (to_string(static_cast<DemosaicMethod>(i)) == s) return static_cast<DemosaicMethod>(i);
  throw std::invalid_argument("unknown demosaic method '" + std::string(s) +
                              "' (expected bilinear, mhc, opencv, opencv-ea or opencv-vng)");
}

int bayer_channel(BayerPattern p, int row, int col) { return kCells[static_cast<int>(p)][(row & 1) * 2 + (col & 1)]; }

cv::Mat mosaic(const cv::Mat& bgr, BayerPattern p) {
  if (bgr.type() != CV_8UC3 && bgr.type() != CV_16UC3) throw std::invalid_argument("mosaic needs an 8- or 16-bit BGR image");
  cv::Mat out(bgr.size(), bgr.depth() == CV_8U ? CV_8UC1 : CV_16UC1);
  for (int r = 0; r < bgr.rows; ++r)
    for (int c = 0; c < bgr.cols; ++c) {
      const int ch = bayer_channel(p, r, c);
      if (bgr.depth() == CV_8U) out.at<std::uint8_t>(r, c) = bgr.at<cv::Vec3b>(r, c)[ch];
      else out.at<std::uint16_t>(r, c) = bgr.at<cv::Vec3w>(r, c)[ch];
    }
  return out;
}

cv::Mat demosaic(const cv::Mat& raw, BayerPattern p, DemosaicMethod m) {
  if (raw.type() != CV_8UC1 && raw.type() != CV_16UC1)
    throw std::invalid_argument("demosaic needs a single-channel 8- or 16-bit mosaic");
  if (raw.rows < 4 || raw.cols < 4) throw std::invalid_argument("demosaic needs at least 4x4 pixels");
  if (m == DemosaicMethod::OpenCvBilinear || m == DemosaicMethod::OpenCvEdgeAware || m == DemosaicMethod::OpenCvVng) {
    if (m == DemosaicMethod::OpenCvVng && raw.depth() != CV_8U) throw std::invalid_argument("OpenCV's VNG is 8-bit only");
    cv::Mat out;
    cv::cvtColor(raw, out, opencv_code(p, m));
    return out;
  }
  cv::Mat out(raw.size(), raw.depth() == CV_8U ? CV_8UC3 : CV_16UC3);
  const bool mhc = m == DemosaicMethod::MalvarHeCutler;
  if (raw.depth() == CV_8U) demosaic_ours<std::uint8_t>(raw, p, mhc, out);
  else demosaic_ours<std::uint16_t>(raw, p, mhc, out);
  return out;
}

double psnr(const cv::Mat& a, const cv::Mat& b, int border) {
  if (a.size() != b.size() || a.type() != b.type()) throw std::invalid_argument("psnr needs images of equal size and type");
  const cv::Rect inner(border, border, a.cols - 2 * border, a.rows - 2 * border);
  cv::Mat da, db;
  a(inner).convertTo(da, CV_64F);
  b(inner).convertTo(db, CV_64F);
  cv::Mat diff = da - db;
  const double mse = cv::mean(diff.mul(diff))[0] + cv::mean(diff.mul(diff))[1] + cv::mean(diff.mul(diff))[2];
  if (mse == 0) return std::numeric_limits<double>::infinity();
  const double peak = a.depth() == CV_8U ? 255.0 : 65535.0;
  return 10 * std::log10(peak * peak / (mse / a.channels()));
}

}  // namespace bs::vision
