// SPDX-License-Identifier: GPL-3.0-or-later
#include "peaks/flops_plot.h"

#include <qcustomplot.h>
#include <QCheckBox>
#include <QHBoxLayout>
#include <QPushButton>
#include <QToolTip>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "analysis/peaks/flops.h"
#include "analysis/stats/units.h"
#include "chart_marks.h"
#include "common/count_tickers.h"
#include "device_palette.h"
#include "peaks/peak_overlay.h"
#include "plot_export.h"
#include "report/run_names.h"

namespace bs::ui {
namespace {

QString series_name(const FlopsRun& r) {
  // A Google Benchmark sweep has no D: its variant (family and counter) names it.
  if (r.dims <= 0)
    return QStringLiteral("%1 · %2 (%3)")
        .arg(QString::fromStdString(r.device), QString::fromStdString(r.backend), QString::fromStdString(r.variant));
  QString name = QStringLiteral("%1 · %2 · D=%3")
                     .arg(QString::fromStdString(r.device), QString::fromStdString(r.backend))
                     .arg(r.dims);
  if (r.variant != "paper") name += QStringLiteral(" (%1)").arg(QString::fromStdString(r.variant));
  return name;
}

// Both axes switch between a log and a linear scale alike; each scale brings its own ticker (x counts workers, so it
// has the count tickers; y has QCustomPlot's).
template <class LogTicker, class LinearTicker>
void set_scale(QCPAxis* axis, bool log) {
  axis->setScaleType(log ? QCPAxis::stLogarithmic : QCPAxis::stLinear);
  if (log)
    axis->setTicker(QSharedPointer<LogTicker>::create());
  else
    axis->setTicker(QSharedPointer<LinearTicker>::create());
}

}  // namespace

FlopsPlot::FlopsPlot(QWidget* parent) : QWidget(parent), plot_(new QCustomPlot(this)) {
  log_x_box_ = new QCheckBox(tr("Log workers"), this);
  log_y_box_ = new QCheckBox(tr("Log FLOPS"), this);
  log_x_box_->setToolTip(tr("Logarithmic worker axis (sweeps span several decades)"));
  log_y_box_->setToolTip(tr("Logarithmic FLOPS axis (compare CPUs and GPUs in one plot)"));
  auto* reset = new QPushButton(tr("Reset view"), this);
  reset->setToolTip(tr("Fit all visible series (R, or double-click the plot)"));
  reset->setShortcut(QKeySequence(Qt::Key_R));
  auto* bar = new QHBoxLayout;
  bar->addWidget(log_x_box_);
  bar->addWidget(log_y_box_);
  bar->addStretch(1);
  bar->addWidget(new QLabel(tr("Drag to pan, wheel to zoom, hover for values"), this));
  bar->addWidget(reset);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addLayout(bar);
  layout->addWidget(plot_, 1);

  plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
  plot_->xAxis->setLabel(tr("Workers"));
  plot_->legend->setVisible(true);
  plot_->legend->setFont(QFont(font().family(), 8));
  plot_->legend->setRowSpacing(-1);
  // Compact: the legend shares the plot area with 13 sweeps of the paper, so every pixel it saves shows data.
  plot_->legend->setIconSize(22, 10);
  plot_->legend->setIconTextPadding(5);
  plot_->legend->setMargins(QMargins(5, 3, 5, 3));
  plot_->legend->setBrush(QColor(255, 255, 255, 225));
  plot_->legend->setBorderPen(QPen(QColor(160, 160, 160)));
  // The legend lives inside the axis rect (the plot keeps the full width); PeakOverlay moves it to the corner
  // that covers the fewest curve segments whenever the data or the axis scales change.
  overlay_ = new PeakOverlay(plot_);
  plot_->setMouseTracking(true);

  connect(log_x_box_, &QCheckBox::toggled, this, &FlopsPlot::set_log_x);
  connect(log_y_box_, &QCheckBox::toggled, this, &FlopsPlot::set_log_y);
  connect(reset, &QPushButton::clicked, this, &FlopsPlot::reset_view);
  connect(plot_, &QCustomPlot::mouseDoubleClick, this, [this] { reset_view(); });
  connect(plot_, &QCustomPlot::mouseMove, this, &FlopsPlot::on_mouse_move);
  // Sweeps span 256 .. 1,024,000 workers (the ramp-up is invisible on a linear axis) and CPUs sit three decades
  // below GPUs, so log-log is the default that shows every series; the paper's linear look is one click away.
  log_x_box_->setChecked(true);
  log_y_box_->setChecked(true);
  rebuild();
}

void FlopsPlot::set_runs(const std::vector<const StoredRun*>& runs, const std::map<std::int64_t, std::string>& labels) {
  runs_ = runs;
  labels_ = labels;
  rebuild();
}

bool FlopsPlot::log_x() const { return plot_->xAxis->scaleType() == QCPAxis::stLogarithmic; }
bool FlopsPlot::log_y() const { return plot_->yAxis->scaleType() == QCPAxis::stLogarithmic; }

void FlopsPlot::set_log_x(bool on) {
  log_x_box_->setChecked(on);
  set_scale<CountTickerLog, CountTicker>(plot_->xAxis, on);
  reset_view();
}

void FlopsPlot::set_log_y(bool on) {
  log_y_box_->setChecked(on);
  set_scale<QCPAxisTickerLog, QCPAxisTicker>(plot_->yAxis, on);
  reset_view();
}

std::vector<QCPGraph*> FlopsPlot::series_graphs() const {
  std::vector<QCPGraph*> graphs;
  for (const Series& s : series_) graphs.push_back(s.graph);
  return graphs;
}

QString FlopsPlot::value_axis_label() const { return plot_->yAxis->label(); }

void FlopsPlot::reset_view() {
  overlay_->request_legend_placement();
  plot_->rescaleAxes();
  if (!log_y()) plot_->yAxis->setRangeLower(0);
  plot_->yAxis->scaleRange(1.05, plot_->yAxis->range().center());
  if (!log_y()) plot_->yAxis->setRangeLower(0);
  plot_->replot();
}

void FlopsPlot::rebuild() {
  overlay_->clear();
  plot_->clearGraphs();
  plot_->clearItems();
  series_.clear();
  double max_flops = 0;
  for (const StoredRun* r : runs_)
    if (const auto p = find_peak(r->run)) max_flops = std::max(max_flops, p->flops);
  struct PeakMark {
    double flops, workers;
    QColor color;
    bool flagged;  // implausible (analysis/plausibility.h): the label says "⚠", the peak table says why
    QCPGraph* curve;
  };
  std::vector<PeakMark> peaks;
  const int exponent = si_exponent(max_flops);
  scale_ = std::pow(10.0, exponent);
  plot_->yAxis->setLabel(tr("Performance (%1FLOPS)").arg(QString::fromUtf8(si_prefix(exponent).data())));

  // Names that read apart, and a marker per repeat of one series.
  std::vector<RunIdentity> identities;
  for (const StoredRun* r : runs_) {
    const auto label = labels_.find(r->id);
    identities.push_back(run_identity(r->run, series_name(r->run).toStdString(),
                                      label == labels_.end() ? std::string() : label->second));
  }
  const std::vector<std::string> names = distinct_names(identities);
  std::map<std::string, int> repeats;
  std::size_t index = 0;
  for (const StoredRun* stored : runs_) {
    const FlopsRun& run = stored->run;
    const std::string& name = names[index++];
    const int repeat = repeats[run.platform + '\x1f' + series_name(run).toStdString()]++;
    const auto curve = flops_curve(run);
    QVector<double> keys, mean, lo, hi;
    bool repeated = false;
    for (const CurvePoint& p : curve) {
      keys << static_cast<double>(p.workers);
      mean << p.flops.mean / scale_;
      lo << std::max(p.flops.mean - p.flops.sd, 0.0) / scale_;  // FLOPS are never negative
      hi << (p.flops.mean + p.flops.sd) / scale_;
      repeated = repeated || p.flops.n > 1;
    }
    const QColor color = device_color(stored->color_index);
    if (repeated) {
      QCPGraph* upper = plot_->addGraph();
      QCPGraph* lower = plot_->addGraph();
      upper->setData(keys, hi, true);
      lower->setData(keys, lo, true);
      upper->setPen(Qt::NoPen);
      lower->setPen(Qt::NoPen);
      QColor band = color;
      band.setAlpha(50);
      lower->setBrush(band);
      lower->setChannelFillGraph(upper);
      upper->removeFromLegend();
      lower->removeFromLegend();
    }
    QCPGraph* g = plot_->addGraph();
    g->setData(keys, mean, true);
    QPen pen(color, 1.5, dims_pen_style(run.dims));
    g->setPen(pen);
    // Colour is the device, line style D, and a sparse marker along the curve the backend: the same device's CUDA
    // and OpenCL curves (one colour, one D) are told apart, in the legend too.
    g->setScatterStyle(QCPScatterStyle(
        static_cast<QCPScatterStyle::ScatterShape>(run_marker_shape(QString::fromStdString(run.backend), repeat)),
        color, Qt::white, 6));
    g->setScatterSkip(std::max(0, static_cast<int>(keys.size()) / 8 - 1));
    g->setName(QString::fromStdString(name));
    series_.push_back({g, stored});
    overlay_->add_curve(g);

    if (const auto peak = find_peak(run)) {
      QCPGraph* marker = plot_->addGraph();
      marker->setData({static_cast<double>(peak->workers)}, {peak->flops / scale_}, true);
      marker->setLineStyle(QCPGraph::lsNone);
      marker->setScatterStyle(QCPScatterStyle(
          static_cast<QCPScatterStyle::ScatterShape>(run_marker_shape(QString::fromStdString(run.backend), repeat)),
          color.darker(130), color, 9));
      marker->removeFromLegend();
      const std::vector<PeakRow> checked = peak_table(std::span<const FlopsRun>(&run, 1));
      const bool flagged = !checked.empty() && !checked.front().flags.empty();
      // A flagged peak is drawn where it was measured, as a hollow marker; its label carries the warning sign.
      if (flagged) mark_flagged_points(marker, color);
      // In an exported figure the legend names the peak too: labels there give way where peaks crowd.
      const QString value = QString::fromStdString(format_si(peak->flops, "FLOPS"));
      set_figure_name(g, QStringLiteral("%1 (peak %2)").arg(g->name(), flagged ? flag_label(value) : value));
      peaks.push_back({peak->flops, static_cast<double>(peak->workers), color, flagged, g});
    }
  }
  plot_->legend->setVisible(!series_.empty());
  // Labels in order of priority: flagged peaks first (their "⚠" is the warning, it must not give way to a plain
  // label or to sweeps added later), then by peak height: where two collide, the higher peak keeps its label.
  std::stable_sort(peaks.begin(), peaks.end(), [](const PeakMark& a, const PeakMark& b) {
    return a.flagged != b.flagged ? a.flagged : a.flops > b.flops;
  });
  for (const PeakMark& p : peaks)
    overlay_->add_peak_label(p.workers, p.flops / scale_,
                             p.flagged ? flag_label(QString::fromStdString(format_si(p.flops, "FLOPS")))
                                       : QString::fromStdString(format_si(p.flops, "FLOPS")),
                             p.color, p.curve);
  reset_view();
}

QString FlopsPlot::read_out_at(const QPointF& pixel) const {
  double best = 15.0;  // pixels: how close the cursor must be to a data point
  QString text;
  for (const Series& s : series_) {
    const auto& data = s.graph->data();
    if (data->isEmpty()) continue;
    const double key = plot_->xAxis->pixelToCoord(pixel.x());
    auto it = data->findBegin(key, true);
    for (int k = 0; k < 2 && it != data->constEnd(); ++k, ++it) {
      const QPointF p(plot_->xAxis->coordToPixel(it->key), plot_->yAxis->coordToPixel(it->value));
      const double d = std::hypot(p.x() - pixel.x(), p.y() - pixel.y());
      if (d >= best) continue;
      best = d;
      const auto index = static_cast<std::size_t>(it - data->constBegin());
      const auto curve = flops_curve(s.run->run);
      const Summary& f = curve[index].flops;
      const int e = si_exponent(f.mean);
      const double sc = std::pow(10.0, e);
      const QString unit = QString::fromUtf8(si_prefix(e).data()) + "FLOPS";
      text =
          QStringLiteral("%1\n%2 on %3, %4\nWorkers: %L5\n%6")
              .arg(QString::fromStdString(s.run->run.device), QString::fromStdString(s.run->run.backend),
                   QString::fromStdString(s.run->run.platform))
              .arg(s.run->run.dims > 0 ? QStringLiteral("D = %1").arg(s.run->run.dims)
                                       : QString::fromStdString(s.run->run.variant))
              .arg(static_cast<qlonglong>(curve[index].workers))
              .arg(f.n > 1 ? QString::fromStdString(format_mean_sd(f.mean / sc, f.sd / sc, f.n, unit.toStdString(), 3))
                           : QStringLiteral("%1 %2 (n = 1)").arg(f.mean / sc, 0, 'f', 3).arg(unit));
    }
  }
  return text;
}

void FlopsPlot::on_mouse_move(QMouseEvent* event) {
  const QString text = read_out_at(event->position());
  if (text.isEmpty())
    QToolTip::hideText();
  else
    QToolTip::showText(event->globalPosition().toPoint(), text, plot_);
}

}  // namespace bs::ui
