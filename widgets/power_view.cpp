// SPDX-License-Identifier: GPL-3.0-or-later
#include "power_view.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <qcustomplot.h>

#include "analysis/power.h"
#include "device_palette.h"

namespace bs::ui {
namespace {

constexpr double kBatteryVolts = 14.8, kBatteryAh = 3.85;  // the paper's 4S LiPo

QString platform_name(const PowerTrace& t) {
  return t.platform.empty() ? QString::fromStdString(t.label) : QString::fromStdString(t.platform);
}

}  // namespace

PowerView::PowerView(QWidget* parent) : QWidget(parent), plot_(new QCustomPlot(this)), table_(new QTableWidget(this)) {
  auto* hint = new QLabel(tr("Zoom (wheel) or pan (drag) the time axis to choose the range the table summarises; "
                              "double-click shows the whole log"), this);
  plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
  plot_->axisRect()->setRangeZoom(Qt::Horizontal);
  plot_->axisRect()->setRangeDrag(Qt::Horizontal);
  plot_->xAxis->setLabel(tr("Time (s)"));
  plot_->yAxis->setLabel(tr("Power (W)"));
  plot_->legend->setVisible(true);
  plot_->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
  connect(plot_->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this] {
    redraw_visible();
    update_table();
  });
  connect(plot_, &QCustomPlot::mouseDoubleClick, this, [this] {
    plot_->rescaleAxes();
    plot_->replot();
  });
  table_->setColumnCount(8);
  table_->setHorizontalHeaderLabels({tr("Platform"), tr("Samples"), tr("Current (A)"), tr("Power (W)"),
                                     tr("Max power (W)"), tr("Energy (J)"), tr("GFLOPS/W (paper)"),
                                     tr("Battery (min)")});
  table_->horizontalHeaderItem(6)->setToolTip(tr("Peak FLOPS of the platform's best run / (supply V × max current)"));
  table_->horizontalHeaderItem(7)->setToolTip(tr("14.8 V × 3.85 Ah / mean power (the paper's constant-power model)"));
  table_->verticalHeader()->hide();
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addWidget(hint);
  layout->addWidget(plot_, 3);
  layout->addWidget(table_, 1);
}

void PowerView::set_data(std::vector<StoredPowerTrace> traces, std::vector<PeakRow> peaks,
                         std::vector<std::pair<std::string, int>> colors) {
  traces_ = std::move(traces);
  peaks_ = std::move(peaks);
  power_.clear();
  plot_->clearGraphs();
  for (const StoredPowerTrace& s : traces_) {
    power_.push_back(power_series(s.trace));
    QCPGraph* g = plot_->addGraph();
    int color = static_cast<int>(plot_->graphCount()) + 7;
    for (const auto& [platform, index] : colors)
      if (platform == s.trace.platform) color = index;
    g->setPen(QPen(device_color(color), 1));
    g->setName(platform_name(s.trace) + (power_.back().empty() ? tr(" (power unknown: no supply voltage)") : QString()));
  }
  plot_->rescaleAxes();
  double max_t = 0, max_p = 0;
  for (std::size_t i = 0; i < traces_.size(); ++i) {
    if (!traces_[i].trace.time_s.empty()) max_t = std::max(max_t, traces_[i].trace.time_s.back());
    for (double p : power_[i]) max_p = std::max(max_p, p);
  }
  plot_->xAxis->setRange(0, max_t > 0 ? max_t : 1);
  plot_->yAxis->setRange(0, max_p > 0 ? max_p * 1.1 : 1);
  redraw_visible();
  update_table();
}

void PowerView::redraw_visible() {
  // Min/max per pixel column of the visible range: a 10-million-sample trace stays a few thousand points.
  const QCPRange range = plot_->xAxis->range();
  const int columns = std::max(200, plot_->axisRect()->width());
  for (std::size_t i = 0; i < traces_.size() && i < static_cast<std::size_t>(plot_->graphCount()); ++i) {
    const auto& t = traces_[i].trace.time_s;
    const auto& p = power_[i];
    QVector<double> keys, values;
    if (!p.empty()) {
      const auto first = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), range.lower) - t.begin());
      const auto last = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), range.upper) - t.begin());
      const std::size_t lo = first > 0 ? first - 1 : 0, hi = std::min(last + 1, t.size());
      if (hi - lo <= static_cast<std::size_t>(2 * columns)) {
        for (std::size_t k = lo; k < hi; ++k) keys << t[k], values << p[k];
      } else {
        const double width = (range.upper - range.lower) / columns;
        std::size_t k = lo;
        for (int c = 0; c < columns && k < hi; ++c) {
          const double end = range.lower + (c + 1) * width;
          double mn = p[k], mx = p[k], t_mn = t[k], t_mx = t[k];
          for (; k < hi && t[k] < end; ++k) {
            if (p[k] < mn) mn = p[k], t_mn = t[k];
            if (p[k] > mx) mx = p[k], t_mx = t[k];
          }
          // Keep the order in time so the line goes through both extremes of the column.
          if (t_mn <= t_mx) keys << t_mn << t_mx, values << mn << mx;
          else keys << t_mx << t_mn, values << mx << mn;
        }
      }
    }
    plot_->graph(static_cast<int>(i))->setData(keys, values, true);
  }
  plot_->replot();
}

void PowerView::update_table() {
  const QCPRange range = plot_->xAxis->range();
  table_->setRowCount(static_cast<int>(traces_.size()));
  for (std::size_t i = 0; i < traces_.size(); ++i) {
    const PowerTrace& t = traces_[i].trace;
    const TraceStats s = trace_stats(t, std::nullopt, range.lower, range.upper);
    auto cell = [&](int col, const QString& text) {
      auto* item = new QTableWidgetItem(text);
      if (col > 0) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      table_->setItem(static_cast<int>(i), col, item);
    };
    const auto mean_sd = [](const std::optional<Summary>& v) {
      return v ? QStringLiteral("%1 ± %2").arg(v->mean, 0, 'f', 2).arg(v->sd, 0, 'f', 2) : QStringLiteral("–");
    };
    cell(0, platform_name(t) + QStringLiteral(" (%1)").arg(QString::fromUtf8(to_string(t.provenance.origin).data())));
    cell(1, QLocale().toString(static_cast<qulonglong>(s.n)));
    cell(2, mean_sd(s.current_a));
    cell(3, mean_sd(s.power_w));
    cell(4, s.power_w ? QString::number(s.power_w->max, 'f', 2) : QStringLiteral("–"));
    cell(5, s.power_w ? QString::number(s.energy_j, 'f', 1) : QStringLiteral("–"));
    QString gflops_w = QStringLiteral("–");
    const PeakRow* best = nullptr;
    for (const PeakRow& r : peaks_)
      if (r.platform == t.platform && (!best || r.peak.flops > best->peak.flops)) best = &r;
    if (best && s.current_a && t.supply_voltage_v)
      gflops_w = QString::number(paper_flops_per_watt(best->peak.flops, *t.supply_voltage_v, s.current_a->max) / 1e9, 'f', 2);
    cell(6, gflops_w);
    cell(7, s.power_w ? QString::number(constant_power_runtime_h(kBatteryVolts, kBatteryAh, s.power_w->mean) * 60, 'f', 2)
                      : QStringLiteral("–"));
  }
}

}  // namespace bs::ui
