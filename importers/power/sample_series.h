// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Named value series filled one log sample at a time: the clocks and temperatures a power log carries beside its
// rails (tegrastats, jtop CSV, nvidia-smi). A name met for the first time starts a series padded with NaN for the
// samples before it; a name missing from a sample gets NaN there, so every series has one value per sample.
// Bounded against hostile input: at most `max_series` names, and at most kMaxPaddedValues NaNs added for names that
// appear late (a sensor that first shows up at line ten million would otherwise cost ten million values at once).
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace bs::meter {

class SampleSeries {
 public:
  static constexpr std::size_t kMaxPaddedValues = std::size_t{4} << 20;

  struct Series {
    std::string name;
    std::vector<double> values;
  };
  enum class Set { Ok, TooManyNames };

  explicit SampleSeries(std::size_t max_series) : max_series_(max_series) {}

  // This sample's value of `name` (a second value for the same name in one sample replaces the first).
  Set set(std::string_view name, double v) {
    for (Series& s : series_)
      if (s.name == name) {
        if (s.values.size() > samples_)
          s.values.back() = v;
        else
          s.values.push_back(v);
        return Set::Ok;
      }
    if (series_.size() >= max_series_ || padded_ + samples_ > kMaxPaddedValues) return Set::TooManyNames;
    padded_ += samples_;
    Series& s = series_.emplace_back();
    s.name = std::string(name);
    s.values.assign(samples_, std::nan(""));
    s.values.push_back(v);
    return Set::Ok;
  }
  // Closes the sample: every name it did not mention gets NaN.
  void end_sample() {
    ++samples_;
    for (Series& s : series_)
      if (s.values.size() < samples_) s.values.push_back(std::nan(""));
  }
  std::vector<Series>& series() { return series_; }

 private:
  std::vector<Series> series_;
  std::size_t samples_ = 0, padded_ = 0, max_series_;
};

}  // namespace bs::meter
