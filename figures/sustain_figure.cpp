// SPDX-License-Identifier: GPL-3.0-or-later
#include "sustain_figure.h"

#include <qcustomplot.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "device_palette.h"
#include "plot_export.h"

namespace bs::ui {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t kMostTemperatures = 8;  // more lines than a legend can name: the hottest ones are drawn

const QColor kBand(230, 80, 60, 45);  // throttled spans, light enough for the curves over them

// A series as steps over its intervals: the value of interval i holds from its start to its end (t_s is each end).
void set_steps(QCPGraph* g, const SustainRun& run, const std::vector<double>& values) {
  QVector<double> keys, vals;
  for (std::size_t i = 0; i < values.size() && i < run.t_s.size(); ++i) {
    if (i == 0) {
      keys << sustain::interval_start(run, 0);
      vals << values[0];
    }
    keys << run.t_s[i];
    vals << values[i];
  }
  g->setData(keys, vals, true);
  g->setLineStyle(QCPGraph::lsStepRight);
}

QCPGraph* add_series(QCustomPlot& plot, QCPAxisRect* rect, const QString& name, const QColor& color,
                     Qt::PenStyle style = Qt::SolidLine, double width = 1.6) {
  QCPGraph* g = plot.addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
  g->setName(name);
  g->setPen(QPen(color, width, style));
  return g;
}

// A horizontal reference (a threshold, a trip point, the sustained level) across the whole run, named in the legend.
void add_level(QCustomPlot& plot, QCPAxisRect* rect, const SustainRun& run, double level, const QString& name,
               const QColor& color, Qt::PenStyle style) {
  QCPGraph* g = add_series(plot, rect, name, color, style, 1.0);
  g->setData(QVector<double>{0, run.t_s.empty() ? 1.0 : run.t_s.back()}, QVector<double>{level, level}, true);
}

// Shaded spans over the whole height of a panel.
void add_bands(QCustomPlot& plot, QCPAxisRect* rect, const std::vector<std::pair<double, double>>& spans) {
  for (const auto& [start, end] : spans) {
    auto* band = new QCPItemRect(&plot);
    band->setClipAxisRect(rect);
    for (QCPItemPosition* p : {band->topLeft, band->bottomRight}) {
      p->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
      p->setAxisRect(rect);
      p->setTypeX(QCPItemPosition::ptPlotCoords);
      p->setTypeY(QCPItemPosition::ptAxisRectRatio);
    }
    band->topLeft->setCoords(start, 0);
    band->bottomRight->setCoords(end, 1);
    band->setPen(Qt::NoPen);
    band->setBrush(kBand);
    band->setLayer(QStringLiteral("background"));
  }
}

// A vertical mark through a panel at `t`, with `text` at its top in the panel where `text` is given.
void add_mark(QCustomPlot& plot, QCPAxisRect* rect, double t, const QColor& color, const QString& text,
              double label_y = 0.04) {
  auto* line = new QCPItemStraightLine(&plot);
  line->setClipAxisRect(rect);
  for (QCPItemPosition* p : {line->point1, line->point2})
    p->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
  line->point1->setCoords(t, 0);
  line->point2->setCoords(t, 1);
  line->setPen(QPen(color, 1.2, Qt::DashLine));
  if (text.isEmpty()) return;
  auto* label = new QCPItemText(&plot);
  label->setClipAxisRect(rect);
  label->position->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
  label->position->setAxisRect(rect);
  label->position->setTypeX(QCPItemPosition::ptPlotCoords);
  label->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
  label->position->setCoords(t, label_y);  // from the top of the panel, as a share of its height
  label->setPositionAlignment(Qt::AlignTop | Qt::AlignLeft);
  label->setText(text);
  label->setColor(color);
  label->setPadding(QMargins(3, 1, 3, 1));
  label->setBrush(QBrush(QColor(255, 255, 255, 210)));
}

double finite_max(const std::vector<double>& v) {
  double m = kNaN;
  for (double x : v)
    if (std::isfinite(x) && !(x <= m)) m = x;
  return m;
}

// The lowest and the mean of the CPUs' clocks in each interval (as % of each one's maximum when `percent`).
std::pair<std::vector<double>, std::vector<double>> cpu_lowest_and_mean(const SustainRun& run, bool percent) {
  std::vector<double> lowest(run.t_s.size(), kNaN), mean(run.t_s.size(), kNaN);
  for (std::size_t i = 0; i < run.t_s.size(); ++i) {
    double sum = 0;
    int n = 0;
    for (const ClockSeries& c : run.clocks) {
      if (!is_cpu_clock(c.name) || i >= c.hz.size() || !std::isfinite(c.hz[i])) continue;
      const double v = percent ? 100 * c.hz[i] / *c.max_hz : c.hz[i] / 1e6;
      sum += v;
      ++n;
      if (!(v >= lowest[i])) lowest[i] = v;
    }
    if (n > 0) mean[i] = sum / n;
  }
  return {lowest, mean};
}

int count_cpus(const SustainRun& run) {
  return static_cast<int>(
      std::count_if(run.clocks.begin(), run.clocks.end(), [](const ClockSeries& c) { return is_cpu_clock(c.name); }));
}

void draw_rate(QCustomPlot& plot, QCPAxisRect* rect, const SustainRun& run, const sustain::SustainAnalysis& a) {
  const QString unit = QString::fromStdString(run.rate_unit);
  rect->axis(QCPAxis::atLeft)->setLabel(QObject::tr("rate\n(%1)").arg(unit));
  set_steps(add_series(plot, rect, QObject::tr("rate per interval"), device_color(0), Qt::SolidLine, 1.8), run,
            run.rate);
  if (a.sustained.n > 0)
    add_level(plot, rect, run, a.sustained.mean,
              QObject::tr("sustained (last third) %1 %2").arg(a.sustained.mean, 0, 'f', 2).arg(unit), device_color(1),
              Qt::DashLine);
  if (a.peak_rate)
    add_level(plot, rect, run, *a.peak_rate * a.options.stable_percent / 100,
              QObject::tr("%1 % of the best interval").arg(a.options.stable_percent, 0, 'g', 3), QColor(120, 120, 120),
              Qt::DotLine);
  // Named where it is not the onset of throttling too (that mark, at the same time, says it).
  if (a.first_slow && !(a.throttle.onset_s && *a.throttle.onset_s == a.first_slow->start_s))
    add_mark(plot, rect, a.first_slow->start_s, QColor(90, 90, 90),
             QObject::tr("first slow interval %1 s").arg(a.first_slow->start_s, 0, 'f', 1), 0.55);
}

void draw_clocks(QCustomPlot& plot, QCPAxisRect* rect, const SustainRun& run, const sustain::SustainAnalysis& a) {
  // As % of the maximum where every clock states one (then the throttle threshold is one line for all), else MHz.
  const bool percent =
      std::all_of(run.clocks.begin(), run.clocks.end(), [](const ClockSeries& c) { return c.max_hz && *c.max_hz > 0; });
  rect->axis(QCPAxis::atLeft)->setLabel(percent ? QObject::tr("clock\n(% of max)") : QObject::tr("clock\n(MHz)"));
  int color = 2;
  if (const int cpus = count_cpus(run); cpus > 0) {
    const auto [lowest, mean] = cpu_lowest_and_mean(run, percent);
    set_steps(add_series(plot, rect, QObject::tr("CPUs, lowest of %1").arg(cpus), device_color(color)), run, lowest);
    if (cpus > 1)
      set_steps(add_series(plot, rect, QObject::tr("CPUs, mean of %1").arg(cpus), device_color(color), Qt::DashLine),
                run, mean);
    ++color;
  }
  for (const ClockSeries& c : run.clocks) {
    if (is_cpu_clock(c.name)) continue;
    std::vector<double> v(c.hz.size());
    std::transform(c.hz.begin(), c.hz.end(), v.begin(),
                   [&](double hz) { return percent ? 100 * hz / *c.max_hz : hz / 1e6; });
    set_steps(add_series(plot, rect, QString::fromStdString(c.name), device_color(color++), Qt::SolidLine), run, v);
  }
  if (percent)
    add_level(plot, rect, run, 100 * a.options.throttle_threshold,
              QObject::tr("throttle threshold %1 %").arg(100 * a.options.throttle_threshold, 0, 'g', 3),
              QColor(200, 30, 30), Qt::DotLine);
}

void draw_temperatures(QCustomPlot& plot, QCPAxisRect* rect, const SustainRun& run) {
  rect->axis(QCPAxis::atLeft)->setLabel(QObject::tr("temperature\n(°C)"));
  std::vector<const TemperatureSeries*> shown;
  for (const TemperatureSeries& t : run.temperatures) shown.push_back(&t);
  // The hottest first, so a cap drops the coolest; equal peaks keep the record's order.
  std::stable_sort(shown.begin(), shown.end(), [](const TemperatureSeries* x, const TemperatureSeries* y) {
    return finite_max(x->celsius) > finite_max(y->celsius);
  });
  if (shown.size() > kMostTemperatures) {
    add_figure_note(
        plot, QObject::tr("temperatures: the %1 hottest of %2 sensors drawn").arg(kMostTemperatures).arg(shown.size()));
    shown.resize(kMostTemperatures);
  }
  std::vector<double> trips;
  int color = 5;
  static const Qt::PenStyle styles[] = {Qt::SolidLine, Qt::DashLine, Qt::DashDotLine, Qt::DotLine};
  for (std::size_t i = 0; i < shown.size(); ++i) {
    set_steps(add_series(plot, rect, QString::fromStdString(shown[i]->name), device_color(color++), styles[i % 4]), run,
              shown[i]->celsius);
    if (shown[i]->trip_c && std::find(trips.begin(), trips.end(), *shown[i]->trip_c) == trips.end())
      trips.push_back(*shown[i]->trip_c);
  }
  std::sort(trips.begin(), trips.end());
  if (trips.size() > 2) trips.resize(2);  // the lowest trip points: where throttling starts
  for (double trip : trips)
    add_level(plot, rect, run, trip, QObject::tr("trip point %1 °C").arg(trip, 0, 'g', 4), QColor(200, 30, 30),
              Qt::DashDotDotLine);
}

void draw_power(QCustomPlot& plot, QCPAxisRect* rect, const SustainRun& run) {
  rect->axis(QCPAxis::atLeft)->setLabel(QObject::tr("power\n(W)"));
  const QString sensor = run.power_sensor.empty() ? QObject::tr("power") : QString::fromStdString(run.power_sensor);
  set_steps(add_series(plot, rect, sensor, device_color(4)), run, run.power_w);
}

// The layout rebuilt: the title, the first (default) axis rect and the legend kept, every other element deleted.
void reset_layout(QCustomPlot& plot, const QString& title) {
  QCPLayoutGrid* grid = plot.plotLayout();
  QCPAxisRect* first = plot.axisRect(0);
  if (plot.legend->layout()) plot.legend->layout()->take(plot.legend);
  grid->take(first);
  grid->clear();
  grid->simplify();
  auto* heading = new QCPTextElement(&plot, title, QFont(plot.font().family(), 10, QFont::Bold));
  grid->addElement(0, 0, heading);
  grid->addElement(1, 0, first);
  grid->setRowStretchFactor(0, 0.001);
}

}  // namespace

bool is_cpu_clock(const std::string& name) {
  if (name.size() < 4 || std::tolower(static_cast<unsigned char>(name[0])) != 'c' ||
      std::tolower(static_cast<unsigned char>(name[1])) != 'p' ||
      std::tolower(static_cast<unsigned char>(name[2])) != 'u')
    return false;
  return std::all_of(name.begin() + 3, name.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

int sustain_figure(QCustomPlot& plot, const SustainRun& run, const sustain::SustainAnalysis& a, const QString& title) {
  plot.clearPlottables();
  plot.clearItems();
  clear_figure_notes(plot);
  reset_layout(plot, title);
  enum class Panel { Rate, Clocks, Temperatures, Power };
  std::vector<Panel> panels;
  if (a.has_rate) panels.push_back(Panel::Rate);
  if (!run.clocks.empty()) panels.push_back(Panel::Clocks);
  if (!run.temperatures.empty()) panels.push_back(Panel::Temperatures);
  if (!run.power_w.empty()) panels.push_back(Panel::Power);
  QCPLayoutGrid* grid = plot.plotLayout();
  std::vector<QCPAxisRect*> rects;
  auto* margins = new QCPMarginGroup(&plot);
  for (std::size_t i = 0; i < std::max<std::size_t>(panels.size(), 1); ++i) {
    QCPAxisRect* rect = i == 0 ? plot.axisRect(0) : new QCPAxisRect(&plot);
    if (i > 0) grid->addElement(static_cast<int>(i) + 1, 0, rect);
    rect->setMarginGroup(QCP::msLeft | QCP::msRight, margins);
    rect->axis(QCPAxis::atBottom)->setTickLabels(i + 1 == panels.size() || panels.empty());
    rect->axis(QCPAxis::atBottom)->setLabel(i + 1 == panels.size() ? QObject::tr("time since start (s)") : QString());
    rects.push_back(rect);
  }
  if (panels.empty()) {
    rects[0]->axis(QCPAxis::atLeft)->setLabel(QString());
    add_figure_note(plot, QObject::tr("nothing to draw: the record has no rate, clock, temperature or power"));
    plot.replot();
    return 0;
  }
  for (std::size_t i = 0; i < panels.size(); ++i) {
    switch (panels[i]) {
      case Panel::Rate:
        draw_rate(plot, rects[i], run, a);
        break;
      case Panel::Clocks:
        draw_clocks(plot, rects[i], run, a);
        break;
      case Panel::Temperatures:
        draw_temperatures(plot, rects[i], run);
        break;
      case Panel::Power:
        draw_power(plot, rects[i], run);
        break;
    }
    add_bands(plot, rects[i], a.throttle.spans);
    if (a.throttle.onset_s)
      add_mark(plot, rects[i], *a.throttle.onset_s, QColor(200, 30, 30),
               i == 0 ? QObject::tr("throttling from %1 s").arg(*a.throttle.onset_s, 0, 'f', 1) : QString());
  }
  // One time axis: every panel shows the same span, and panning or zooming one moves the others.
  const double end = run.t_s.empty() ? 1 : run.t_s.back();
  for (QCPAxisRect* rect : rects) {
    rect->axis(QCPAxis::atBottom)->setRange(0, end);
    for (QCPAxisRect* other : rects)
      if (other != rect)
        QObject::connect(rect->axis(QCPAxis::atBottom), qOverload<const QCPRange&>(&QCPAxis::rangeChanged),
                         other->axis(QCPAxis::atBottom), qOverload<const QCPRange&>(&QCPAxis::setRange));
    // Few value ticks: the panels share the figure's height, and an export's panel is a few lines tall.
    rect->axis(QCPAxis::atLeft)->ticker()->setTickCount(3);
    rect->setRangeDrag(Qt::Horizontal);
    rect->setRangeZoom(Qt::Horizontal);
  }
  for (int i = 0; i < plot.graphCount(); ++i)
    plot.graph(i)->rescaleValueAxis(i > 0 && plot.graph(i)->valueAxis() == plot.graph(i - 1)->valueAxis());
  for (QCPAxisRect* rect : rects) {
    QCPAxis* y = rect->axis(QCPAxis::atLeft);
    const QCPRange r = y->range();
    const double pad = std::max(0.08 * (r.upper - r.lower), 1e-9);
    y->setRange(std::min(0.0, r.lower - pad), r.upper + pad);  // from 0: a drop reads as the share it is
  }
  // The legend under the panels, in rows, never over the data.
  // Three entries a row: the legend's width is the plot's minimum width, and the tab must fit a 1280 px window
  // beside the workspace dock.
  plot.legend->setVisible(true);
  plot.legend->setWrap(3);
  plot.legend->setFillOrder(QCPLegend::foColumnsFirst, true);  // rearranged: the entries were added before
  grid->addElement(static_cast<int>(rects.size()) + 1, 0, plot.legend);
  grid->setRowStretchFactor(static_cast<int>(rects.size()) + 1, 0.001);
  plot.replot();
  return static_cast<int>(panels.size());
}

}  // namespace bs::ui
