// SPDX-License-Identifier: GPL-3.0-or-later
#include "candidates_figure.h"

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "chart_marks.h"
#include "plot_labels.h"

namespace bs::ui {
namespace {

// Class colours: distinguishable in print (Okabe-Ito).
const QColor kClassColors[] = {QColor(0, 114, 178), QColor(213, 94, 0),   QColor(0, 158, 115), QColor(204, 121, 167),
                               QColor(230, 159, 0), QColor(86, 180, 233), QColor(0, 0, 0),     QColor(240, 228, 66)};

QCPScatterStyle origin_marker(DataOrigin o, const QColor& c) {
  switch (o) {
    case DataOrigin::Measured:
      return QCPScatterStyle(QCPScatterStyle::ssDisc, c, c, 9);
    case DataOrigin::Reconstructed:
      return QCPScatterStyle(QCPScatterStyle::ssSquare, QPen(c, 2), Qt::white, 9);
    case DataOrigin::Published:
      return QCPScatterStyle(QCPScatterStyle::ssDiamond, QPen(c, 1.5), QColor(c.red(), c.green(), c.blue(), 90), 11);
    case DataOrigin::Unknown:
      break;
  }
  return QCPScatterStyle(QCPScatterStyle::ssCross, QPen(c, 2), Qt::NoBrush, 9);
}

QString origin_name(DataOrigin o) { return QString::fromStdString(origin_label(o)); }

}  // namespace

QString draw_candidates(QCustomPlot& plot, std::span<const CandidateClass> classes) {
  // The points' names, placed after every layout pass around their points, apart from each other and from the
  // markers (figures/plot_labels.h): fixed offsets printed names over each other where points crowd. One placer per
  // plot, kept across redraws.
  auto* names = plot.findChild<AnchoredLabels*>(QStringLiteral("bs-candidate-names"));
  if (!names) {
    names = new AnchoredLabels(&plot);
    names->setObjectName(QStringLiteral("bs-candidate-names"));
  }
  names->clear();
  plot.clearGraphs();
  plot.clearItems();
  struct Name {
    double x, y;
    QString text;
    QColor color;
    bool flagged;
  };
  std::vector<Name> to_name;
  plot.legend->setVisible(true);
  plot.legend->setFont(QFont(plot.font().family(), 8));
  // The legend goes under the axes, never over the points (a box inside the axes hid the published ones in a
  // small plot): taken out of the axis rect's inset layout once, in rows of three entries.
  if (plot.legend->layout() == plot.axisRect()->insetLayout() && plot.axisRect()->insetLayout()->take(plot.legend)) {
    plot.plotLayout()->addElement(1, 0, plot.legend);
    plot.plotLayout()->setRowStretchFactor(1, 0.001);
    plot.legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    plot.legend->setWrap(2);
  }
  plot.xAxis->setLabel(QObject::tr("Power (W)"));
  plot.yAxis->setLabel(QObject::tr("Inferences per second"));
  plot.yAxis->setScaleType(QCPAxis::stLogarithmic);
  plot.yAxis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
  QStringList left_out, flagged;
  double xmax = 1, ymin = 1e9, ymax = 1e-9;
  std::size_t class_no = 0;
  for (const CandidateClass& k : classes) {
    const QColor color = kClassColors[class_no++ % std::size(kClassColors)];
    bool legend_for_class = false;
    for (const Candidate& c : k.rows) {
      if (!c.power_w || !c.throughput_per_s || *c.throughput_per_s <= 0) {
        left_out << QString::fromStdString(c.platform + " (" + k.network + ", " + origin_label(c.origin) + ")");
        continue;
      }
      QCPGraph* g = plot.addGraph();
      g->setLineStyle(QCPGraph::lsNone);
      g->setScatterStyle(origin_marker(c.origin, color));
      g->addData(*c.power_w, *c.throughput_per_s);
      // A flagged row is drawn where its numbers put it, hollow and labelled with the warning sign (chart_marks.h);
      // the note names it and says why.
      const bool is_flagged = !c.flags.empty();
      if (is_flagged) {
        mark_flagged_points(g, color);
        QStringList why;
        for (const PlausibilityFlag& f : c.flags) why << QString::fromStdString(f.reason);
        flagged << QString::fromStdString(c.platform + " (" + k.network + "): ") + why.join(QStringLiteral("; "));
      }
      // One legend entry per class (its colour), named, from an unflagged row where the class has one; the origins
      // get entries of their own below.
      const bool unflagged_left = std::any_of(&c + 1, k.rows.data() + k.rows.size(),
                                              [](const Candidate& x) { return x.flags.empty() && x.power_w; });
      if (!legend_for_class && (!is_flagged || !unflagged_left)) {
        g->setName(QString::fromStdString(k.title()));
        g->setScatterStyle(origin_marker(c.origin, color));
        legend_for_class = true;
      } else {
        g->removeFromLegend();
      }
      to_name.push_back(
          {*c.power_w, *c.throughput_per_s,
           is_flagged ? flag_label(QString::fromStdString(c.platform)) : QString::fromStdString(c.platform), color,
           is_flagged});
      xmax = std::max(xmax, *c.power_w);
      ymin = std::min(ymin, *c.throughput_per_s);
      ymax = std::max(ymax, *c.throughput_per_s);
    }
  }
  // Legend entries for the origins, in grey, drawn nowhere (no data).
  for (DataOrigin o : {DataOrigin::Measured, DataOrigin::Reconstructed, DataOrigin::Published}) {
    QCPGraph* g = plot.addGraph();
    g->setLineStyle(QCPGraph::lsNone);
    g->setScatterStyle(origin_marker(o, QColor(90, 90, 90)));
    g->setName(QObject::tr("origin: %1").arg(origin_name(o)));
  }
  // Flagged points are named first: their "⚠" must not give way to a plain name where two crowd.
  std::stable_sort(to_name.begin(), to_name.end(), [](const Name& a, const Name& b) { return a.flagged > b.flagged; });
  for (const Name& n : to_name) names->add(n.x, n.y, n.text, n.color)->setFont(QFont(plot.font().family(), 7));
  if (ymin > ymax) ymin = 0.1, ymax = 10;
  plot.xAxis->setRange(0, xmax * 1.35);
  // Whole decades: the log ticker then labels 1, 10, 100 ... (within less than a decade it falls back to linear
  // ticks, which crowd the top of a log axis: 10, 12.5, 15, 17.5).
  plot.yAxis->setRange(std::pow(10.0, std::floor(std::log10(ymin / 2))),
                       std::pow(10.0, std::ceil(std::log10(ymax * 3))));
  plot.replot();
  QStringList note;
  if (!flagged.isEmpty())
    note << QObject::tr("\u26A0 hollow: flagged as implausible, drawn at its value: %1")
                .arg(flagged.join(QStringLiteral("; ")));
  if (!left_out.isEmpty())
    note << QObject::tr("Not drawn (no power or rate): %1").arg(left_out.join(QStringLiteral("; ")));
  return note.join(QStringLiteral("\n"));
}

QImage render_candidates(std::span<const CandidateClass> classes, int width, int height, QString* note) {
  QCustomPlot plot;
  plot.resize(width, height);
  const QString n = draw_candidates(plot, classes);
  if (note) *note = n;
  return plot.toPixmap(width, height).toImage();
}

}  // namespace bs::ui
