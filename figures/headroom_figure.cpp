// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom_figure.h"

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

#include <QFontMetricsF>
#include <QPointer>

#include <QJsonObject>

#include "device_palette.h"
#include "overlay_geometry.h"
#include "paper_figures.h"
#include "plot_labels.h"

namespace bs::ui {
namespace {

constexpr double kFloor = 0.5;  // an empty bin is drawn on the axis floor: a log axis has no 0

Qt::PenStyle thread_style(int thread) {
  static const Qt::PenStyle styles[] = {Qt::SolidLine, Qt::DashLine, Qt::DotLine, Qt::DashDotLine};
  return styles[static_cast<std::size_t>(thread) % 4];
}

// Keeps the deadline's label whole inside the axes at every size the figure is drawn at (the tab, an export at a
// column's width), after each layout pass: beside its line, left (as it always was) or right, at the height where it
// covers the least curve and never the legend; over the line where neither side has room; in a smaller font (down to
// 5 pt) where it is wider than the axes. Right-aligned to the line always, a deadline near the axis' start cut the
// label's lines at the axes' left edge (issue #50.5).
class DeadlineLabelPlacer : public QObject {
 public:
  static constexpr const char* kName = "bs-deadline-label";

  explicit DeadlineLabelPlacer(QCustomPlot* plot) : QObject(plot), plot_(plot) {
    setObjectName(kName);
    connect(plot, &QCustomPlot::afterLayout, this, &DeadlineLabelPlacer::place);
  }
  // The plot's placer, made on first use (only this class names a child of the plot so: a static_cast is safe).
  static DeadlineLabelPlacer* find(QCustomPlot& plot) {
    return static_cast<DeadlineLabelPlacer*>(plot.findChild<QObject*>(kName, Qt::FindDirectChildrenOnly));
  }
  static DeadlineLabelPlacer* of(QCustomPlot& plot) {
    DeadlineLabelPlacer* placer = find(plot);
    return placer ? placer : new DeadlineLabelPlacer(&plot);
  }
  void set(QCPItemText* label, double x) {
    label_ = label;
    x_ = x;
    shrunk_ = false;
  }

 private:
  // Every line of the text with its padding, as QCPItemText draws it (a single-line size runs the lines together).
  QSizeF label_size() const {
    const QMarginsF pad = label_->padding();
    return QFontMetricsF(label_->font()).boundingRect(QRectF(), Qt::AlignRight, label_->text()).size() +
           QSizeF(pad.left() + pad.right(), pad.top() + pad.bottom());
  }

  void place() {
    if (!label_) return;
    const QRectF axes = plot_->axisRect()->rect();
    // Shrunk from the font it was given each time (its own, or an export's): a narrow first layout must not leave
    // it small for good. A font still the one shrunk here was given as `given_`.
    QFont f = shrunk_ && label_->font() == shrunk_to_ ? given_ : label_->font();
    given_ = f;
    label_->setFont(f);
    QSizeF size = label_size();
    for (; size.width() > axes.width() && f.pointSizeF() > 5.25; size = label_size()) {
      f.setPointSizeF(f.pointSizeF() - 0.5);
      label_->setFont(f);
    }
    shrunk_ = f != given_;
    shrunk_to_ = f;
    const double line = plot_->xAxis->coordToPixel(x_);
    std::vector<double> lefts;
    if (line - size.width() >= axes.left()) lefts.push_back(line - size.width());
    if (line + size.width() <= axes.right()) lefts.push_back(line);
    if (lefts.empty())  // wider than either side: over the line, inside the axes
      lefts.push_back(
          std::clamp(line - size.width() / 2, axes.left(), std::max(axes.left(), axes.right() - size.width())));
    std::vector<QPointer<QCPGraph>> graphs;
    for (int i = 0; i < plot_->graphCount(); ++i) graphs.emplace_back(plot_->graph(i));
    const std::vector<QPolygonF> curves = graphs_in_pixels(graphs);
    const bool legend_inside = plot_->legend->visible() && plot_->legend->layout() == plot_->axisRect()->insetLayout();
    const auto cost = [&](const QRectF& spot) {
      return covered_length(spot, curves) +
             (legend_inside && spot.intersects(QRectF(plot_->legend->outerRect())) ? 1e6 : 0.0);
    };
    // From the top (where it always was) down to the floor in five steps; the first of equal costs wins.
    const double margin = 0.02 * axes.height();
    const double room = std::max(0.0, axes.height() - 2 * margin - size.height());
    QRectF best;
    double best_cost = 0;
    for (int step = 0; step <= 4; ++step)
      for (const double left : lefts) {
        const QRectF spot(QPointF(left, axes.top() + margin + room * step / 4), size);
        if (const double c = cost(spot); best.isNull() || c < best_cost) {
          best = spot;
          best_cost = c;
        }
      }
    label_->setPositionAlignment(Qt::AlignTop | Qt::AlignLeft);
    label_->setTextAlignment(best.right() <= line + 0.5 ? Qt::AlignRight : Qt::AlignLeft);  // towards the line
    label_->position->setPixelPosition(best.topLeft());
  }

  QCustomPlot* plot_;
  QPointer<QCPItemText> label_;
  double x_ = 0;
  QFont given_, shrunk_to_;  // the font the label was given, and the one it was shrunk to here
  bool shrunk_ = false;
};

QString us(std::int64_t ns) {
  const double v = static_cast<double>(ns) / 1000.0;
  return ns % 1000 == 0 || v >= 100 ? QString::number(v, 'f', 0) : QString::number(v, 'f', 1);
}

}  // namespace

std::vector<HeadroomCurve> headroom_curves(const headroom::HeadroomMeasurement& m, const QString& prefix) {
  std::vector<HeadroomCurve> out;
  int phase_index = 0;
  for (const headroom::Phase& p : m.phases) {
    for (const headroom::ThreadLatency& t : p.threads) {
      if (t.histogram.bins.empty()) continue;  // an imported summary has no distribution to draw (the table has it)
      QString label = prefix + QString::fromStdString(p.name);
      if (p.threads.size() > 1 || t.cpu)
        label += QStringLiteral(" · T%1").arg(t.index) + (t.cpu ? QStringLiteral(" (CPU %1)").arg(*t.cpu) : QString());
      out.push_back({label, &t.histogram, phase_index, t.index});
    }
    ++phase_index;
  }
  return out;
}

std::vector<BeyondDeadline> headroom_histogram_figure(QCustomPlot& plot, const std::vector<HeadroomCurve>& curves,
                                                      std::optional<std::int64_t> deadline_ns, const QString& title) {
  plot.clearGraphs();
  plot.clearItems();
  plot.yAxis->setScaleType(QCPAxis::stLogarithmic);
  plot.yAxis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
  plot.yAxis->setNumberFormat(QStringLiteral("eb"));
  plot.yAxis->setNumberPrecision(0);
  // cyclictest -N keeps 1 ns bins; everything else 1 us.
  const bool ns_bins = !curves.empty() && curves.front().histogram->bin_ns < 1000;
  plot.xAxis->setLabel(ns_bins ? QObject::tr("Latency (µs), %1 ns bins").arg(curves.front().histogram->bin_ns)
                               : QObject::tr("Latency (µs), 1 µs bins"));
  plot.yAxis->setLabel(QObject::tr("Cycles (log scale)"));
  plot.legend->setVisible(!curves.empty());
  plot.axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);

  std::vector<BeyondDeadline> beyond;
  double x_max = 10, y_max = 10;
  for (const HeadroomCurve& c : curves) {
    const headroom::LatencyHistogram& h = *c.histogram;
    std::size_t last = 0;
    for (std::size_t i = 0; i < h.bins.size(); ++i)
      if (h.bins[i] != 0) last = i + 1;
    QVector<double> keys, values;
    const double bin_us = static_cast<double>(h.bin_ns) / 1000.0;
    for (std::size_t i = 0; i <= last; ++i) {
      const double count = i < h.bins.size() ? static_cast<double>(h.bins[i]) : 0.0;
      keys.push_back(static_cast<double>(i) * bin_us);
      values.push_back(std::max(count, kFloor));
      y_max = std::max(y_max, count);
    }
    // The step ends at the upper edge of the last occupied bin, back on the floor.
    keys.push_back(static_cast<double>(last) * bin_us);
    values.push_back(kFloor);
    x_max = std::max(x_max, static_cast<double>(last) * bin_us);
    QCPGraph* g = plot.addGraph();
    g->setLineStyle(QCPGraph::lsStepLeft);
    QPen pen(device_color(c.color_index), 1.6);
    pen.setStyle(thread_style(c.thread));
    g->setPen(pen);
    g->setData(keys, values, true);
    QString name = c.label;
    if (h.max_ns) name += QObject::tr(", max %1 µs").arg(us(*h.max_ns));
    if (h.overflows > 0) name += QObject::tr(" (%1 beyond %2 µs)").arg(h.overflows).arg(us(h.limit_ns()));
    g->setName(name);
    if (deadline_ns) {
      const headroom::LatencyHistogram::Beyond b = h.count_above(*deadline_ns);
      beyond.push_back({c.label, b.count,
                        h.cycles > 0 ? 100.0 * static_cast<double>(b.count) / static_cast<double>(h.cycles) : 0.0,
                        b.exact});
    }
  }
  if (deadline_ns) {
    const double x = static_cast<double>(*deadline_ns) / 1000.0;
    x_max = std::max(x_max, x);
    auto* line = new QCPItemStraightLine(&plot);
    line->point1->setCoords(x, 1);
    line->point2->setCoords(x, 10);
    line->setPen(QPen(QColor(200, 30, 30), 1.4, Qt::DashLine));
    QString text = QObject::tr("deadline %1 µs").arg(us(*deadline_ns));
    for (const BeyondDeadline& b : beyond)
      text += QStringLiteral("\n") + b.label +
              QObject::tr(": %1%2 beyond (%3%4 %)")
                  .arg(b.exact ? QString() : QStringLiteral("≥ "))
                  .arg(b.count)
                  .arg(b.exact ? QString() : QStringLiteral("≥ "))
                  .arg(b.percent, 0, 'g', 3);
    auto* label = new QCPItemText(&plot);
    label->setPositionAlignment(Qt::AlignTop | Qt::AlignRight);
    label->position->setTypeX(QCPItemPosition::ptPlotCoords);
    label->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
    label->position->setCoords(x, 0.02);
    label->setTextAlignment(Qt::AlignRight);
    label->setText(text);
    label->setColor(QColor(200, 30, 30));
    label->setPadding(QMargins(4, 2, 6, 2));
    label->setBrush(QBrush(QColor(255, 255, 255, 210)));
    DeadlineLabelPlacer::of(plot)->set(label, x);
  } else if (DeadlineLabelPlacer* placer = DeadlineLabelPlacer::find(plot)) {
    placer->set(nullptr, 0);
  }
  plot.xAxis->setRange(0, x_max * 1.08);
  // Room above the tallest bin for the deadline's label, a line of its text about 0.3 of a decade at the tab's and
  // an export's sizes: the label sits over no bar where it always was, at the top.
  const double label_lines = deadline_ns ? static_cast<double>(beyond.size() + 1) : 0.0;
  plot.yAxis->setRange(kFloor, y_max * 3 * std::pow(10.0, 0.3 * label_lines));
  if (!title.isEmpty()) {
    if (plot.plotLayout()->rowCount() < 2 || !qobject_cast<QCPTextElement*>(plot.plotLayout()->element(0, 0))) {
      plot.plotLayout()->insertRow(0);
      plot.plotLayout()->addElement(0, 0, new QCPTextElement(&plot, title));
    } else {
      qobject_cast<QCPTextElement*>(plot.plotLayout()->element(0, 0))->setText(title);
    }
  }
  return beyond;
}

QJsonArray headroom_template_figure(QCustomPlot& plot, const FigureTemplate& t,
                                    const std::vector<headroom::HeadroomMeasurement>& measurements,
                                    QJsonArray& left_out) {
  const auto wanted = [&](const headroom::HeadroomMeasurement& m) {
    return t.platforms.empty() || std::find(t.platforms.begin(), t.platforms.end(), m.platform) != t.platforms.end();
  };
  const headroom::HeadroomMeasurement* chosen = nullptr;
  for (const headroom::HeadroomMeasurement& m : measurements)
    if (wanted(m) && (!chosen || m.provenance.date > chosen->provenance.date)) chosen = &m;
  if (!chosen)
    throw NoFigureData(t.id + ": no headroom measurement" +
                       (t.platforms.empty() ? "" : " of the template's platforms") +
                       " (benchscope-cli headroom, the Headroom tab, or an imported cyclictest / rttest file)");
  for (const headroom::HeadroomMeasurement& m : measurements)
    if (&m != chosen)
      left_out.append(
          QJsonObject{{"platform", QString::fromStdString(m.platform)},
                      {"what", QString::fromStdString(m.tool + " " + m.provenance.date)},
                      {"reason", wanted(m) ? QStringLiteral("an older measurement: the figure shows the newest one")
                                           : QStringLiteral("not among the template's platforms")}});
  std::optional<std::int64_t> deadline;
  for (const headroom::Phase& p : chosen->phases)
    if (!p.threads.empty() && p.threads.front().deadline_ns > 0) {
      deadline = p.threads.front().deadline_ns;
      break;
    }
  headroom_histogram_figure(plot, headroom_curves(*chosen), deadline, QString());
  if (!t.x_label.empty()) plot.xAxis->setLabel(QString::fromStdString(t.x_label));
  if (!t.y_label.empty()) plot.yAxis->setLabel(QString::fromStdString(t.y_label));
  QJsonArray sources;
  sources.append(QJsonObject{
      {"platform", QString::fromStdString(chosen->platform)},
      {"what", QString::fromStdString(std::string(headroom::to_string(chosen->kind)) + ", " + chosen->tool + ", " +
                                      (chosen->realtime() ? "real-time" : "NON-REAL-TIME"))},
      {"file", QString::fromStdString(chosen->provenance.source_file.empty() ? chosen->command
                                                                             : chosen->provenance.source_file)},
      {"origin", QString::fromStdString(std::string(to_string(chosen->provenance.origin)))},
      {"date", QString::fromStdString(chosen->provenance.date)}});
  return sources;
}

}  // namespace bs::ui
