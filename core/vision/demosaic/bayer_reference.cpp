// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/demosaic/bayer_reference.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include <opencv2/core/utility.hpp>

#include "vision/demosaic/bayer_pixel.h"

namespace bs::vision {
namespace {

template <class T>
void demosaic_rows_reference(const cv::Mat& raw, BayerPattern p, bool mhc, cv::Mat& out) {
  const int rows = raw.rows, cols = raw.cols;
  const int maxv = std::numeric_limits<T>::max();
  // Stripes of rows on OpenCV's pool: the reference is only as parallel as that, so tests over many images stay quick.
  cv::parallel_for_(
      cv::Range(0, rows),
      [&](const cv::Range& range) {
        for (int r = range.start; r < range.end; ++r) {
          // Rows r-2 .. r+2 with the top and bottom reflected, so only the left and right edges need the slow reader.
          const T* row[5];
          for (int k = 0; k < 5; ++k) row[k] = raw.ptr<T>(detail::reflect(r - 2 + k, rows));
          T* dst = out.ptr<T>(r);
          const int margin = std::min(2, cols);
          for (int c = 0; c < margin; ++c)
            detail::demosaic_edge_pixel<T>(row, c, cols, bayer_channel(p, r, c), bayer_channel(p, r, c + 1), mhc, maxv,
                                           dst);
          // The two site kinds of this row alternate: even and odd columns each get a branch-free inner loop.
          for (int parity = 0; parity < 2; ++parity) {
            const int here = bayer_channel(p, r, parity), row_colour = bayer_channel(p, r, parity + 1);
            for (int c = 2 + parity; c < cols - 2; c += 2)
              detail::demosaic_inner_pixel<T>(row, c, here, row_colour, mhc, maxv, dst);
          }
          for (int c = std::max(margin, cols - 2); c < cols; ++c)
            detail::demosaic_edge_pixel<T>(row, c, cols, bayer_channel(p, r, c), bayer_channel(p, r, c + 1), mhc, maxv,
                                           dst);
        }
      },
      std::max(1.0, rows / 16.0));
}

}  // namespace

namespace detail {
void check_demosaic_input(const cv::Mat& raw) {
  if (raw.type() != CV_8UC1 && raw.type() != CV_16UC1)
    throw std::invalid_argument("demosaic needs a single-channel 8- or 16-bit mosaic");
  if (raw.rows < 4 || raw.cols < 4) throw std::invalid_argument("demosaic needs at least 4x4 pixels");
}

void demosaic_reference_into(const cv::Mat& raw, BayerPattern p, bool mhc, cv::Mat& out) {
  if (raw.depth() == CV_8U)
    demosaic_rows_reference<std::uint8_t>(raw, p, mhc, out);
  else
    demosaic_rows_reference<std::uint16_t>(raw, p, mhc, out);
}
}  // namespace detail

cv::Mat demosaic_reference(const cv::Mat& raw, BayerPattern p, DemosaicMethod m) {
  detail::check_demosaic_input(raw);
  if (m != DemosaicMethod::Bilinear && m != DemosaicMethod::MalvarHeCutler)
    throw std::invalid_argument("demosaic_reference defines only BenchScope's bilinear and Malvar-He-Cutler");
  cv::Mat out(raw.size(), raw.depth() == CV_8U ? CV_8UC3 : CV_16UC3);
  detail::demosaic_reference_into(raw, p, m == DemosaicMethod::MalvarHeCutler, out);
  return out;
}

}  // namespace bs::vision
