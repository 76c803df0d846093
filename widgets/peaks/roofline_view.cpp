// SPDX-License-Identifier: GPL-3.0-or-later
#include "peaks/roofline_view.h"

#include <qcustomplot.h>
#include <QHelpEvent>
#include <QLabel>
#include <QToolTip>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "analysis/peaks/flops.h"
#include "analysis/stats/units.h"
#include "chart_marks.h"
#include "device_palette.h"
#include "plot_export.h"
#include "plot_labels.h"

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
  // Short enough for a figure at an IEEE column's height (the stages' integer op/s are said in their legend entry).
  plot_->yAxis->setLabel(tr("Performance (FLOP/s)"));
  flag_labels_ = new AnchoredLabels(plot_);
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
  plot_->installEventFilter(this);  // tooltips of the stage markers
}

QString RooflineView::stage_tooltip(const StagePlacement& s) const {
  const auto si = [](double v, const char* unit) { return QString::fromStdString(format_si(v, unit)); };
  QString t =
      tr("<b>%1 preprocessing</b> under %2<br>%3<br>")
          .arg(QString::fromStdString(s.platform).toHtmlEscaped(), QString::fromStdString(s.device).toHtmlEscaped(),
               QString::fromStdString(s.cost.label).toHtmlEscaped());
  t += tr("Frame %1×%2 → %3×%4%5<br>")
           .arg(s.geometry.source_width)
           .arg(s.geometry.source_height)
           .arg(s.geometry.output_width)
           .arg(s.geometry.output_height)
           .arg(s.geometry_assumed ? tr(" (view assumed the frame's size)") : QString());
  t += tr("%1 integer ops and %2 bytes per output pixel: intensity %3 op/byte<br>")
           .arg(s.cost.ops_per_output_pixel, 0, 'f', 1)
           .arg(s.cost.bytes_per_output_pixel, 0, 'f', 1)
           .arg(s.point.intensity, 0, 'f', 3);
  t += tr("Measured %1 ± %2 ms (n = %3) → achieved %4")
           .arg(s.time.mean_s * 1e3, 0, 'f', 2)
           .arg(s.time.sd_s * 1e3, 0, 'f', 2)
           .arg(s.time.n)
           .arg(si(s.point.flops, "op/s"));
  if (s.ops_per_s_low)
    t += tr(" (%1 … %2 at mean ± SD)")
             .arg(si(*s.ops_per_s_low, "op/s"), s.ops_per_s_high ? si(*s.ops_per_s_high, "op/s") : tr("∞"));
  t += tr("<br>Roof at this intensity %1: %2 of it%3<br>")
           .arg(si(s.point.attainable, "op/s"))
           .arg(QString::number(100 * s.point.fraction, 'f', 2) + " %")
           .arg(!s.memory_ceiling_known ? tr(" (no measured bandwidth: the roof is the compute peak alone)")
                : s.point.memory_bound  ? tr(", memory-bound")
                                        : tr(", compute-bound"));
  t += tr("Run: %1 (%2), %3 backend<br>")
           .arg(QString::fromStdString(s.source).toHtmlEscaped(), QString::fromUtf8(to_string(s.origin).data()),
                QString::fromStdString(s.backend).toHtmlEscaped());
  t +=
      tr("<i>Ops: integer adds, multiplies, shifts counted in the kernels; bytes: compulsory DRAM traffic, "
         "perfect cache reuse, no write-allocate.</i>");
  return t;
}

bool RooflineView::eventFilter(QObject* watched, QEvent* event) {
  if (watched == plot_ && event->type() == QEvent::ToolTip) {
    const QPoint pos = static_cast<QHelpEvent*>(event)->pos();
    for (const StagePlacement& s : stages_.placed) {
      const double px = plot_->xAxis->coordToPixel(s.point.intensity), py = plot_->yAxis->coordToPixel(s.point.flops);
      if (std::hypot(px - pos.x(), py - pos.y()) <= 9) {
        QToolTip::showText(static_cast<QHelpEvent*>(event)->globalPos(), stage_tooltip(s), plot_);
        return true;
      }
    }
  }
  return QWidget::eventFilter(watched, event);
}

void RooflineView::set_data(std::vector<FlopsRun> runs, std::vector<ResultSet> sets,
                            std::map<std::pair<std::string, std::string>, int> colors,
                            std::vector<PipelineRun> pipelines) {
  pipelines_ = std::move(pipelines);
  runs_ = std::move(runs);
  sets_ = std::move(sets);
  colors_ = std::move(colors);
  redraw();
}

void RooflineView::redraw() {
  flag_labels_->clear();  // before the items it placed are deleted
  plot_->clearGraphs();
  plot_->clearItems();
  ceilings_ = roofline_ceilings(runs_, sets_);
  points_.clear();
  double y_min = 1e30, y_max = 0;
  int without_bandwidth = 0;
  const std::vector<PeakRow> peak_rows = peak_table(runs_);
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
    // A roof at a flagged measured peak (no spec or computed peak to take instead) is drawn there, and says so.
    const bool flagged_roof = c.peak_source.rfind("measured", 0) == 0 &&
                              std::any_of(peak_rows.begin(), peak_rows.end(), [&](const PeakRow& r) {
                                return r.platform == c.platform && r.device == c.device && !r.flags.empty() &&
                                       std::abs(r.peak.flops - c.peak_flops) <= 1e-9 * c.peak_flops;
                              });
    if (flagged_roof) name = flag_label(name);
    roof->setName(name);
    y_min = std::min(y_min, ys.front());
    y_max = std::max(y_max, c.peak_flops);
    if (c.empirical_flops) {
      // The empirical ceiling: the same roof with the measured instruction-mix peak, dotted.
      QVector<double> ex, ey;
      const double ridge_e = c.bandwidth_bps ? *c.empirical_flops / *c.bandwidth_bps : kMinIntensity;
      ex = c.bandwidth_bps
               ? QVector<double>{kMinIntensity, std::clamp(ridge_e, kMinIntensity, kMaxIntensity), kMaxIntensity}
               : QVector<double>{kMinIntensity, kMaxIntensity};
      for (double x : ex)
        ey.push_back(c.bandwidth_bps ? std::min(*c.empirical_flops, x * *c.bandwidth_bps) : *c.empirical_flops);
      QCPGraph* emp = plot_->addGraph();
      emp->setData(ex, ey, true);
      emp->setPen(QPen(color, 1.5, Qt::DotLine));
      emp->setName(QString::fromStdString((c.flags.empty() ? std::string() : "\xE2\x9A\xA0 ") + c.device +
                                          ": empirical ceiling " + format_si(*c.empirical_flops, "FLOPS") + " (" +
                                          c.empirical_source + ")"));
      y_max = std::max(y_max, *c.empirical_flops);
    }
  }
  // Each run at its peak: the rotation kernel's intensity for its D and N.
  struct FlaggedLabel {
    double intensity, flops;
    QString text;
    QColor color;
  };
  std::vector<FlaggedLabel> flagged;
  for (const PeakRow& row : peak_rows) {
    const auto c = std::find_if(ceilings_.begin(), ceilings_.end(), [&](const RooflineCeiling& x) {
      return x.platform == row.platform && x.device == row.device;
    });
    if (c == ceilings_.end() || row.dims <= 0) continue;  // dims 0: another tool's sweep, intensity unknown
    const double intensity = rotation_intensity(row.dims, row.iterations);
    const double flop_count = rotation_flop_count(row.dims, row.iterations, row.peak.workers);
    RooflinePoint p = place_on_roofline(*c, row.device + " " + row.backend + " D=" + std::to_string(row.dims),
                                        flop_count, flop_count / intensity, flop_count / row.peak.flops);
    points_.push_back(p);
    const auto it = colors_.find({row.platform, row.device});
    QCPGraph* g = plot_->addGraph();
    g->setLineStyle(QCPGraph::lsNone);
    g->setScatterStyle(QCPScatterStyle(
        static_cast<QCPScatterStyle::ScatterShape>(backend_marker_shape(QString::fromStdString(row.backend))),
        device_color(it == colors_.end() ? 0 : it->second), 7));
    g->addData(p.intensity, p.flops);
    g->removeFromLegend();
    // A flagged peak is drawn where it was measured, hollow and labelled with the warning sign (chart_marks.h).
    if (!row.flags.empty()) {
      const QColor color = device_color(it == colors_.end() ? 0 : it->second);
      mark_flagged_points(g, color);
      flagged.push_back({p.intensity, p.flops, flag_label(QString::fromStdString(format_si(row.peak.flops, "FLOPS"))),
                         color.darker(130)});
    }
    y_min = std::min(y_min, p.flops);
  }
  // Highest first: where two would collide, the higher keeps its label (the marker stays hollow either way).
  std::stable_sort(flagged.begin(), flagged.end(),
                   [](const FlaggedLabel& a, const FlaggedLabel& b) { return a.flops > b.flops; });
  for (const FlaggedLabel& f : flagged) flag_labels_->add(f.intensity, f.flops, f.text, f.color);
  // The preprocessing stages: a star per pipeline run under its device's roof, a vertical bar for mean ± SD.
  stages_ = place_preprocessing(ceilings_, pipelines_);
  if (!stages_.placed.empty()) {
    QCPGraph* key = plot_->addGraph();  // legend entry only
    key->setLineStyle(QCPGraph::lsNone);
    key->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssStar, QPen(Qt::black, 1.5), Qt::NoBrush, 11));
    key->setName(tr("Preprocessing stage of a pipeline run, integer op/s (hover: numbers, source); bar: ± SD"));
    // On paper there is nothing to hover: the figure's own name for the key.
    set_figure_name(key, tr("Preprocessing stage of a pipeline run, integer op/s; bar: mean ± SD"));
  }
  QFont label_font(font().family(), 7);
  for (const StagePlacement& s : stages_.placed) {
    const auto it = colors_.find({s.platform, s.device});
    const QColor color = device_color(it == colors_.end() ? 0 : it->second);
    QCPGraph* g = plot_->addGraph();
    g->setLineStyle(QCPGraph::lsNone);
    g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssStar, QPen(color, 2), Qt::NoBrush, 13));
    g->addData(s.point.intensity, s.point.flops);
    g->removeFromLegend();
    if (s.ops_per_s_low) {
      auto* bar = new QCPItemLine(plot_);
      bar->setPen(QPen(color, 1.5));
      bar->start->setCoords(s.point.intensity, *s.ops_per_s_low);
      bar->end->setCoords(s.point.intensity, s.ops_per_s_high ? *s.ops_per_s_high : s.point.flops * 10);
      y_min = std::min(y_min, *s.ops_per_s_low);
    }
    // Stages of the same kernels share an intensity, their stars close together: the labels are placed around
    // them like the peaks' (after the flagged ones), apart from each other; one without room is left to the hover.
    const bool fused = s.cost.kernels.size() == 1 && s.cost.kernels.front() == StageKernel::Fused;
    flag_labels_
        ->add(s.point.intensity, s.point.flops,
              tr("%1 %2 %3 ms")
                  .arg(QString::fromStdString(s.platform), fused ? tr("fused preprocessing") : tr("preprocessing"))
                  .arg(s.time.mean_s * 1e3, 0, 'f', 2),
              color)
        ->setFont(label_font);
    y_min = std::min(y_min, s.point.flops);
  }
  if (ceilings_.empty()) {
    note_->setText(tr("No FLOPS runs yet: import runs or measure them with the Kernel Runner to see rooflines."));
  } else {
    note_->setText(
        tr("Markers: the rotation kernel's runs at their peak (6·D·N flops per worker over 16·D + 4 bytes). "
           "%1 Measure a memory ceiling with <tt>benchscope-cli run bandwidth --workspace …</tt>.")
            .arg(without_bandwidth
                     ? tr("%1 device(s) without a measured bandwidth: flat dashed roof only.").arg(without_bandwidth)
                     : QString()));
    if (!stages_.placed.empty())
      note_->setText(note_->text() +
                     tr("<br>Stars: each pipeline run's preprocessing at its modelled intensity (integer ops and "
                        "compulsory DRAM bytes per pixel counted in the kernels: bilinear demosaic 8 op + 4 B per "
                        "mosaic pixel, reprojection 27 op + 9 B per output pixel + 3 B per source pixel, fused "
                        "59 op + 11 B + 1 B) and its measured time; hover for the numbers and the run."));
    for (const std::string& why : stages_.skipped)
      note_->setText(note_->text() + tr("<br>Not placed: %1.").arg(QString::fromStdString(why).toHtmlEscaped()));
  }
  plot_->xAxis->setRange(kMinIntensity, kMaxIntensity);
  if (y_max > 0) plot_->yAxis->setRange(std::max(y_min / 3, y_max * 1e-6), y_max * 3);
  plot_->replot();
}

}  // namespace bs::ui
