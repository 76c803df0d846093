// SPDX-License-Identifier: GPL-3.0-or-later
#include "report_chart.h"

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/platform/platform_table.h"
#include "analysis/stats/units.h"
#include "chart_marks.h"
#include "device_palette.h"
#include "paper_figures.h"

namespace bs::ui {
namespace {

// The footnote marker ("[1]") the platforms table gives a cell, so that the chart and the table cite the same note.
std::string marker_of(const std::string& cell) {
  const auto open = cell.rfind(" [");
  return open == std::string::npos || cell.back() != ']' ? std::string() : cell.substr(open + 1);
}

// Platform names wrap at spaces into lines of about 11 characters under their bar, so neighbours never touch.
QString wrapped(const std::string& name) {
  QStringList lines;
  for (const QString& word : QString::fromStdString(name).split(' ', Qt::SkipEmptyParts)) {
    if (!lines.isEmpty() && lines.back().size() + 1 + word.size() <= 11)
      lines.back() += ' ' + word;
    else
      lines << word;
  }
  return lines.join('\n');
}

}  // namespace

std::string comparison_chart_caption() {
  return "Best peak of each platform (GFLOPS, log scale). Hatched with \xE2\x9A\xA0: a flagged value, drawn as "
         "measured (Table 1's footnote says why); pale: fails a constraint or has no power log.";
}

std::string comparison_chart(QCustomPlot& plot, const std::vector<PlatformRow>& rows,
                             const std::vector<PlatformVerdict>& verdicts, const std::map<std::string, int>& colors,
                             const FigureOptions& o) {
  const ExportTable table = platform_table(rows, verdicts);
  const QFont small = figure_font(o, 0.9);
  QSharedPointer<QCPAxisTickerText> ticker(new QCPAxisTickerText);
  std::string sources;
  double lo = 1e300, hi = 0;
  int k = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const PeakRow* peak = rows[i].best_peak();
    if (!peak) continue;
    ++k;
    const double gflops = peak->peak.flops / 1e9;
    lo = std::min(lo, gflops);
    hi = std::max(hi, gflops);
    const auto c = colors.find(rows[i].platform);
    QColor color = device_color(c == colors.end() ? static_cast<int>(i) : c->second);
    const bool fails = i < verdicts.size() && (!verdicts[i].meets_all || !verdicts[i].note.empty());
    if (fails) color = QColor::fromHsvF(color.hsvHueF(), color.hsvSaturationF() * 0.35, 0.95);
    auto* bars = new QCPBars(plot.xAxis, plot.yAxis);
    bars->setWidth(0.6);
    bars->setData({static_cast<double>(k)}, {gflops});
    bars->setPen(QPen(color.darker(140), o.line_width_pt * 0.6));
    const std::string cell = table.rows[i][peak == (rows[i].gpu ? &*rows[i].gpu : nullptr) ? 1 : 2];
    const std::string marker = peak->flags.empty() ? std::string() : marker_of(cell);
    if (!peak->flags.empty())
      mark_flagged_bars(bars, color);
    else
      bars->setBrush(color);
    bars->removeFromLegend();
    const bool chosen = i < verdicts.size() && verdicts[i].recommended;
    ticker->addTick(k, wrapped(rows[i].platform) + (chosen ? QStringLiteral("\n(recommended)") : QString()));
    // The value over the bar; a flagged one says so with the footnote number.
    // In the axis' unit, three significant digits: short enough for neighbouring bars.
    QString text = QString::number(gflops, 'f', gflops >= 100 ? 0 : gflops >= 1 ? 2 : 3);
    if (!peak->flags.empty()) text = flag_label(text, QString::fromStdString(marker));
    auto* label = new QCPItemText(&plot);
    label->setFont(small);
    label->setText(text);
    label->setPositionAlignment(Qt::AlignHCenter | Qt::AlignBottom);
    label->position->setCoords(k, gflops);
    label->setPadding(QMargins(0, 0, 0, 2));
    label->setColor(peak->flags.empty() ? Qt::black : kFlagColor);
    sources += (sources.empty() ? "" : "; ") + rows[i].platform + ": " + peak->device + ", " + peak->backend +
               (peak->dims > 0 ? ", D = " + std::to_string(peak->dims) : "") + " from " + peak->source_file;
  }
  if (k == 0) throw std::runtime_error("no platform has a FLOPS peak to chart");
  plot.xAxis->setTicker(ticker);
  plot.xAxis->setSubTicks(false);
  plot.xAxis->setTickLength(0, 0);
  plot.xAxis->setRange(0.4, k + 0.6);
  plot.xAxis->grid()->setVisible(false);
  plot.yAxis->setScaleType(QCPAxis::stLogarithmic);
  QSharedPointer<QCPAxisTickerLog> log_ticker(new QCPAxisTickerLog);
  log_ticker->setTickCount(4);  // a few decades labelled: the chart is short
  plot.yAxis->setTicker(log_ticker);
  plot.yAxis->setNumberFormat("gb");
  // Bars on a log axis start at the decade below the smallest; a decade above the largest leaves room for labels.
  plot.yAxis->setRange(std::pow(10, std::floor(std::log10(lo)) - 0.3), hi * 40);
  plot.yAxis->setLabel("Peak (GFLOPS)");
  for (QCPAxis* a : {plot.xAxis, plot.yAxis}) style_figure_axis(a, o);
  plot.yAxis->grid()->setPen(QPen(QColor(0xdd, 0xdd, 0xdd), 0.4, Qt::DotLine));
  plot.legend->setVisible(false);
  // Room on the right for the last bar's label and platform name, which are centred on it.
  plot.axisRect()->setAutoMargins(QCP::msLeft | QCP::msTop | QCP::msBottom);
  plot.axisRect()->setMargins(QMargins(0, 0, static_cast<int>(o.font_pt * 4), 0));
  return sources;
}

}  // namespace bs::ui
