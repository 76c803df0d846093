// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/count_tickers.h"

#include <cmath>

namespace bs::ui {

QString compact_count(double value) {
  static const char* const suffixes[] = {"", "k", "M", "G", "T"};
  // Round to three significant digits first, so 999,999.6 becomes "1M" and not "1e+03k".
  const double rounded = value == 0 ? 0.0 : QString::number(value, 'g', 3).toDouble();
  int step = 0;
  double scaled = rounded;
  while (std::abs(scaled) >= 1000 && step < 4) {
    scaled /= 1000;
    ++step;
  }
  return QString::number(scaled, 'g', 3) + QString::fromLatin1(suffixes[step]);
}

QString CountTicker::getTickLabel(double tick, const QLocale&, QChar, int) { return compact_count(tick); }

QString CountTickerLog::getTickLabel(double tick, const QLocale&, QChar, int) { return compact_count(tick); }

}  // namespace bs::ui
