// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/efficiency_view.h"

#include <qcustomplot.h>
#include <QHeaderView>
#include <QLabel>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <optional>

#include "chart_marks.h"
#include "plot_export.h"

namespace bs::ui {
namespace {

enum Column { Platform, Peak, Source, Supply, MaxCurrent, MeanCurrent, MeanPower, Paper, AtMean, Energy, ColumnCount };

QString mean_sd_n(const Summary& s, int decimals) {
  return QStringLiteral("%1 ± %2 (n = %3)").arg(s.mean, 0, 'f', decimals).arg(s.sd, 0, 'f', decimals).arg(s.n);
}

}  // namespace

EfficiencyView::EfficiencyView(QWidget* parent)
    : QWidget(parent), table_(new QTableWidget(this)), plot_(new QCustomPlot(this)) {
  auto* note = new QLabel(
      tr("Each platform's highest FLOPS peak (any device) with its power log. <b>Paper</b>: peak / (supply V "
         "× <i>maximum</i> current), a best-case numerator over a worst-case denominator taken at different times; "
         "a log of power only (tegrastats, jtop) has no current for it. <b>At mean power</b>: peak / mean power of "
         "the log. <b>Energy</b>: joules per GFLOP at the peak rate and the mean power."),
      this);
  note->setWordWrap(true);
  table_->setColumnCount(ColumnCount);
  table_->setHorizontalHeaderLabels({tr("Platform"), tr("Peak (GFLOPS)"), tr("Peak from (device, backend, D)"),
                                     tr("Supply (V)"), tr("Max current (A)"), tr("Mean current (A)"),
                                     tr("Mean power (W)"), tr("GFLOPS/W paper\npeak / (V × max I)"),
                                     tr("GFLOPS/W\npeak / mean power"), tr("Energy (J/GFLOP)\nmean power / peak")});
  table_->horizontalHeaderItem(Paper)->setToolTip(
      tr("The paper's definition: peak FLOPS / (supply voltage × the "
         "largest current in the log)"));
  table_->horizontalHeaderItem(AtMean)->setToolTip(tr("Peak FLOPS / mean power over the whole log"));
  table_->horizontalHeaderItem(Energy)->setToolTip(
      tr("Joules per 10^9 floating-point operations at the peak rate, "
         "drawing the mean power"));
  table_->verticalHeader()->hide();
  // Sized to the platforms' figures (fill_table): a left-out platform's reason spans the columns and must not widen
  // the first of them.
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);

  plot_->yAxis->setLabel(tr("Efficiency (GFLOPS/W)"));
  plot_->xAxis->setLabel(tr("Platform"));
  plot_->legend->setVisible(true);
  plot_->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignLeft);

  auto* split = new QSplitter(Qt::Vertical, this);
  split->addWidget(table_);
  split->addWidget(plot_);
  split->setStretchFactor(0, 1);
  split->setStretchFactor(1, 3);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addWidget(note);
  layout->addWidget(split, 1);
}

void EfficiencyView::set_data(const std::vector<FlopsRun>& runs, const std::vector<PowerTrace>& traces) {
  EfficiencyComparison table = compare_efficiency(runs, traces);
  rows_ = std::move(table.rows);
  left_out_ = std::move(table.left_out);
  fill_table();
  fill_plot();
}

void EfficiencyView::fill_table() {
  table_->clearSpans();
  table_->clearContents();  // a left-out platform's reason left in a cell would size its column
  table_->setRowCount(static_cast<int>(rows_.size() + left_out_.size()));
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    const PlatformEfficiency& e = rows_[r];
    const auto cell = [&](int col, const QString& text, const QString& tip = {}) {
      auto* item = new QTableWidgetItem(text);
      if (col != Platform && col != Source) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      if (!tip.isEmpty()) item->setToolTip(tip);
      table_->setItem(static_cast<int>(r), col, item);
    };
    cell(Platform, QString::fromStdString(e.peak.platform),
         tr("power log: %1\npower measured by: %2")
             .arg(QString::fromStdString(e.trace_label), QString::fromStdString(e.measurement)));
    cell(Peak, QString::number(e.peak.peak.flops / 1e9, 'f', 2),
         tr("at %1 workers; %2").arg(e.peak.peak.workers).arg(QString::fromStdString(e.peak.source_file)));
    cell(Source, QStringLiteral("%1, %2, D = %3")
                     .arg(QString::fromStdString(e.peak.device), QString::fromStdString(e.peak.backend))
                     .arg(e.peak.dims));
    // A log of power only has no supply voltage or current: a dash, and the paper's column says why in words.
    const QString none = QStringLiteral("—");
    cell(Supply, e.supply_v ? QString::number(*e.supply_v, 'f', 1) : none);
    cell(MaxCurrent, e.current_a ? QString::number(e.current_a->max, 'f', 3) : none);
    cell(MeanCurrent, e.current_a ? mean_sd_n(*e.current_a, 2) : none);
    cell(MeanPower, mean_sd_n(e.power_w, 2));
    // The figures come in the order paper (when the log allows it), at mean power, J/GFLOP.
    const std::vector<int> columns =
        e.paper_gflops_per_w ? std::vector<int>{Paper, AtMean, Energy} : std::vector<int>{AtMean, Energy};
    for (std::size_t i = 0; i < columns.size() && i < e.figures.size(); ++i) {
      const EfficiencyFigure& f = e.figures[i];
      cell(columns[i], QString::number(f.value, 'f', columns[i] == Energy ? 4 : 2),
           QString::fromStdString(f.label) + QStringLiteral(" (") + QString::fromStdString(f.unit) + ')');
    }
    if (!e.paper_gflops_per_w)
      cell(Paper, e.current_a ? tr("none: no supply voltage") : tr("none: no supply current"),
           tr("No paper figure: %1").arg(QString::fromStdString(e.paper_missing)));
    // A flagged peak or power log: the numbers made from it are marked, tinted and explained.
    if (!e.flags.empty()) {
      const QString why = QString::fromStdString(flags_text(e.flags));
      const bool peak_flagged = !e.peak.flags.empty();
      const bool power_flagged = e.flags.size() > e.peak.flags.size();  // the log's flags follow the peak's
      for (int col :
           {int(Peak), int(MaxCurrent), int(MeanCurrent), int(MeanPower), int(Paper), int(AtMean), int(Energy)}) {
        const bool ratio = col == Paper || col == AtMean || col == Energy;
        if (!ratio && !(col == Peak ? peak_flagged : power_flagged)) continue;
        QTableWidgetItem* item = table_->item(static_cast<int>(r), col);
        if (!item || item->text().startsWith(none) || item->text().startsWith(tr("none"))) continue;
        item->setText(QStringLiteral("⚠ ") + item->text());
        item->setBackground(QColor(0xff, 0xe0, 0xb2));
        item->setToolTip(why + "\n\n" + item->toolTip());
      }
    }
  }
  table_->resizeColumnsToContents();
  // The platforms without a figure, each with why across the row: a platform never leaves the tab unexplained.
  for (std::size_t i = 0; i < left_out_.size(); ++i) {
    const int r = static_cast<int>(rows_.size() + i);
    const QString platform = QString::fromStdString(left_out_[i].platform);
    const QString why = tr("No efficiency figure: %1").arg(QString::fromStdString(left_out_[i].reason));
    table_->setItem(r, Platform, new QTableWidgetItem(platform));
    auto* reason = new QTableWidgetItem(why);
    reason->setForeground(palette().color(QPalette::PlaceholderText));
    reason->setToolTip(why);
    table_->setItem(r, Peak, reason);
    for (int col = Peak + 1; col < ColumnCount; ++col) table_->setItem(r, col, nullptr);
    table_->setSpan(r, Peak, 1, ColumnCount - Peak);
  }
  table_->resizeColumnToContents(Platform);  // the left-out platforms' names too
}

void EfficiencyView::fill_plot() {
  plot_->clearPlottables();
  plot_->clearItems();
  clear_figure_notes(*plot_);
  const int n = static_cast<int>(rows_.size());
  QSharedPointer<QCPAxisTickerText> ticker(new QCPAxisTickerText);
  for (int i = 0; i < n; ++i)
    ticker->addTick(i + 1, QString::fromStdString(rows_[static_cast<std::size_t>(i)].peak.platform));
  plot_->xAxis->setTicker(ticker);
  plot_->xAxis->setSubTicks(false);
  plot_->xAxis->setTickLength(0, 4);
  // Two bars per platform side by side, one colour per variant. A figure made from a flagged peak or power log is
  // drawn at its value, hatched, and labelled "⚠": shown, marked, never replaced.
  const struct {
    QString name;
    QColor color;
    std::optional<double> (*value)(const PlatformEfficiency&);
    double offset;
  } variants[] = {
      {tr("Paper: peak / (V × max current)"), QColor(31, 119, 180),
       [](const PlatformEfficiency& e) { return e.paper_gflops_per_w; }, -0.19},
      {tr("Peak / mean power"), QColor(255, 127, 14),
       [](const PlatformEfficiency& e) { return std::optional<double>(e.mean_power_gflops_per_w); }, 0.19},
  };
  double top = 0;
  bool any_flagged = false;
  for (const auto& v : variants) {
    auto* plain = new QCPBars(plot_->xAxis, plot_->yAxis);
    auto* flagged = new QCPBars(plot_->xAxis, plot_->yAxis);
    for (QCPBars* bars : {plain, flagged}) {
      bars->setName(v.name);
      bars->setPen(QPen(v.color.darker(130)));
      bars->setBrush(v.color);
      bars->setWidth(0.35);
    }
    mark_flagged_bars(flagged, v.color);
    flagged->removeFromLegend();
    QVector<double> keys, values, flagged_keys, flagged_values;
    for (int i = 0; i < n; ++i) {
      const PlatformEfficiency& e = rows_[static_cast<std::size_t>(i)];
      const std::optional<double> figure = v.value(e);
      if (!figure) {  // no bar where the log allows no figure: its place says so
        auto* none = new QCPItemText(plot_);
        none->position->setCoords(i + 1 + v.offset, 0);
        none->setPositionAlignment(Qt::AlignHCenter | Qt::AlignBottom);
        none->setText(tr("n/a"));
        none->setColor(QColor(90, 90, 90));
        none->setPadding(QMargins(0, 0, 0, 2));
        continue;
      }
      const double value = *figure;
      (e.flags.empty() ? keys : flagged_keys) << i + 1 + v.offset;
      (e.flags.empty() ? values : flagged_values) << value;
      top = std::max(top, value);
      // The value over its bar, so the figures can be read off the chart (104.64, 41.26 on the paper's data).
      auto* label = new QCPItemText(plot_);
      label->position->setCoords(i + 1 + v.offset, value);
      label->setPositionAlignment(Qt::AlignHCenter | Qt::AlignBottom);
      label->setText(e.flags.empty() ? QString::number(value, 'f', 2) : flag_label(QString::number(value, 'f', 2)));
      label->setColor(e.flags.empty() ? Qt::black : kFlagColor);
      label->setPadding(QMargins(0, 0, 0, 2));
    }
    plain->setData(keys, values);
    flagged->setData(flagged_keys, flagged_values);
    any_flagged = any_flagged || !flagged_keys.isEmpty();
  }
  // One legend entry for the hatching, and the reasons in the figure's note (an export carries them).
  if (any_flagged) {
    auto* key = new QCPBars(plot_->xAxis, plot_->yAxis);
    key->setName(tr("⚠ from a flagged peak or power log (hatched)"));
    key->setPen(QPen(QColor(90, 90, 90)));
    mark_flagged_bars(key, QColor(120, 120, 120));
    for (const PlatformEfficiency& e : rows_)
      if (!e.flags.empty())
        add_figure_note(*plot_,
                        QStringLiteral("⚠ %1: %2")
                            .arg(QString::fromStdString(e.peak.platform), QString::fromStdString(flags_text(e.flags))));
  }
  // What the bars leave out, named in the figure's note (an export carries it; the table says it on screen).
  for (const PlatformEfficiency& e : rows_)
    if (!e.paper_gflops_per_w)
      add_figure_note(*plot_,
                      tr("n/a: %1 has no paper figure: %2")
                          .arg(QString::fromStdString(e.peak.platform), QString::fromStdString(e.paper_missing)));
  for (const EfficiencyLeftOut& l : left_out_)
    add_figure_note(*plot_,
                    tr("Not drawn: %1, %2").arg(QString::fromStdString(l.platform), QString::fromStdString(l.reason)));
  plot_->xAxis->setRange(0.4, n + 0.6);
  plot_->yAxis->setRange(0, top > 0 ? top * 1.3 : 1);  // room for the value labels and the legend
  plot_->replot();
}

}  // namespace bs::ui
