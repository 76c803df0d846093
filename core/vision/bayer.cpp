// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/bayer.h"

#include <cmath>
#include <limits>
#include <stdexcept>

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

template <class T>
void demosaic_ours(const cv::Mat& raw, BayerPattern p, bool mhc, cv::Mat& out) {
  const int rows = raw.rows, cols = raw.cols;
  const double maxv = static_cast<double>(std::numeric_limits<T>::max());
  auto at = [&](int r, int c) { return static_cast<double>(raw.at<T>(reflect(r, rows), reflect(c, cols))); };
#pragma omp parallel for schedule(static)
  for (int r = 0; r < rows; ++r) {
    auto* dst = out.ptr<cv::Vec<T, 3>>(r);
    for (int c = 0; c < cols; ++c) {
      const int here = bayer_channel(p, r, c);
      const double v = at(r, c);
      double ch[3];
      ch[here] = v;
      // Neighbour averages: cross (N,S,E,W), diagonal, horizontal pair, vertical pair.
      const double cross = (at(r - 1, c) + at(r + 1, c) + at(r, c - 1) + at(r, c + 1)) / 4;
      const double diag = (at(r - 1, c - 1) + at(r - 1, c + 1) + at(r + 1, c - 1) + at(r + 1, c + 1)) / 4;
      const double horiz = (at(r, c - 1) + at(r, c + 1)) / 2;
      const double vert = (at(r - 1, c) + at(r + 1, c)) / 2;
      if (!mhc) {
        if (here == 1) {
          // Green site: the row neighbours carry one of R/B, the column neighbours the other.
          const int row_colour = bayer_channel(p, r, c + 1);
          ch[row_colour] = horiz;
          ch[2 - row_colour] = vert;
        } else {
          ch[1] = cross;
          ch[2 - here] = diag;
        }
      } else {
        // Malvar-He-Cutler: bilinear estimate plus a scaled Laplacian of the measured channel (kernels / 8).
        const double n2 = at(r - 2, c) + at(r + 2, c), w2 = at(r, c - 2) + at(r, c + 2);
        if (here == 1) {
          const int row_colour = bayer_channel(p, r, c + 1);
          const double d = at(r - 1, c - 1) + at(r - 1, c + 1) + at(r + 1, c - 1) + at(r + 1, c + 1);
          // Colour in the same row: 5v + 4(E+W) - (diagonals) - (W2+E2) + (N2+S2)/2, over 8.
          ch[row_colour] = (5 * v + 8 * horiz - d - w2 + 0.5 * n2) / 8;
          ch[2 - row_colour] = (5 * v + 8 * vert - d - n2 + 0.5 * w2) / 8;
        } else {
          ch[1] = (4 * v + 8 * cross - n2 - w2) / 8;
          ch[2 - here] = (6 * v + 8 * diag - 1.5 * (n2 + w2)) / 8;
        }
      }
      for (int k = 0; k < 3; ++k) dst[c][k] = static_cast<T>(std::clamp(std::round(ch[k]), 0.0, maxv));
    }
  }
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
