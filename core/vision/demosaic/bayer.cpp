// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/demosaic/bayer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include "vision/demosaic/bayer_reference.h"
#include "vision/demosaic/bayer_simd.h"

namespace bs::vision {
namespace {

// Top-left 2x2 cell of each pattern, row-major: colour index at (0,0), (0,1), (1,0), (1,1).
constexpr int kCells[4][4] = {{0, 1, 1, 2}, {2, 1, 1, 0}, {1, 2, 0, 1}, {1, 0, 2, 1}};

// OpenCV names its Bayer codes after the pixels in the second row, second and third columns ("BayerRG" = R, G
// there), so a BGGR sensor (row 1: G R G R) is COLOR_BayerRG2BGR; the test checks this against ground truth.
int opencv_code(BayerPattern p, DemosaicMethod m) {
  static const int bilinear[4] = {cv::COLOR_BayerRG2BGR, cv::COLOR_BayerBG2BGR, cv::COLOR_BayerGB2BGR,
                                  cv::COLOR_BayerGR2BGR};
  static const int ea[4] = {cv::COLOR_BayerRG2BGR_EA, cv::COLOR_BayerBG2BGR_EA, cv::COLOR_BayerGB2BGR_EA,
                            cv::COLOR_BayerGR2BGR_EA};
  static const int vng[4] = {cv::COLOR_BayerRG2BGR_VNG, cv::COLOR_BayerBG2BGR_VNG, cv::COLOR_BayerGB2BGR_VNG,
                             cv::COLOR_BayerGR2BGR_VNG};
  const int i = static_cast<int>(p);
  return m == DemosaicMethod::OpenCvEdgeAware ? ea[i] : m == DemosaicMethod::OpenCvVng ? vng[i] : bilinear[i];
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
  if (bgr.type() != CV_8UC3 && bgr.type() != CV_16UC3)
    throw std::invalid_argument("mosaic needs an 8- or 16-bit BGR image");
  cv::Mat out(bgr.size(), bgr.depth() == CV_8U ? CV_8UC1 : CV_16UC1);
  for (int r = 0; r < bgr.rows; ++r)
    for (int c = 0; c < bgr.cols; ++c) {
      const int ch = bayer_channel(p, r, c);
      if (bgr.depth() == CV_8U)
        out.at<std::uint8_t>(r, c) = bgr.at<cv::Vec3b>(r, c)[ch];
      else
        out.at<std::uint16_t>(r, c) = bgr.at<cv::Vec3w>(r, c)[ch];
    }
  return out;
}

void demosaic(const cv::Mat& raw, BayerPattern p, DemosaicMethod m, cv::Mat& out) {
  detail::check_demosaic_input(raw);
  if (m == DemosaicMethod::OpenCvBilinear || m == DemosaicMethod::OpenCvEdgeAware || m == DemosaicMethod::OpenCvVng) {
    if (m == DemosaicMethod::OpenCvVng && raw.depth() != CV_8U)
      throw std::invalid_argument("OpenCV's VNG is 8-bit only");
    cv::cvtColor(raw, out, opencv_code(p, m));
    return;
  }
  out.create(raw.size(), raw.depth() == CV_8U ? CV_8UC3 : CV_16UC3);
  demosaic_simd(raw, p, m == DemosaicMethod::MalvarHeCutler, out);
}

cv::Mat demosaic(const cv::Mat& raw, BayerPattern p, DemosaicMethod m) {
  cv::Mat out;
  demosaic(raw, p, m, out);
  return out;
}

double psnr(const cv::Mat& a, const cv::Mat& b, int border) {
  if (a.size() != b.size() || a.type() != b.type())
    throw std::invalid_argument("psnr needs images of equal size and type");
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
