// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot_export.h"

#include <QFile>
#include <QSvgGenerator>
#include <qcustomplot.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "paper_figures.h"

namespace bs::ui {
namespace {

// What export_plot changes and puts back.
struct PlotLook {
  struct AxisLook {
    QCPAxis* axis;
    QFont label, ticks;
  };
  std::vector<AxisLook> axes;
  QFont legend;
  std::vector<std::pair<QCPGraph*, double>> pen_widths;

  explicit PlotLook(QCustomPlot& plot) : legend(plot.legend->font()) {
    for (QCPAxis* a : plot.axisRect()->axes()) axes.push_back({a, a->labelFont(), a->tickLabelFont()});
    for (int i = 0; i < plot.graphCount(); ++i) pen_widths.emplace_back(plot.graph(i), plot.graph(i)->pen().widthF());
  }
  void restore(QCustomPlot& plot) const {
    for (const AxisLook& a : axes) {
      a.axis->setLabelFont(a.label);
      a.axis->setTickLabelFont(a.ticks);
    }
    plot.legend->setFont(legend);
    for (const auto& [g, w] : pen_widths) {
      QPen p = g->pen();
      p.setWidthF(w);
      g->setPen(p);
    }
  }
};

void apply_figure_look(QCustomPlot& plot, const FigureOptions& o) {
  QFont f("DejaVu Sans");
  f.setPointSizeF(o.font_pt);
  QFont small = f;
  small.setPointSizeF(o.font_pt * 0.9);
  for (QCPAxis* a : plot.axisRect()->axes()) {
    a->setLabelFont(f);
    a->setTickLabelFont(small);
  }
  plot.legend->setFont(small);
  for (int i = 0; i < plot.graphCount(); ++i) {
    QPen p = plot.graph(i)->pen();
    p.setWidthF(o.line_width_pt);
    plot.graph(i)->setPen(p);
  }
}

}  // namespace

QSizeF figure_size_pt(const FigureOptions& o) {
  constexpr double kPtPerMm = 72.0 / 25.4;
  const double h_mm = o.height_mm > 0 ? o.height_mm : o.width_mm * 0.62;
  return {o.width_mm * kPtPerMm, h_mm * kPtPerMm};
}

void save_plot(QCustomPlot& plot, const QString& stem, const FigureOptions& o, const QString& title, QStringList& files,
               const CancelToken* cancel) {
  const QSizeF size = figure_size_pt(o);
  const int w = static_cast<int>(std::lround(size.width())), h = static_cast<int>(std::lround(size.height()));
  for (const QString& format : o.formats) {
    if (cancel) cancel->throw_if_cancelled();
    const QString path = stem + "." + format;
    bool ok = false;
    if (format == "pdf") {
      ok = plot.savePdf(path, w, h, QCP::epNoCosmetic, "BenchScope", title);
    } else if (format == "svg") {
      QSvgGenerator svg;
      svg.setFileName(path);
      svg.setSize(QSize(w, h));
      svg.setViewBox(QRect(0, 0, w, h));
      svg.setResolution(72);
      svg.setTitle(title);
      QCPPainter painter;
      ok = painter.begin(&svg);
      if (ok) {
        plot.toPainter(&painter, w, h);
        ok = painter.end();
      }
    } else if (format == "png") {
      ok = plot.savePng(path, w, h, o.dpi / 72.0, -1, o.dpi, QCP::ruDotsPerInch);
    } else {
      throw std::runtime_error("unknown figure format '" + format.toStdString() + "' (pdf, svg, png)");
    }
    if (!ok || !QFile::exists(path)) throw std::runtime_error(path.toStdString() + ": cannot write the figure");
    files << path;
  }
}

void export_plot(QCustomPlot& plot, const QString& stem, const FigureOptions& o, const QString& title, QStringList& files) {
  const PlotLook look(plot);
  apply_figure_look(plot, o);
  try {
    save_plot(plot, stem, o, title, files);
  } catch (...) {
    look.restore(plot);
    plot.replot();
    throw;
  }
  look.restore(plot);
  plot.replot();
}

}  // namespace bs::ui
