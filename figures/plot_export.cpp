// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot_export.h"

#include <qcustomplot.h>
#include <QFile>
#include <QSvgGenerator>
#include <QTemporaryDir>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "paper_figures.h"

namespace bs::ui {
namespace {

// A legend shown over the axes (the views' layout) while it is moved below them for an export, and put back after.
class LegendBelow {
 public:
  explicit LegendBelow(QCustomPlot& plot) : plot_(plot) {
    QCPLayoutInset* inset = plot.axisRect()->insetLayout();
    for (int i = 0; i < inset->elementCount(); ++i)
      if (inset->elementAt(i) == plot.legend) {
        moved_ = plot.legend->visible();
        alignment_ = inset->insetAlignment(i);
      }
    if (!moved_) return;
    border_ = plot.legend->borderPen();
    brush_ = plot.legend->brush();
    wrap_ = plot.legend->wrap();
    fill_order_ = plot.legend->fillOrder();
    row_spacing_ = plot.legend->rowSpacing();
    column_spacing_ = plot.legend->columnSpacing();
    icon_size_ = plot.legend->iconSize();
    for (int i = 0; i < plot.legend->itemCount(); ++i) item_fonts_.push_back(plot.legend->item(i)->font());
  }
  bool moved() const { return moved_; }
  void restore() {
    if (!moved_) return;
    plot_.plotLayout()->take(plot_.legend);
    plot_.plotLayout()->simplify();
    plot_.axisRect()->insetLayout()->addElement(plot_.legend, alignment_);
    plot_.legend->setBorderPen(border_);
    plot_.legend->setBrush(brush_);
    plot_.legend->setFillOrder(fill_order_, false);
    plot_.legend->setWrap(wrap_);
    plot_.legend->setFillOrder(fill_order_, true);
    plot_.legend->setRowSpacing(row_spacing_);
    plot_.legend->setColumnSpacing(column_spacing_);
    plot_.legend->setIconSize(icon_size_);
    for (int i = 0; i < plot_.legend->itemCount() && i < static_cast<int>(item_fonts_.size()); ++i)
      plot_.legend->item(i)->setFont(item_fonts_[static_cast<std::size_t>(i)]);
    moved_ = false;
  }

 private:
  QCustomPlot& plot_;
  bool moved_ = false;
  Qt::Alignment alignment_;
  QPen border_;
  QBrush brush_;
  int wrap_ = 0;
  QCPLayoutGrid::FillOrder fill_order_ = QCPLayoutGrid::foRowsFirst;
  int row_spacing_ = 0, column_spacing_ = 0;
  QSize icon_size_;
  std::vector<QFont> item_fonts_;
};

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

void place_legend_below(QCustomPlot& plot, double font_pt) {
  plot.legend->setVisible(true);
  plot.legend->setBorderPen(Qt::NoPen);
  plot.legend->setBrush(Qt::NoBrush);
  plot.legend->setRowSpacing(0);
  plot.legend->setColumnSpacing(static_cast<int>(font_pt * 1.5));
  plot.legend->setIconSize(static_cast<int>(font_pt * 2.5), static_cast<int>(font_pt));
  plot.axisRect()->insetLayout()->take(plot.legend);
  plot.plotLayout()->addElement(1, 0, plot.legend);
  plot.plotLayout()->setRowStretchFactor(1, 0.001);
  plot.plotLayout()->setRowSpacing(0);
}

void wrap_legend(QCustomPlot& plot, double font_pt, double width_pt) {
  // Fewer columns first; if even one column is too wide for a narrow figure, a smaller legend font (down to 5 pt).
  for (double pt = font_pt * 0.9; pt >= 5; pt -= 0.5) {
    QFont f = plot.legend->font();
    f.setPointSizeF(pt);
    plot.legend->setFont(f);
    for (int i = 0; i < plot.legend->itemCount(); ++i) plot.legend->item(i)->setFont(f);
    plot.legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, false);
    for (int columns = std::max(1, plot.legend->itemCount()); columns >= 1; --columns) {
      plot.legend->setWrap(columns);  // with foColumnsFirst: entries per row
      plot.legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true);
      if (plot.legend->minimumOuterSizeHint().width() <= width_pt) return;
    }
  }
}

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

FigureOptions prepare_export(QCustomPlot& plot, const FigureOptions& o) {
  apply_figure_look(plot, o);
  FigureOptions sized = o;
  if (!plot.legend->visible()) return sized;
  const double width_pt = figure_size_pt(o).width();
  place_legend_below(plot, o.font_pt);
  wrap_legend(plot, o.font_pt, width_pt);
  if (o.height_mm <= 0) {  // automatic height: the axes keep their share of the width, the legend adds its own
    const double legend_pt = plot.legend->minimumOuterSizeHint().height();
    sized.height_mm = (width_pt * 0.62 + legend_pt) * 25.4 / 72.0;
  }
  return sized;
}

void export_plot(QCustomPlot& plot, const QString& stem, const FigureOptions& o, const QString& title,
                 QStringList& files) {
  const PlotLook look(plot);
  LegendBelow legend(plot);
  const auto put_back = [&] {
    legend.restore();
    look.restore(plot);
    plot.replot();
  };
  try {
    const FigureOptions sized = legend.moved() ? prepare_export(plot, o) : (apply_figure_look(plot, o), o);
    save_plot(plot, stem, sized, title, files);
  } catch (...) {
    put_back();
    throw;
  }
  put_back();
}

QImage render_export_preview(QCustomPlot& plot, const FigureOptions& o, int width_px) {
  QTemporaryDir dir;
  if (!dir.isValid()) return {};
  FigureOptions small = o;
  small.formats = {"png"};
  small.dpi = std::max(10, static_cast<int>(std::lround(width_px / (o.width_mm / 25.4))));
  QStringList files;
  try {
    export_plot(plot, dir.filePath("preview"), small, QString(), files);
  } catch (const std::exception&) {
    return {};
  }
  return QImage(dir.filePath("preview.png"));
}

}  // namespace bs::ui
