// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/pipeline/threads.h"

#include <stdexcept>

#include <omp.h>
#include <opencv2/core/utility.hpp>

namespace bs::vision {

int vision_threads() { return omp_get_max_threads(); }

void set_vision_threads(int n) {
  if (n < 1) throw std::invalid_argument("thread count must be >= 1");
  omp_set_num_threads(n);
  cv::setNumThreads(n);
}

int opencv_threads() { return cv::getNumThreads(); }

}  // namespace bs::vision
