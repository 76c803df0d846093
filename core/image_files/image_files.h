// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Image files (PNG, TIFF, PGM, JPEG) read and written through OpenCV's imgcodecs, which is loaded the first time a
// file is read or written instead of when a program starts. imgcodecs brings GDAL, GDCM (DICOM), libheif and about
// 115 other shared libraries: loading them cost every benchscope-cli start 0.2 s of CPU (0.5 s under ASan) although
// most commands never touch an image, and a robot's scripts and the desk's remote jobs start the CLI many times.
// Same meaning as cv::imread and cv::imwrite (the flags are imgcodecs' IMREAD_* values); nothing here links
// imgcodecs, so a direct cv::imread in a library or the CLI fails to link and is caught.
#include <string>

#include <opencv2/core/mat.hpp>
#include <opencv2/imgcodecs.hpp>  // the IMREAD_* flags only: no function of it is called directly

namespace bs::image_files {

// As cv::imread: an empty Mat when the file cannot be decoded; cv::Exception from a decoder as imread throws it.
// Throws std::runtime_error naming the library when imgcodecs itself cannot be loaded.
cv::Mat read(const std::string& path, int flags);
// As cv::imwrite: false when the image cannot be written. Throws std::runtime_error as `read` when imgcodecs cannot
// be loaded.
bool write(const std::string& path, const cv::Mat& image);

}  // namespace bs::image_files
