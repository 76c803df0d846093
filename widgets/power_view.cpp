// SPDX-License-Identifier: GPL-3.0-or-later
#include "power_view.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDateTime>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QTimeZone>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>
#include <qcustomplot.h>

#include "analysis/decimate.h"
#include "analysis/measurement_text.h"
#include "analysis/power.h"
#include "device_palette.h"
#include "phase_markers.h"

namespace bs::ui {
namespace {

constexpr double kBatteryVolts = 14.8, kBatteryAh = 3.85;  // the paper's 4S LiPo

// Seconds since 1970 (UTC) of a log's first sample from its ISO 8601 start_time; NaN when it has none.
double start_epoch_s(const PowerTrace& t) {
  if (t.start_time.empty()) return std::nan("");
  QDateTime when = QDateTime::fromString(QString::fromStdString(t.start_time), Qt::ISODateWithMs);
  if (!when.isValid()) when = QDateTime::fromString(QString::fromStdString(t.start_time), Qt::ISODate);
  if (!when.isValid()) return std::nan("");
  if (when.timeSpec() == Qt::LocalTime) when.setTimeSpec(Qt::UTC);  // no zone stated: read as UTC, as the importers write it
  return static_cast<double>(when.toMSecsSinceEpoch()) / 1000.0;
}

QString platform_name(const PowerTrace& t) {
  return t.platform.empty() ? QString::fromStdString(t.label) : QString::fromStdString(t.platform);
}

}  // namespace

PowerView::PowerView(QWidget* parent)
    : QWidget(parent),
      quantity_box_(new QComboBox(this)),
      wall_clock_box_(new QCheckBox(tr("Wall-clock time (UTC)"), this)),
      plot_(new QCustomPlot(this)),
      table_(new QTableWidget(this)) {
  wall_clock_box_->setToolTip(tr("Plot against the time of day the logs were recorded (when every log states its "
                                 "absolute start) instead of seconds from each log's start"));
  connect(wall_clock_box_, &QCheckBox::toggled, this, [this](bool on) { set_wall_clock(on); });
  quantity_box_->addItem(tr("Current (A)"));
  quantity_box_->addItem(tr("Power (W)"));
  quantity_box_->setToolTip(tr("Supply current as in the paper's figure 4, or power"));
  connect(quantity_box_, &QComboBox::currentIndexChanged, this,
          [this](int i) { set_quantity(i == 0 ? Quantity::Current : Quantity::Power); });
  auto* hint = new QLabel(tr("Zoom (wheel) or pan (drag) the time axis to choose the range the table summarises; "
                              "double-click shows the whole log"), this);
  hint->setWordWrap(true);  // wraps in a narrow window instead of setting its minimum width
  plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
  plot_->axisRect()->setRangeZoom(Qt::Horizontal);
  plot_->axisRect()->setRangeDrag(Qt::Horizontal);
  plot_->xAxis->setLabel(tr("Time (s)"));
  plot_->yAxis->setLabel(tr("Current (A)"));
  plot_->legend->setVisible(true);
  plot_->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
  connect(plot_->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this] {
    redraw_visible();
    update_table();
  });
  connect(plot_, &QCustomPlot::mouseDoubleClick, this, [this] { rescale(); });
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
  auto* top = new QHBoxLayout;
  top->addWidget(new QLabel(tr("Plot:"), this));
  top->addWidget(quantity_box_);
  top->addWidget(wall_clock_box_);
  top->addWidget(hint, 1);
  layout->addLayout(top);
  layout->addWidget(plot_, 3);
  layout->addWidget(table_, 1);
}

void PowerView::set_data(std::vector<StoredPowerTrace> traces, std::vector<PeakRow> peaks,
                         std::vector<std::pair<std::string, int>> colors) {
  traces_ = std::move(traces);
  peaks_ = std::move(peaks);
  power_.clear();
  current_.clear();
  flags_.clear();
  start_epoch_.clear();
  colors_.clear();
  plot_->clearGraphs();
  for (const StoredPowerTrace& s : traces_) {
    flags_.push_back(check_power_trace_bundled(s.trace));
    power_.push_back(power_series(s.trace));
    current_.push_back(current_series(s.trace));
    QCPGraph* g = plot_->addGraph();
    int color = static_cast<int>(plot_->graphCount()) + 7;
    for (const auto& [platform, index] : colors)
      if (platform == s.trace.platform) color = index;
    g->setPen(QPen(device_color(color), 1));
    colors_.push_back(color);
    start_epoch_.push_back(start_epoch_s(s.trace));
  }
  const bool all_absolute = !traces_.empty() && std::none_of(start_epoch_.begin(), start_epoch_.end(),
                                                             [](double e) { return std::isnan(e); });
  wall_clock_box_->setEnabled(all_absolute);
  if (!all_absolute && wall_clock_on_) set_wall_clock(false);
  place_phase_markers();
  set_quantity(quantity_);
}

void PowerView::place_phase_markers() {
  plot_->clearItems();  // the previous traces' phase markers
  for (std::size_t i = 0; i < traces_.size(); ++i) {
    std::vector<TracePhase> phases = traces_[i].trace.phases;
    for (TracePhase& p : phases) p.start_s += offset(i), p.end_s += offset(i);
    add_phase_markers(plot_, phases, device_color(colors_[i]));  // warm-up, sweep points, pipeline windows
  }
}

bool PowerView::set_wall_clock(bool on) {
  if (on && !wall_clock_box_->isEnabled()) on = false;
  wall_clock_on_ = on;
  {
    const QSignalBlocker block(wall_clock_box_);
    wall_clock_box_->setChecked(on);
  }
  if (on) {
    auto ticker = QSharedPointer<QCPAxisTickerDateTime>(new QCPAxisTickerDateTime);
    ticker->setDateTimeFormat(QStringLiteral("HH:mm:ss\nyyyy-MM-dd"));
    ticker->setTimeZone(QTimeZone::utc());
    plot_->xAxis->setTicker(ticker);
    plot_->xAxis->setLabel(tr("Time of day (UTC)"));
  } else {
    plot_->xAxis->setTicker(QSharedPointer<QCPAxisTicker>(new QCPAxisTicker));
    plot_->xAxis->setLabel(tr("Time (s)"));
  }
  place_phase_markers();
  rescale();
  return on;
}

const std::vector<double>& PowerView::shown(std::size_t trace) const {
  return quantity_ == Quantity::Current ? current_[trace] : power_[trace];
}

void PowerView::set_quantity(Quantity q) {
  quantity_ = q;
  const bool current = q == Quantity::Current;
  const QSignalBlocker block(quantity_box_);
  quantity_box_->setCurrentIndex(current ? 0 : 1);
  plot_->yAxis->setLabel(current ? tr("Current (A)") : tr("Power (W)"));
  for (std::size_t i = 0; i < traces_.size() && i < static_cast<std::size_t>(plot_->graphCount()); ++i) {
    const QString missing = current ? tr(" (no current channel)") : tr(" (power unknown: no supply voltage)");
    plot_->graph(static_cast<int>(i))->setName(platform_name(traces_[i].trace) + (shown(i).empty() ? missing : QString()));
  }
  rescale();
}

void PowerView::rescale() {
  // Every log on one time axis from its own start (t = 0 s), so the platforms line up as in the paper's figure 4.
  double min_t = wall_clock_on_ ? std::numeric_limits<double>::infinity() : 0, max_t = 0, max_v = 0;
  for (std::size_t i = 0; i < traces_.size(); ++i) {
    if (!traces_[i].trace.time_s.empty()) {
      min_t = std::min(min_t, offset(i) + traces_[i].trace.time_s.front());
      max_t = std::max(max_t, offset(i) + traces_[i].trace.time_s.back());
    }
    for (double v : shown(i))
      if (!std::isnan(v)) max_v = std::max(max_v, v);
  }
  if (!std::isfinite(min_t)) min_t = 0;
  plot_->yAxis->setRange(0, max_v > 0 ? max_v * 1.25 : 1);  // headroom: the legend sits above the traces
  const QCPRange before = plot_->xAxis->range();
  plot_->xAxis->setRange(min_t, max_t > min_t ? max_t : min_t + 1);
  if (before == plot_->xAxis->range()) {  // no rangeChanged signal: redraw here
    redraw_visible();
    update_table();
  }
}

void PowerView::redraw_visible() {
  // Min/max per pixel column of the visible range: a 10-million-sample trace stays a few thousand points.
  const QCPRange range = plot_->xAxis->range();
  const auto columns = static_cast<std::size_t>(std::max(200, plot_->axisRect()->width()));
  for (std::size_t i = 0; i < traces_.size() && i < static_cast<std::size_t>(plot_->graphCount()); ++i) {
    const std::vector<double>& values = shown(i);
    QVector<double> keys, vals;
    if (!values.empty()) {
      const double off = offset(i);
      const DecimatedSeries d = decimate_min_max(traces_[i].trace.time_s, values, range.lower - off, range.upper - off, columns);
      keys = QVector<double>(d.t.begin(), d.t.end());
      for (double& k : keys) k += off;
      vals = QVector<double>(d.v.begin(), d.v.end());
    }
    plot_->graph(static_cast<int>(i))->setData(keys, vals, true);
  }
  plot_->replot();
}

void PowerView::update_table() {
  const QCPRange range = plot_->xAxis->range();
  table_->setRowCount(static_cast<int>(traces_.size()));
  for (std::size_t i = 0; i < traces_.size(); ++i) {
    const PowerTrace& t = traces_[i].trace;
    const TraceStats s = trace_stats(t, std::nullopt, range.lower - offset(i), range.upper - offset(i));
    // Every cell says how the log was measured; a flagged log's row is tinted and its tooltips start with why.
    const QString measured = tr("Power measured by: %1").arg(QString::fromStdString(measurement_text(t.provenance)));
    const std::vector<PlausibilityFlag>& flags = flags_[i];
    const QString tip = flags.empty() ? measured : QString::fromStdString(flags_text(flags)) + "\n\n" + measured;
    auto cell = [&](int col, const QString& text) {
      auto* item = new QTableWidgetItem(col == 0 && !flags.empty() ? QStringLiteral("⚠ ") + text : text);
      if (col > 0) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      item->setToolTip(tip);
      if (!flags.empty()) item->setBackground(QColor(0xff, 0xe0, 0xb2));
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
    if (best && !best->flags.empty() && table_->item(static_cast<int>(i), 6)) {  // the peak behind GFLOPS/W is flagged
      QTableWidgetItem* item = table_->item(static_cast<int>(i), 6);
      item->setText(QStringLiteral("⚠ ") + item->text());
      item->setBackground(QColor(0xff, 0xe0, 0xb2));
      item->setToolTip(QString::fromStdString(flags_text(best->flags)) + "\n\n" + item->toolTip());
    }
    cell(7, s.power_w ? QString::number(constant_power_runtime_h(kBatteryVolts, kBatteryAh, s.power_w->mean) * 60, 'f', 2)
                      : QStringLiteral("–"));
  }
}

}  // namespace bs::ui
