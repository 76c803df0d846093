// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How many threads the vision code uses: our OpenMP loops and OpenCV's own pool, set together so that comparisons
// between our kernels and OpenCV's run on the same number of cores.

namespace bs::vision {

int vision_threads();            // OpenMP's current maximum
void set_vision_threads(int n);  // n >= 1: OpenMP and cv::setNumThreads
int opencv_threads();            // cv::getNumThreads()

}  // namespace bs::vision
