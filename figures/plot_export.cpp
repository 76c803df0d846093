// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot_export.h"

#include <qcustomplot.h>
#include <QFile>
#include <QFontMetricsF>
#include <QSvgGenerator>
#include <QTemporaryDir>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

#include "paper_figures.h"

namespace bs::ui {
namespace {

constexpr const char* kNoteName = "bs-legend-note";            // objectName of the note element under the legend
constexpr const char* kNotesProperty = "bs_figure_notes";      // the figure's own note lines (QStringList)
constexpr const char* kFigureNameProperty = "bs_figure_name";  // a plottable's name in figures (QString)
constexpr const char* kWholeNameProperty = "bs_whole_name";    // its name before elide_wide_entries shortened it

// Whether the legend stands in a column beside the axes (put_legend_beside: the Platforms tab's candidates).
// Every axis of every panel: a figure of panels one over the other (the Sustained tab's) has several axis rects.
QList<QCPAxis*> all_axes(QCustomPlot& plot) {
  QList<QCPAxis*> axes;
  for (QCPAxisRect* rect : plot.axisRects()) axes += rect->axes();
  return axes;
}

bool legend_beside_axes(QCustomPlot& plot) {
  return plot.legend->layout() == plot.plotLayout() && plot.plotLayout()->columnCount() > 1;
}

// Everything layout_figure changes on a view's plot, saved so that export_plot can put the view back as it was.
class ViewState {
 public:
  explicit ViewState(QCustomPlot& plot) : plot_(plot) {
    for (QCPAxis* a : all_axes(plot)) axes_.push_back({a, a->labelFont(), a->tickLabelFont(), a->range()});
    legend_font_ = plot.legend->font();
    for (int i = 0; i < plot.plottableCount(); ++i) {
      QCPAbstractPlottable* p = plot.plottable(i);
      plottables_.push_back({p, p->name(), p->pen().widthF(), plot.legend->hasItemWithPlottable(p)});
    }
    for (int i = 0; i < plot.itemCount(); ++i)
      if (auto* t = qobject_cast<QCPItemText*>(plot.item(i))) texts_.push_back({t, t->font(), t->visible()});
    for (int i = 0; i < plot.plotLayout()->elementCount(); ++i)
      if (auto* t = qobject_cast<QCPTextElement*>(plot.plotLayout()->elementAt(i)))
        titles_.push_back({t, t->text(), t->font()});
    QCPLayoutInset* inset = plot.axisRect()->insetLayout();
    for (int i = 0; i < inset->elementCount(); ++i)
      if (inset->elementAt(i) == plot.legend) {
        legend_inside_ = true;
        alignment_ = inset->insetAlignment(i);
      }
    // A legend beside the axes goes under them on paper and comes back after.
    legend_beside_ = legend_beside_axes(plot);
    border_ = plot.legend->borderPen();
    brush_ = plot.legend->brush();
    wrap_ = plot.legend->wrap();
    fill_order_ = plot.legend->fillOrder();
    row_spacing_ = plot.legend->rowSpacing();
    column_spacing_ = plot.legend->columnSpacing();
    icon_size_ = plot.legend->iconSize();
    legend_visible_ = plot.legend->visible();
    // A legend's grid may hold empty cells (entries taken out and put back, as the Power tab's overlay does):
    // item(i) is null there.
    for (int i = 0; i < plot.legend->itemCount(); ++i)
      if (const QCPAbstractLegendItem* item = plot.legend->item(i)) item_fonts_.push_back(item->font());
  }

  void restore() {
    // The note, and the legend back where it was (over the axes, in its corner) with its own entries in order.
    if (auto* note = plot_.findChild<QCPTextElement*>(kNoteName)) {
      plot_.plotLayout()->remove(note);
      plot_.plotLayout()->simplify();
    }
    if (legend_inside_ && plot_.legend->layout() != plot_.axisRect()->insetLayout()) {
      plot_.plotLayout()->take(plot_.legend);
      plot_.plotLayout()->simplify();
      plot_.axisRect()->insetLayout()->addElement(plot_.legend, alignment_);
    }
    if (legend_beside_ && !plot_.plotLayout()->hasElement(0, 1)) {
      plot_.plotLayout()->take(plot_.legend);
      plot_.plotLayout()->simplify();
      plot_.plotLayout()->addElement(0, 1, plot_.legend);
      plot_.plotLayout()->setColumnStretchFactor(1, 0.001);
    }
    plot_.legend->clearItems();
    for (const Plottable& p : plottables_) {
      p.plottable->setName(p.name);
      p.plottable->setProperty(kWholeNameProperty, QVariant());
      QPen pen = p.plottable->pen();
      pen.setWidthF(p.pen_width);
      p.plottable->setPen(pen);
      if (p.in_legend) p.plottable->addToLegend(plot_.legend);
    }
    plot_.legend->setVisible(legend_visible_);
    plot_.legend->setBorderPen(border_);
    plot_.legend->setBrush(brush_);
    plot_.legend->setFillOrder(fill_order_, false);
    plot_.legend->setWrap(wrap_);
    plot_.legend->setFillOrder(fill_order_, true);
    plot_.legend->setRowSpacing(row_spacing_);
    plot_.legend->setColumnSpacing(column_spacing_);
    plot_.legend->setIconSize(icon_size_);
    plot_.legend->setFont(legend_font_);
    for (int i = 0, k = 0; i < plot_.legend->itemCount() && k < static_cast<int>(item_fonts_.size()); ++i)
      if (QCPAbstractLegendItem* item = plot_.legend->item(i))
        item->setFont(item_fonts_[static_cast<std::size_t>(k++)]);
    for (const Axis& a : axes_) {
      a.axis->setLabelFont(a.label);
      a.axis->setTickLabelFont(a.ticks);
      a.axis->setRange(a.range);
    }
    for (const Text& t : texts_) {
      t.item->setFont(t.font);
      t.item->setVisible(t.visible);
    }
    for (const Title& t : titles_) {
      t.element->setText(t.text);
      t.element->setFont(t.font);
    }
  }

 private:
  struct Axis {
    QCPAxis* axis;
    QFont label, ticks;
    QCPRange range;
  };
  struct Plottable {
    QCPAbstractPlottable* plottable;
    QString name;
    double pen_width;
    bool in_legend;
  };
  struct Text {
    QCPItemText* item;
    QFont font;
    bool visible;
  };
  struct Title {
    QCPTextElement* element;
    QString text;
    QFont font;
  };
  QCustomPlot& plot_;
  std::vector<Axis> axes_;
  std::vector<Plottable> plottables_;
  std::vector<Text> texts_;
  std::vector<Title> titles_;  // text rows of the layout (a title), wrapped on paper
  QFont legend_font_;
  bool legend_inside_ = false, legend_beside_ = false, legend_visible_ = false;
  Qt::Alignment alignment_;
  QPen border_;
  QBrush brush_;
  int wrap_ = 0;
  QCPLayoutGrid::FillOrder fill_order_ = QCPLayoutGrid::foRowsFirst;
  int row_spacing_ = 0, column_spacing_ = 0;
  QSize icon_size_;
  std::vector<QFont> item_fonts_;
};

void apply_figure_look(QCustomPlot& plot, const FigureOptions& o) {
  QFont f("DejaVu Sans");
  f.setPointSizeF(o.font_pt);
  QFont small = f;
  small.setPointSizeF(o.font_pt * 0.9);
  QFont label = f;
  label.setPointSizeF(o.font_pt * 0.85);
  for (QCPAxis* a : all_axes(plot)) {
    a->setLabelFont(f);
    a->setTickLabelFont(small);
  }
  plot.legend->setFont(small);
  for (int i = 0; i < plot.plotLayout()->elementCount(); ++i)  // a title in the figure's font, not the screen's
    if (auto* title = qobject_cast<QCPTextElement*>(plot.plotLayout()->elementAt(i))) title->setFont(f);
  for (int i = 0; i < plot.graphCount(); ++i) {
    QPen p = plot.graph(i)->pen();
    if (p.style() == Qt::NoPen) continue;
    p.setWidthF(o.line_width_pt);
    plot.graph(i)->setPen(p);
  }
  for (int i = 0; i < plot.itemCount(); ++i)
    if (auto* t = qobject_cast<QCPItemText*>(plot.item(i))) t->setFont(label);
}

void place_legend_below(QCustomPlot& plot, double font_pt) {
  plot.legend->setBorderPen(Qt::NoPen);
  plot.legend->setBrush(Qt::NoBrush);
  plot.legend->setRowSpacing(0);
  plot.legend->setColumnSpacing(static_cast<int>(font_pt * 1.5));
  plot.legend->setIconSize(static_cast<int>(font_pt * 2.5), static_cast<int>(font_pt));
  if (plot.legend->layout() == plot.axisRect()->insetLayout()) plot.axisRect()->insetLayout()->take(plot.legend);
  if (legend_beside_axes(plot)) {
    plot.plotLayout()->take(plot.legend);
    plot.plotLayout()->simplify();
  }
  if (plot.legend->layout() != plot.plotLayout()) {
    // In the row under the axes, which is not row 1 where a title stands above them (the Headroom tab's): adding
    // to a taken cell fails, and the figure lost its legend.
    QCPLayoutGrid* grid = plot.plotLayout();
    int axes_row = 0;
    for (int r = 0; r < grid->rowCount(); ++r)
      if (grid->element(r, 0) == plot.axisRect()) axes_row = r;
    grid->insertRow(axes_row + 1);
    grid->addElement(axes_row + 1, 0, plot.legend);
    grid->setRowStretchFactor(axes_row + 1, 0.001);
  }
  plot.plotLayout()->setRowSpacing(0);
}

// Entries that read and look alike (repeated runs of one series) become one: "name (3 runs)".
void merge_alike_entries(QCustomPlot& plot) {
  std::map<QString, std::pair<QCPAbstractPlottable*, int>> seen;
  std::vector<QCPAbstractPlottable*> in_order;
  for (int i = 0; i < plot.legend->itemCount(); ++i)
    if (auto* item = qobject_cast<QCPPlottableLegendItem*>(plot.legend->item(i))) in_order.push_back(item->plottable());
  for (QCPAbstractPlottable* p : in_order) {
    QString key = p->name() + '|' + p->pen().color().name() + '|' + QString::number(p->pen().style());
    if (auto* g = qobject_cast<QCPGraph*>(p)) key += '|' + QString::number(g->scatterStyle().shape());
    const auto it = seen.find(key);
    if (it == seen.end()) {
      seen[key] = {p, 1};
      continue;
    }
    ++it->second.second;
    p->removeFromLegend(plot.legend);
  }
  for (auto& [key, entry] : seen)
    if (entry.second > 1) entry.first->setName(entry.first->name() + QStringLiteral(" (%1 runs)").arg(entry.second));
}

// As many legend columns as fit `width_pt` (measured by the legend's own layout, fonts included); a smaller font
// (down to 5 pt) when even one column is too wide.
void wrap_legend(QCustomPlot& plot, double font_pt, double width_pt) {
  for (double pt = font_pt * 0.9; pt >= 5; pt -= 0.5) {
    QFont f = plot.legend->font();
    f.setPointSizeF(pt);
    plot.legend->setFont(f);
    for (int i = 0; i < plot.legend->itemCount(); ++i)
      if (QCPAbstractLegendItem* item = plot.legend->item(i)) item->setFont(f);
    plot.legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, false);
    for (int columns = std::max(1, plot.legend->itemCount()); columns >= 1; --columns) {
      plot.legend->setWrap(columns);  // with foColumnsFirst: entries per row
      plot.legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true);
      if (plot.legend->minimumOuterSizeHint().width() <= width_pt) return;
    }
  }
}

// `text` broken into lines at spaces so that each fits `width_pt` in `metrics`.
QStringList wrapped(const QString& text, const QFontMetricsF& metrics, double width_pt) {
  QStringList lines;
  QString line;
  for (const QString& word : text.split(' ', Qt::SkipEmptyParts)) {
    const QString trial = line.isEmpty() ? word : line + ' ' + word;
    if (!line.isEmpty() && metrics.horizontalAdvance(trial) > width_pt) {
      lines << line;
      line = word;
    } else {
      line = trial;
    }
  }
  if (!line.isEmpty()) lines << line;
  return lines;
}

// Entries still wider than the figure at the smallest font (wrap_legend) go on two or more lines, broken between
// words, so that the figure still names them whole; only a single word wider than the row is shortened in the
// middle ("…"). Never cut at the figure's edge; the view gets its names back afterwards (export_plot).
void elide_wide_entries(QCustomPlot& plot, double width_pt) {
  // The legend's row is the figure less the layout's margins.
  const QMargins margins = plot.plotLayout()->margins();
  const double room = width_pt - margins.left() - margins.right() - 2;
  for (int pass = 0; pass < 5; ++pass) {
    const double excess = plot.legend->minimumOuterSizeHint().width() - room;
    if (excess <= 0) return;
    double widest = 0;
    for (int i = 0; i < plot.legend->itemCount(); ++i)
      if (QCPAbstractLegendItem* item = plot.legend->item(i))
        widest = std::max(widest, static_cast<double>(item->minimumOuterSizeHint().width()));
    const double limit = widest - excess - 1;
    for (int i = 0; i < plot.legend->itemCount(); ++i) {
      auto* item = qobject_cast<QCPPlottableLegendItem*>(plot.legend->item(i));
      const double w = item ? static_cast<QCPLayoutElement*>(item)->minimumOuterSizeHint().width() : 0;
      if (!item || w <= limit) continue;
      const QFontMetricsF m(item->font());
      const QString name = item->plottable()->name();
      const double room_pt = m.horizontalAdvance(name) - (w - limit);
      const QStringList lines = wrapped(name, m, room_pt);
      const bool whole =
          std::all_of(lines.begin(), lines.end(), [&](const QString& l) { return m.horizontalAdvance(l) <= room_pt; });
      if (!item->plottable()->property(kWholeNameProperty).isValid())
        item->plottable()->setProperty(kWholeNameProperty, name);
      item->plottable()->setName(whole && lines.size() > 1 ? lines.join('\n')
                                                           : m.elidedText(name, Qt::ElideMiddle, room_pt));
    }
  }
}

// Entries beyond kMaxLegendRows rows leave the legend; returns the sentence that names them ("" when all fit).
QString cap_legend(QCustomPlot& plot) {
  const int columns = std::max(1, plot.legend->wrap());
  const int keep = kMaxLegendRows * columns;
  if (plot.legend->itemCount() <= keep) return {};
  QStringList rest;
  std::vector<QCPAbstractPlottable*> leaving;
  for (int i = keep - 1; i < plot.legend->itemCount(); ++i)  // one slot less: the note says where they went
    if (auto* item = qobject_cast<QCPPlottableLegendItem*>(plot.legend->item(i))) leaving.push_back(item->plottable());
  for (QCPAbstractPlottable* p : leaving) {
    // The note wraps, so an entry shortened to fit the legend's row is named whole there.
    const QVariant whole = p->property(kWholeNameProperty);
    rest << (whole.isValid() ? whole.toString() : p->name());
    p->removeFromLegend(plot.legend);
  }
  plot.legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true);
  return QStringLiteral("Also drawn (%1 more): %2.").arg(rest.size()).arg(rest.join("; "));
}

// The note under the legend: the figure's own lines, then every entry the legend left out, whole (a figure that
// names only some of what it draws leaves the reader to guess the rest), each wrapped to the width.
void add_note(QCustomPlot& plot, const QString& also_drawn, double font_pt, double width_pt) {
  QFont f("DejaVu Sans");
  f.setPointSizeF(std::max(5.0, font_pt * 0.8));
  const QFontMetricsF metrics(f);
  QStringList lines;
  for (const QString& note : plot.property(kNotesProperty).toStringList())
    lines << wrapped(note, metrics, width_pt * 0.97);
  if (!also_drawn.isEmpty()) lines << wrapped(also_drawn, metrics, width_pt * 0.97);
  if (lines.isEmpty()) return;
  auto* note = new QCPTextElement(&plot, lines.join('\n'), f);
  note->setObjectName(kNoteName);
  note->setTextFlags(Qt::AlignLeft | Qt::AlignTop);
  note->setTextColor(QColor(60, 60, 60));
  note->setMargins(QMargins(4, 2, 4, 2));
  plot.plotLayout()->addElement(plot.plotLayout()->rowCount(), 0, note);
  plot.plotLayout()->setRowStretchFactor(plot.plotLayout()->rowCount() - 1, 0.001);
}

// A title row wider than the figure is broken between words: centred on the axes and cut at both edges, the Headroom
// tab's title lost its platform and its measurement's number (issue #50.5).
void wrap_titles(QCustomPlot& plot, double width_pt) {
  for (int i = 0; i < plot.plotLayout()->elementCount(); ++i)
    if (auto* title = qobject_cast<QCPTextElement*>(plot.plotLayout()->elementAt(i));
        title && title->objectName() != QLatin1String(kNoteName)) {
      const QFontMetricsF metrics(title->font());
      if (metrics.horizontalAdvance(title->text()) > width_pt * 0.97)
        title->setText(wrapped(title->text(), metrics, width_pt * 0.97).join('\n'));
    }
}

// Widens each value axis so that every visible plottable's values in the shown key range fit: a curve is never cut
// off at the top of a figure because the view on screen was zoomed or the legend made room.
void fit_value_axes(QCustomPlot& plot) {
  std::map<QCPAxis*, QCPRange> need;
  for (int i = 0; i < plot.plottableCount(); ++i) {
    QCPAbstractPlottable* p = plot.plottable(i);
    if (!p->visible() || !p->keyAxis() || !p->valueAxis()) continue;
    bool found = false;
    const QCP::SignDomain sign = p->valueAxis()->scaleType() == QCPAxis::stLogarithmic ? QCP::sdPositive : QCP::sdBoth;
    const QCPRange r = p->getValueRange(found, sign, p->keyAxis()->range());
    if (!found) continue;
    auto it = need.find(p->valueAxis());
    if (it == need.end())
      need[p->valueAxis()] = r;
    else
      it->second.expand(r);
  }
  for (auto& [axis, r] : need) {
    QCPRange range = axis->range();
    const bool log = axis->scaleType() == QCPAxis::stLogarithmic;
    if (r.upper > range.upper)
      range.upper = log ? r.upper * 1.15 : r.upper + 0.05 * (r.upper - std::min(range.lower, r.lower));
    if (r.lower < range.lower)
      range.lower = log ? r.lower / 1.15 : r.lower - 0.05 * (std::max(range.upper, r.upper) - r.lower);
    if (!(range == axis->range())) axis->setRange(range);
  }
}

}  // namespace

QSizeF figure_size_pt(const FigureOptions& o) {
  constexpr double kPtPerMm = 72.0 / 25.4;
  const double h_mm = o.height_mm > 0 ? o.height_mm : o.width_mm * 0.62;
  return {o.width_mm * kPtPerMm, h_mm * kPtPerMm};
}

FigureOptions layout_figure(QCustomPlot& plot, const FigureOptions& o) {
  apply_figure_look(plot, o);
  for (int i = 0; i < plot.plottableCount(); ++i)
    if (const QString name = plot.plottable(i)->property(kFigureNameProperty).toString(); !name.isEmpty())
      plot.plottable(i)->setName(name);
  const double width_pt = figure_size_pt(o).width();
  double below_pt = 0;
  QString also_drawn;
  if (plot.legend->visible() && plot.legend->itemCount() > 0) {
    plot.legend->setFillOrder(plot.legend->fillOrder(), true);  // its entries packed, no empty cells between them
    place_legend_below(plot, o.font_pt);
    merge_alike_entries(plot);
    wrap_legend(plot, o.font_pt, width_pt);
    elide_wide_entries(plot, width_pt);
    also_drawn = cap_legend(plot);
    below_pt = plot.legend->minimumOuterSizeHint().height();
  } else {
    plot.legend->setVisible(false);
  }
  wrap_titles(plot, width_pt);                                 // before the note: the note is no title
  for (int i = 0; i < plot.plotLayout()->elementCount(); ++i)  // a title's rows add theirs too, the axes keep theirs
    if (auto* title = qobject_cast<QCPTextElement*>(plot.plotLayout()->elementAt(i)))
      below_pt += static_cast<QCPLayoutElement*>(title)->minimumOuterSizeHint().height();
  add_note(plot, also_drawn, o.font_pt, width_pt);
  if (auto* note = plot.findChild<QCPTextElement*>(kNoteName))
    below_pt += static_cast<QCPLayoutElement*>(note)->minimumOuterSizeHint().height();
  fit_value_axes(plot);
  FigureOptions sized = o;
  if (o.height_mm <= 0) {
    // Panels one over the other share the width: each gets half the height one plot would have.
    const double panels = std::max(1.0, 0.5 * static_cast<double>(plot.axisRectCount()) + 0.1);
    const double axes_pt = width_pt * (o.width_mm < 80 ? 0.8 : 0.62) * panels;
    sized.height_mm = (axes_pt + below_pt) * 25.4 / 72.0;
  }
  return sized;
}

void set_figure_name(QCPAbstractPlottable* plottable, const QString& name) {
  plottable->setProperty(kFigureNameProperty, name);
}

QString figure_name(const QCPAbstractPlottable* plottable) {
  const QString name = plottable->property(kFigureNameProperty).toString();
  return name.isEmpty() ? plottable->name() : name;
}

void add_figure_note(QCustomPlot& plot, const QString& line) {
  QStringList notes = plot.property(kNotesProperty).toStringList();
  notes << line;
  plot.setProperty(kNotesProperty, notes);
}

void clear_figure_notes(QCustomPlot& plot) { plot.setProperty(kNotesProperty, QStringList()); }

QString legend_note(const QCustomPlot& plot) {
  const auto* note = plot.findChild<QCPTextElement*>(kNoteName);
  return note ? note->text() : QString();
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

void export_plot(QCustomPlot& plot, const QString& stem, const FigureOptions& o, const QString& title,
                 QStringList& files) {
  ViewState view(plot);
  const auto put_back = [&] {
    view.restore();
    plot.replot();
  };
  try {
    save_plot(plot, stem, layout_figure(plot, o), title, files);
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
