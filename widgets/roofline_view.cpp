// SPDX-License-Identifier: GPL-3.0-or-later
#include "roofline_view.h"

#include <QLabel>
#include <QVBoxLayout>
#include <cmath>
#include <qcustomplot.h>

#include "analysis/flops.h"
#include "analysis/units.h"
#include "device_palette.h"

namespace bs::ui {
namespace {

constexpr double kMinIntensity = 0.01, kMaxIntensity = 1e6;  // FLOP/byte, the x range

}  // namespace

RooflineView::RooflineView(QWidget* parent) : QWidget(parent), plot_(new QCustomPlot(this)), note_(new QLabel(this)) {
  note_->setWordWrap(true);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(plot_, 1);
  layout->addWidget(note_);
  for (QCPAxis* axis : {plot_->xAxis, plot_->yAxis}) {
    axis->setScaleType(QCPAxis::stLogarithmic);
    axis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
    axis->setNumberFormat("eb");
    axis->setNumberPrecision(0);
  }
  plot_->xAxis->setLabel(tr("Arithmetic intensity (FLOP/byte)"));
  plot_->yAxis->setLabel(tr("Performance (FLOP/s)"));
  plot_->legend->setVisible(true);
  plot_->legend->setFont(QFont(font().family(), 8));
  // The legend sits right of the axes: roofs span the whole width, so inside it would always cover one.
  auto* legend_rect = new QCPLayoutGrid;
  plot_->plotLayout()->addElement(0, 1, legend_rect);
  legend_rect->addElement(0, 0, plot_->legend);
  legend_rect->setMargins(QMargins(0, 0, 0, 0));
  plot_->plotLayout()->setColumnStretchFactor(1, 0.001);
  plot_->legend->setMaximumSize(420, 10000);
  plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
  plot_->setToolTip(tr("Drag to pan, wheel to zoom. Ceilings: min(peak, intensity × bandwidth)."));
}

void RooflineView::set_data(std::vector<FlopsRun> runs, std::vector<ResultSet> sets,
                            std::map<std::pair<std::string, std::string>, int> colors) {
  runs_ = std::move(runs);
  sets_ = std::move(sets);
  colors_ = std::move(colors);
  redraw();
}

void RooflineView::redraw() {
  plot_->clearGraphs();
  plot_->clearItems();
  ceilings_ = roofline_ceilings(runs_, sets_);
  points_.clear();
  double y_min = 1e30, y_max = 0;
  int without_bandwidth = 0;
  for (const RooflineCeiling& c : ceilings_) {
    const auto it = colors_.find({c.platform, c.device});
    const QColor color = device_color(it == colors_.end() ? 0 : it->second);
    // The roof: a sloped memory part up to the ridge, then flat; flat only (dashed) when the bandwidth is unknown.
    QVector<double> xs, ys;
    const auto ridge = c.ridge_intensity();
    if (ridge) {
      xs = {kMinIntensity, std::clamp(*ridge, kMinIntensity, kMaxIntensity), kMaxIntensity};
    } else {
      xs = {kMinIntensity, kMaxIntensity};
      ++without_bandwidth;
    }
    for (double x : xs) ys.push_back(c.attainable(x));
    QCPGraph* roof = plot_->addGraph();
    roof->setData(xs, ys, true);
    roof->setPen(QPen(color, 2, ridge ? Qt::SolidLine : Qt::DashLine));
    QString name = QString::fromStdString(c.platform + " — " + c.device) + ": " +
                   QString::fromStdString(format_si(c.peak_flops, "FLOPS"));
    if (c.bandwidth_bps) name += ", " + QString::fromStdString(format_si(*c.bandwidth_bps, "B/s"));
    roof->setName(name);
    y_min = std::min(y_min, ys.front());
    y_max = std::max(y_max, c.peak_flops);
  }
  // Each run at its peak: the rotation kernel's intensity for its D and N.
  for (const PeakRow& row : peak_table(runs_)) {
    const auto c = std::find_if(ceilings_.begin(), ceilings_.end(), [&](const RooflineCeiling& x) {
      return x.platform == row.platform && x.device == row.device;
    });
    if (c == ceilings_.end()) continue;
    const double intensity = rotation_intensity(row.dims, row.iterations);
    const double flop_count = rotation_flop_count(row.dims, row.iterations, row.peak.workers);
    RooflinePoint p = place_on_roofline(*c, row.device + " " + row.backend + " D=" + std::to_string(row.dims),
                                        flop_count, flop_count / intensity, flop_count / row.peak.flops);
    points_.push_back(p);
    const auto it = colors_.find({row.platform, row.device});
    QCPGraph* g = plot_->addGraph();
    g->setLineStyle(QCPGraph::lsNone);
    g->setScatterStyle(QCPScatterStyle(static_cast<QCPScatterStyle::ScatterShape>(backend_marker_shape(
                                           QString::fromStdString(row.backend))),
                                       device_color(it == colors_.end() ? 0 : it->second), 7));
    g->addData(p.intensity, p.flops);
    g->removeFromLegend();
    y_min = std::min(y_min, p.flops);
  }
  if (ceilings_.empty()) {
    note_->setText(tr("No FLOPS runs yet: import runs or measure them with the Kernel Runner to see rooflines."));
  } else {
    note_->setText(tr("Markers: the rotation kernel's runs at their peak (6·D·N flops per worker over 16·D + 4 bytes). "
                      "%1 Measure a memory ceiling with <tt>benchscope-cli run bandwidth --workspace …</tt>.")
                       .arg(without_bandwidth ? tr("%1 device(s) without a measured bandwidth: flat dashed roof only.")
                                                     .arg(without_bandwidth)
                                              : QString()));
  }
  plot_->xAxis->setRange(kMinIntensity, kMaxIntensity);
  if (y_max > 0) plot_->yAxis->setRange(std::max(y_min / 3, y_max * 1e-6), y_max * 3);
  plot_->replot();
}

}  // namespace bs::ui
