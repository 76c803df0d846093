// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Axis tickers for counts (workers, tasks): tick labels "500", "10k", "1.5M" instead of "1000000" or "10⁶", so a
// sweep from 1 to 1,024,000 workers reads at a glance on linear and on logarithmic axes.
#include <qcustomplot.h>
#include <QString>

namespace bs::ui {

// "0", "750", "10k", "256k", "1.02M": at most three significant digits, SI suffix from a thousand on.
QString compact_count(double value);

class CountTicker : public QCPAxisTicker {
 protected:
  QString getTickLabel(double tick, const QLocale& locale, QChar format_char, int precision) override;
};

class CountTickerLog : public QCPAxisTickerLog {
 protected:
  QString getTickLabel(double tick, const QLocale& locale, QChar format_char, int precision) override;
};

}  // namespace bs::ui
